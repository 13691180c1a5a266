"""Inkshade: toon/NPR shading and line drawing for triangle meshes (headless OpenGL).

The renderer is the compiled extension ``inkshade._inkshade``; this package re-exports all of
it (docs/library.md) and adds pure-Python parts: ``inkshade.dask`` maps a batch manifest over a
Dask cluster (docs/cluster.md).
"""
from . import _inkshade
from ._inkshade import *  # noqa: F401,F403 - every function and class of the extension
from ._inkshade import __version__  # noqa: F401

__all__ = [name for name in dir(_inkshade) if not name.startswith("_")]

for _name in __all__:
    if isinstance(getattr(_inkshade, _name), type):
        getattr(_inkshade, _name).__module__ = __name__  # inkshade.Renderer in reprs and help()
del _name
