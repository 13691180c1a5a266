"""The Python examples of the docs run as written.

Every ```python block of docs/*.md and README.md runs in a fresh namespace, from a scratch
directory (so an example that writes files leaves nothing behind); an exception fails the test
and names the file and the block's first line.
"""
import glob
import json
import os
import re
import subprocess
import tarfile
import tempfile
import unittest

SOURCE_DIR = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))


def python_blocks():
    files = sorted(glob.glob(os.path.join(SOURCE_DIR, "docs", "*.md"))) + [os.path.join(SOURCE_DIR, "README.md")]
    for path in files:
        with open(path, encoding="utf-8") as f:
            text = f.read()
        for match in re.finditer(r"^```python\n(.*?)^```", text, re.S | re.M):
            line = text.count("\n", 0, match.start()) + 2
            yield os.path.relpath(path, SOURCE_DIR), line, match.group(1)


class DocsTest(unittest.TestCase):
    def test_there_are_examples(self):
        self.assertTrue(any(path == os.path.join("docs", "library.md") for path, _, _ in python_blocks()))

    def test_python_examples_run_as_written(self):
        for path, line, code in python_blocks():
            with self.subTest(example=f"{path}:{line}"), tempfile.TemporaryDirectory() as tmp:
                cwd = os.getcwd()
                os.chdir(tmp)
                try:
                    exec(compile(code, f"{path}:{line}", "exec"), {"__name__": "__doc_example__"})
                finally:
                    os.chdir(cwd)

    def test_dataset_walkthrough_runs_as_written(self):
        """docs/datasets.md's sh blocks, in order, in an empty directory with the built CLI first
        on PATH; then every sample of its shards against the folder layout of the same jobs."""
        with open(os.path.join(SOURCE_DIR, "docs", "datasets.md"), encoding="utf-8") as f:
            script = "\n".join(m.group(1) for m in re.finditer(r"^```sh\n(.*?)^```", f.read(), re.S | re.M))
        self.assertIn("--layout webdataset", script)
        env = dict(os.environ, PATH=os.path.dirname(os.environ["INKSHADE_BIN"]) + os.pathsep + os.environ["PATH"])
        with tempfile.TemporaryDirectory() as tmp:
            run = subprocess.run(["bash", "-euo", "pipefail", "-c", script], cwd=tmp, env=env, capture_output=True,
                                 text=True)
            self.assertEqual(run.returncode, 0, run.stderr)
            for model in ("torus", "knot"):
                directory = os.path.join(tmp, "dataset", model, "nc-lines")
                with open(os.path.join(directory, "transforms.json")) as f:
                    self.assertEqual(len(json.load(f)["frames"]), 12)
                self.assertTrue(os.path.exists(os.path.join(tmp, "dataset", model + ".mesh.ply")))
            samples = {}
            for shard in sorted(glob.glob(os.path.join(tmp, "shards", "*.tar"))):
                with tarfile.open(shard) as tar:
                    for member in tar.getmembers():
                        key, ext = member.name.split(".", 1)
                        samples.setdefault(key, {})[ext] = tar.extractfile(member).read()
            self.assertEqual(len(samples), 24)
            for key, files in samples.items():
                for ext in ("png", "lines.json", "depth.exr", "kr.exr", "shading-s4.png", "camera.json", "json"):
                    self.assertIn(ext, files, key)
                stem = json.loads(files["json"])["stem"]
                for ext, data in files.items():
                    if ext == "json":  # the metadata: its timings differ from run to run
                        continue
                    with open(os.path.join(tmp, "dataset", stem + "." + ext), "rb") as f:
                        self.assertEqual(f.read(), data, f"{key}.{ext}")
                points = json.loads(files["lines.json"])["layers"][0]["paths"][0]
                self.assertEqual(len(points["world"]), len(points["points"]))


if __name__ == "__main__":
    unittest.main()
