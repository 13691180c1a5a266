"""The Python package inkshade: python/inkshade/*.py plus the extension `_inkshade`, which
CMake builds (target inkshade_python) and this file copies into the package.

The CMake build directory is INKSHADE_CMAKE_BUILD_DIR when set (an existing build is reused
as it is, so an up-to-date tree makes the build step a no-op; tests/python/test_package.py),
else build-python/ in the source tree, configured here for the interpreter running the build.
setuptools' own build files go inside it too, not into the CMake tree `build/`.
"""
import os
import re
import shutil
import subprocess
import sys
import sysconfig

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))
BUILD_DIR = os.path.abspath(os.environ.get("INKSHADE_CMAKE_BUILD_DIR") or os.path.join(ROOT, "build-python"))


def project_version():
    with open(os.path.join(ROOT, "CMakeLists.txt"), encoding="utf-8") as f:
        return re.search(r"project\(inkshade VERSION ([0-9.]+)", f.read()).group(1)


class CMakeBuild(build_ext):
    """Configures (first time only) and builds the extension with CMake, then copies it."""

    def build_extension(self, ext):
        if not os.path.exists(os.path.join(BUILD_DIR, "CMakeCache.txt")):
            generator = ["-G", "Ninja"] if shutil.which("ninja") else []
            # No -Werror: a newer compiler's new warning must not fail a user's install.
            subprocess.run(["cmake", "-S", ROOT, "-B", BUILD_DIR, *generator, "-DCMAKE_BUILD_TYPE=Release",
                            "-DINKSHADE_BUILD_TESTS=OFF", "-DINKSHADE_BUILD_BENCH=OFF", "-DINKSHADE_WERROR=OFF",
                            f"-DPython3_EXECUTABLE={sys.executable}"], check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
        subprocess.run(["cmake", "--build", BUILD_DIR, "--target", "inkshade_python", "-j", jobs], check=True)
        built = os.path.join(BUILD_DIR, "python", "inkshade", "_inkshade" + sysconfig.get_config_var("EXT_SUFFIX"))
        if not os.path.exists(built):
            sys.exit(f"setup.py: {built} is missing: {BUILD_DIR} was configured for another Python "
                     f"than {sys.executable} (set INKSHADE_CMAKE_BUILD_DIR to a new directory)")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(built, target)


SETUPTOOLS_DIR = os.path.join(BUILD_DIR, "setuptools")
os.makedirs(SETUPTOOLS_DIR, exist_ok=True)
setup(
    version=project_version(),
    packages=["inkshade"],
    package_dir={"": "python"},
    ext_modules=[Extension("inkshade._inkshade", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": SETUPTOOLS_DIR}, "egg_info": {"egg_base": SETUPTOOLS_DIR}},
    zip_safe=False,
)
