"""`pip install .`, `python3 -m build --wheel` and `--sdist`, as docs/library.md gives them:
offline (--no-build-isolation --no-index), into a temporary venv that sees Debian's numpy, then
`import inkshade` from another directory without any path edit; the sdist holds every file the
extension's CMake build reads (MANIFEST.in) and configures on its own.

setup.py reuses this CMake build (INKSHADE_CMAKE_BUILD_DIR, set by ctest), so on an
up-to-date tree its build step is a no-op and the test takes seconds; a build from scratch is
the same code with a fresh directory (docs/library.md). Needs Debian's python3-venv,
python3-pip, python3-setuptools, python3-wheel and python3-build (scripts/setup).
"""
import glob
import os
import shutil
import subprocess
import sys
import tarfile
import tempfile
import time
import unittest
import zipfile

SOURCE_DIR = os.environ["INKSHADE_SOURCE_DIR"]
BUILD_DIR = os.environ["INKSHADE_CMAKE_BUILD_DIR"]

# From another directory: the installed package, working, its metadata, its Dask part.
CHECK = """
import importlib.metadata, os, sys
import inkshade, inkshade.dask
r = inkshade.Renderer()
r.set_mesh(inkshade.load_mesh("builtin:sphere"))
image = r.render("anime", size=(40, 30))
assert image.shape == (30, 40, 4) and image.dtype.name == "uint8", image.shape
assert (image[:, :, :3] != 255).any(), "a blank picture"
assert importlib.metadata.version("inkshade") == inkshade.__version__, inkshade.__version__
print(os.path.dirname(inkshade.__file__))
print(inkshade._inkshade.__file__)
"""


# What setup.py's CMake build reads (MANIFEST.in), relative to the source tree: files, then folders.
SDIST_FILES = ["CMakeLists.txt", "setup.py", "pyproject.toml", "README.md", "MANIFEST.in",
               "python/CMakeLists.txt", "python/extension.map", "python/inkshade_module.cpp"]
SDIST_FOLDERS = ["cmake", "include", "src", "apps", "shaders", "data/brushes", "python/inkshade"]


def source_files():
    """The files of SDIST_FILES and SDIST_FOLDERS in the source tree, without Python caches."""
    files = set(SDIST_FILES)
    for folder in SDIST_FOLDERS:
        for root, dirs, names in os.walk(os.path.join(SOURCE_DIR, folder)):
            dirs[:] = [d for d in dirs if d != "__pycache__"]
            files.update(os.path.relpath(os.path.join(root, n), SOURCE_DIR) for n in names if not n.endswith(".pyc"))
    return files


def run(*args, **kwargs):
    result = subprocess.run(args, capture_output=True, text=True, **kwargs)
    if result.returncode != 0:
        raise AssertionError(f"{' '.join(args)} failed ({result.returncode}):\n{result.stdout}\n{result.stderr}")
    return result


