"""The Python examples of the docs run as written.

Every ```python block of docs/*.md and README.md runs in a fresh namespace, from a scratch
directory (so an example that writes files leaves nothing behind); an exception fails the test
and names the file and the block's first line.
"""
import glob
import os
import re
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


if __name__ == "__main__":
    unittest.main()
