"""Include expansion at embed time (cmake/embed_files.cmake with EXPAND_INCLUDES=ON, as the
build runs it for shaders/): run in CMake script mode on small trees written here, it must
expand nested includes once per embedded file and stop, naming the including file and line,
at a missing include, a cycle or a malformed include line. Without EXPAND_INCLUDES (the style
presets) files are embedded byte for byte.

  INKSHADE_CMAKE=cmake python3 -m unittest -v embed_files_test      (ctest: embed.includes)
"""
import os
import re
import subprocess
import tempfile
import unittest
from pathlib import Path

SCRIPT = Path(__file__).resolve().parent.parent.parent / "cmake" / "embed_files.cmake"
CMAKE = os.environ.get("INKSHADE_CMAKE", "cmake")


class Tree:
    """A scratch shader folder: files written with `write(path, text)`, embedded with `embed()`."""

    def __init__(self, test):
        d = tempfile.TemporaryDirectory()
        test.addCleanup(d.cleanup)
        self.dir = Path(d.name) / "shaders"
        self.output = Path(d.name) / "embedded.cpp"

    def write(self, path, text):
        p = self.dir / path
        p.parent.mkdir(parents=True, exist_ok=True)
        p.write_bytes(text.encode())

    def where(self, path, line):
        return f"{self.dir / path}:{line}: "

    def embed(self, expand=True):
        """(exit status, stderr, {path: contents} of the generated table or None)."""
        r = subprocess.run([CMAKE, f"-DDIR={self.dir}", f"-DOUTPUT={self.output}", "-DGLOBS=*.glsl|*.frag|*.vert",
                            "-DFUNCTION=embedded", "-DNAMESPACE=test", f"-DEXPAND_INCLUDES={'ON' if expand else 'OFF'}",
                            "-P", str(SCRIPT)], capture_output=True, text=True)
        return r.returncode, r.stderr, parse(self.output) if self.output.exists() else None


def parse(cpp):
    """The table of a generated file: its byte arrays by name, then the {path, array} entries."""
    text = cpp.read_text()
    arrays = {m[1]: bytes(int(b, 16) for b in re.findall(r"0x([0-9a-f]{2})", m[2]))
              for m in re.finditer(r"static const unsigned char (\w+)\[\] = \{([^}]*)\};", text)}
    table = {}
    for m in re.finditer(r'\{"([^"]+)", reinterpret_cast<const char\*>\((\w+)\)\}', text):
        data = arrays[m[2]]
        assert data.endswith(b"\0"), m[1]
        table[m[1]] = data[:-1].decode()
    return table


class EmbedFilesTest(unittest.TestCase):
    def failure(self, tree):
        """Runs the expansion, which must fail, and returns its one error line (without CMake's
        framing) after checking that no table was written."""
        rc, err, table = tree.embed()
        self.assertNotEqual(rc, 0, err)
        self.assertIsNone(table)
        lines = [l.strip() for l in err.splitlines() if l.startswith("   ")]
        self.assertEqual(len(lines), 1, err)
        return lines[0]

    def test_nested_includes_are_expanded_once_each_where_they_stand(self):
        t = Tree(self)
        t.write("main.frag", '#version 450 core\n#include "lib/a.glsl"  // why\n#include "lib/b.glsl"\n'
                             "void main() {}\n")
        t.write("lib/a.glsl", '#include "lib/common.glsl"\nfloat a; // uses [brackets]; and \\ too\n')
        t.write("lib/b.glsl", '#include "lib/common.glsl"\n\nfloat b;\n#include "lib/a.glsl"\n')
        t.write("lib/common.glsl", "float common;")  # no final newline: the expansion ends the line
        t.write("other.vert", "void main() {}\r\n")
        rc, err, table = t.embed()
        self.assertEqual(rc, 0, err)
        self.assertEqual(table["main.frag"], "#version 450 core\nfloat common;\nfloat a; // uses [brackets]; and \\ too\n"
                                             "\nfloat b;\nvoid main() {}\n")
        # Every file is embedded expanded on its own, snippets too; other lines are copied as
        # they are.
        self.assertEqual(table["lib/b.glsl"], "float common;\n\nfloat b;\nfloat a; // uses [brackets]; and \\ too\n")
        self.assertEqual(table["lib/common.glsl"], "float common;\n")
        self.assertEqual(table["other.vert"], "void main() {}\n")  # CMake's file(READ) drops the \r
        self.assertEqual(sorted(table), ["lib/a.glsl", "lib/b.glsl", "lib/common.glsl", "main.frag", "other.vert"])

    def test_without_expansion_files_are_embedded_byte_for_byte(self):
        t = Tree(self)
        t.write("main.frag", '#include "missing.glsl"\n#include <what>\nno newline; é')
        rc, err, table = t.embed(expand=False)
        self.assertEqual(rc, 0, err)
        self.assertEqual(table, {"main.frag": '#include "missing.glsl"\n#include <what>\nno newline; é'})

    def test_missing_include_names_the_including_file_and_line(self):
        t = Tree(self)
        t.write("main.frag", '#version 450 core\n#include "lib/a.glsl"\n')
        t.write("lib/a.glsl", 'float a;\n\n#include "lib/nope.glsl"\n')
        error = self.failure(t)
        self.assertTrue(error.startswith(t.where("lib/a.glsl", 3) + '#include "lib/nope.glsl": no such file'), error)

    def test_include_of_a_file_that_is_not_embedded_is_missing(self):
        t = Tree(self)
        t.write("main.frag", '#include "lib/a.h"\n')
        t.write("lib/a.h", "float a;\n")  # matches none of the globs
        self.assertTrue(self.failure(t).startswith(t.where("main.frag", 1) + '#include "lib/a.h": no such file'))

    def test_cycle_names_the_line_that_closes_it(self):
        t = Tree(self)
        t.write("main.frag", '#include "a.glsl"\n')
        t.write("a.glsl", '#include "b.glsl"\n')
        t.write("b.glsl", '\n#include "a.glsl"\n')
        error = self.failure(t)
        self.assertTrue(error.startswith(t.where("b.glsl", 2) + '#include "a.glsl" is an include cycle'), error)
        self.assertIn("a.glsl -> b.glsl -> a.glsl", error)

    def test_self_include_is_a_cycle(self):
        t = Tree(self)
        t.write("main.frag", 'void main() {}\n#include "main.frag"\n')
        self.assertTrue(self.failure(t).startswith(t.where("main.frag", 2) + '#include "main.frag" is an include cycle'))

    def test_malformed_include_lines(self):
        for line in ['#include "a.glsl', '#include ""', "#include <a.glsl>", "#include a.glsl",
                     '  #include "a.glsl"', '# include "a.glsl"', '#include "a.glsl" "b.glsl"', "#include"]:
            with self.subTest(line=line):
                t = Tree(self)
                t.write("main.frag", f"#version 450 core\n{line}\n")
                t.write("a.glsl", "float a;\n")
                t.write("b.glsl", "float b;\n")
                self.assertTrue(self.failure(t).startswith(t.where("main.frag", 2) + "malformed include line"))

    def test_the_repository_shaders_expand(self):
        # The real tree, as the build embeds it: nothing fails and no include line is left.
        t = Tree(self)
        t.dir = SCRIPT.parent.parent / "shaders"
        rc, err, table = t.embed()
        self.assertEqual(rc, 0, err)
        self.assertGreater(len(table), 30)
        for path, source in table.items():
            self.assertNotRegex(source, re.compile(r"^[ \t]*#[ \t]*include", re.M), path)


if __name__ == "__main__":
    unittest.main()