class PackageTest(unittest.TestCase):
    def setUp(self):
        # Only what a user's shell has: no PYTHONPATH at the build tree.
        self.env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONHOME")}
        # setuptools' own build files (setup.py keeps them in BUILD/setuptools) from an earlier
        # run must not stand in for this one's.
        shutil.rmtree(os.path.join(BUILD_DIR, "setuptools"), ignore_errors=True)

    def test_pip_install_into_a_venv_and_import_from_anywhere(self):
        with tempfile.TemporaryDirectory() as tmp:
            venv = os.path.join(tmp, "venv")
            start = time.monotonic()
            run(sys.executable, "-m", "venv", "--system-site-packages", venv, env=self.env)
            python = os.path.join(venv, "bin", "python")
            made = time.monotonic()
            run(python, "-m", "pip", "install", "--no-build-isolation", "--no-index", SOURCE_DIR, env=self.env)
            installed = time.monotonic()
            elsewhere = os.path.join(tmp, "elsewhere")
            os.mkdir(elsewhere)
            lines = run(python, "-c", CHECK, cwd=elsewhere, env=self.env).stdout.splitlines()
            print(f"venv {made - start:.1f} s, pip install {installed - made:.1f} s", file=sys.stderr)
            site = run(python, "-c", "import sysconfig; print(sysconfig.get_paths()['platlib'])",
                       env=self.env).stdout.strip()
            self.assertEqual(lines[0], os.path.join(site, "inkshade"))
            self.assertTrue(lines[1].startswith(os.path.join(site, "inkshade", "_inkshade.")), lines[1])
            # Debian's interpreter without the venv does not see it.
            outside = subprocess.run([sys.executable, "-c", "import inkshade"], cwd=elsewhere, env=self.env,
                                     capture_output=True, text=True)
            self.assertNotEqual(outside.returncode, 0)
            run(python, "-m", "pip", "uninstall", "-y", "inkshade", env=self.env)
            gone = subprocess.run([python, "-c", "import inkshade"], cwd=elsewhere, env=self.env,
                                  capture_output=True, text=True)
            self.assertIn("No module named 'inkshade'", gone.stderr)

    def test_wheel_holds_the_package_and_needs_only_system_libraries(self):
        with tempfile.TemporaryDirectory() as tmp:
            start = time.monotonic()
            run(sys.executable, "-m", "build", "--wheel", "--no-isolation", "--outdir", tmp, SOURCE_DIR,
                env=self.env)
            print(f"wheel {time.monotonic() - start:.1f} s", file=sys.stderr)
            wheels = glob.glob(os.path.join(tmp, "*.whl"))
            self.assertEqual(len(wheels), 1, wheels)
            tag = f"cp{sys.version_info.major}{sys.version_info.minor}"
            self.assertRegex(os.path.basename(wheels[0]), rf"^inkshade-\d+\.\d+\.\d+-{tag}-{tag}-linux_x86_64\.whl$")
            with zipfile.ZipFile(wheels[0]) as wheel:
                names = wheel.namelist()
                package = sorted(n for n in names if not n.startswith("inkshade-"))
                self.assertIn("inkshade/__init__.py", package)
                self.assertIn("inkshade/dask.py", package)
                extensions = [n for n in package if n.endswith(".so")]
                self.assertEqual(len(extensions), 1, package)  # no libinkshade.so beside it
                self.assertRegex(extensions[0], r"^inkshade/_inkshade\.cpython-.*\.so$")
                extension = wheel.extract(extensions[0], tmp)
            dynamic = run("readelf", "-d", extension).stdout
            self.assertNotIn("RPATH", dynamic)
            self.assertNotIn("RUNPATH", dynamic)
            self.assertNotIn("libinkshade", dynamic)
            # Every library it needs is a system one the dynamic loader finds.
            for line in run("ldd", extension).stdout.splitlines():
                self.assertNotIn("not found", line)
                if "=>" in line:
                    self.assertRegex(line.split("=>")[1].strip(), r"^/(usr/)?lib", line)
            symbols = run("nm", "-D", "--defined-only", extension).stdout.split()
            self.assertEqual([s for s in symbols if s.startswith("Py")], ["PyInit__inkshade"])

    def test_sdist_holds_the_sources_and_configures_on_its_own(self):
        with tempfile.TemporaryDirectory() as tmp:
            run(sys.executable, "-m", "build", "--sdist", "--no-isolation", "--outdir", tmp, SOURCE_DIR, env=self.env)
            archives = glob.glob(os.path.join(tmp, "*.tar.gz"))
            self.assertEqual(len(archives), 1, archives)
            name = os.path.basename(archives[0])[: -len(".tar.gz")]
            self.assertRegex(name, r"^inkshade-\d+\.\d+\.\d+$")
            with tarfile.open(archives[0]) as sdist:
                members = {m.name[len(name) + 1:] for m in sdist.getmembers() if m.isfile()}
                sdist.extractall(tmp, **({"filter": "data"} if hasattr(tarfile, "data_filter") else {}))
            self.assertEqual(members - source_files(), {"PKG-INFO", "setup.cfg"})
            self.assertEqual(source_files() - members, set(), "files the build reads, missing from the sdist")
            # The configure step of `pip install inkshade-X.Y.Z.tar.gz`, on the sdist alone: every
            # file CMake reads at configure time is there (the compile reads the files checked above).
            build = os.path.join(tmp, "build")
            run("cmake", "-S", os.path.join(tmp, name), "-B", build, "-DINKSHADE_BUILD_TESTS=OFF",
                "-DINKSHADE_BUILD_BENCH=OFF", f"-DPython3_EXECUTABLE={sys.executable}", env=self.env)
            self.assertTrue(os.path.exists(os.path.join(build, "inkshadeConfig.cmake")))
            self.assertIn("inkshade_python", run("cmake", "--build", build, "--target", "help").stdout)


if __name__ == "__main__":
    unittest.main()
