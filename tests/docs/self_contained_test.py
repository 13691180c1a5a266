"""The repository's docs and comments stand on their own.

They cite sources by authors, year and title, and never the planning documents that lived
outside the repository while the product was written: numbered "seed" documents, the spec's
sections ("SPEC §3"), or the spec, design and platform notes by file name. Every text file under
the source tree is read; a hit fails the test with FILE:LINE and the line.
"""
import os
import re
import unittest

SOURCE_DIR = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))

OUTSIDE = re.compile(r"\b[Ss]eeds? ?0\d\d\b|\bSPEC ?§|\b(?:SPEC|DESIGN|PLATFORM|STYLE)\.md\b|shared/seeds")
SKIP_DIRS = {".git", "build", "out", "node_modules", "__pycache__", ".device", ".gl", ".whl"}
# Fuzzer inputs are kept byte for byte: what they exercise is their bytes, not their words.
SKIP_PREFIXES = (os.path.join("tests", "styles", "fuzz_regressions"),
                 os.path.join("tests", "styles", "scene_fuzz_regressions"),
                 os.path.join("tests", "io", "fuzz_regressions"),
                 os.path.join("tests", "batch", "fuzz_regressions"),
                 os.path.join("tests", "docs"))


def text_files():
    for root, dirs, files in os.walk(SOURCE_DIR):
        dirs[:] = [d for d in dirs if d not in SKIP_DIRS and not d.startswith("build-")]
        for name in files:
            path = os.path.join(root, name)
            rel = os.path.relpath(path, SOURCE_DIR)
            if rel.startswith(SKIP_PREFIXES):
                continue
            with open(path, "rb") as f:
                data = f.read()
            if b"\0" in data:
                continue  # images and other binaries
            yield rel, data.decode("utf-8", errors="replace")


class SelfContainedTest(unittest.TestCase):
    def test_the_pattern_finds_what_it_must(self):
        for text in ("see seed 003", "Seed 001's F key", "(SPEC §3 vector output)", "as PLATFORM.md says"):
            self.assertTrue(OUTSIDE.search(text), text)
        for text in ("a seed corpus", "seeded jitter", "seed = 42", "DeCarlo et al. 2003 §4"):
            self.assertFalse(OUTSIDE.search(text), text)

    def test_no_reference_to_documents_outside_the_repository(self):
        hits = []
        count = 0
        for rel, text in text_files():
            count += 1
            for number, line in enumerate(text.splitlines(), 1):
                if OUTSIDE.search(line):
                    hits.append(f"{rel}:{number}: {line.strip()[:120]}")
        self.assertGreater(count, 100)
        self.assertEqual(hits, [], "\n" + "\n".join(hits))


if __name__ == "__main__":
    unittest.main()
