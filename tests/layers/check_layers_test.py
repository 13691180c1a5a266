"""The dependency check itself (scripts/check-layers): it runs on small trees written here and
must fail, naming file, line, parts and header, exactly where a part includes what it may not.

  python3 -m unittest -v check_layers_test      (ctest: layers.checker)
"""
import contextlib
import importlib.machinery
import importlib.util
import io
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

SCRIPT = Path(__file__).resolve().parent.parent.parent / "scripts" / "check-layers"


def load_script():
    loader = importlib.machinery.SourceFileLoader("check_layers", str(SCRIPT))
    module = importlib.util.module_from_spec(importlib.util.spec_from_loader(loader.name, loader))
    loader.exec_module(module)
    return module


def run(root, exceptions):
    """The script's exit status and output lines for the tree at `root`, with `exceptions` in
    place of the repository's FRONT_END_EXCEPTIONS (which name the repository's files)."""
    module = load_script()
    module.FRONT_END_EXCEPTIONS = exceptions
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        rc = module.main(["--root", str(root)])
    return rc, out.getvalue().splitlines()


class Tree:
    """A scratch repository: files written with `write(path, *lines)`, checked with `check()`."""

    def __init__(self):
        self._dir = tempfile.TemporaryDirectory()
        self.root = Path(self._dir.name)
        # A clean tree in the repository's layout, one file a part.
        self.write("include/inkshade/mesh.hpp", "#pragma once")
        self.write("include/inkshade/io.hpp", "#pragma once", '#include "inkshade/mesh.hpp"')
        self.write("include/inkshade/renderer.hpp", "#pragma once", '#include "inkshade/mesh.hpp"')
        self.write("include/inkshade/shading.hpp", "#pragma once")
        self.write("include/inkshade/style.hpp", "#pragma once", '#include "inkshade/shading.hpp"')
        self.write("include/inkshade/batch.hpp", "#pragma once", '#include "inkshade/mesh.hpp"')
        self.write("src/core/mesh.cpp", '#include "inkshade/mesh.hpp"', "#include <vector>")
        self.write("src/geometry/weld.hpp", "#pragma once", '#include "inkshade/mesh.hpp"')
        self.write("src/io/text_scanner.hpp", "#pragma once")
        self.write("src/io/load_mesh.cpp", '#include "geometry/weld.hpp"', '#include "io/text_scanner.hpp"',
                   '#include "tiny_gltf.h"')
        self.write("src/render/renderer.cpp", '#include "inkshade/renderer.hpp"', '#include "geometry/weld.hpp"',
                   "#include <epoxy/gl.h>")
        self.write("src/styles/style.cpp", '#include "inkshade/style.hpp"', '#include "io/text_scanner.hpp"')
        self.write("src/batch/jobs.hpp", "#pragma once", '#include "inkshade/batch.hpp"')
        self.write("src/batch/jobs.cpp", '#include "batch/jobs.hpp"', '#include "scene/request.hpp"',
                   '#include "inkshade/style.hpp"')
        self.write("apps/viewer/viewer.hpp", "#pragma once", '#include "inkshade/scene.hpp"')
        self.write("apps/inkshade/commands.hpp", "#pragma once")
        self.write("apps/inkshade/view_command.cpp", '#include "commands.hpp"', '#include "viewer/viewer.hpp"',
                   '#include "batch/jobs.hpp"')
        self.write("python/module.cpp", '#include "inkshade/batch.hpp"')
        # Front ends include public headers only, but for the files and headers listed here.
        self.exceptions = {("apps/inkshade/view_command.cpp", "batch/jobs.hpp"): "the jobs of a dry run"}

    def write(self, path, *lines):
        p = self.root / path
        p.parent.mkdir(parents=True, exist_ok=True)
        p.write_text("\n".join(lines) + "\n")

    def check(self):
        return run(self.root, self.exceptions)

    def close(self):
        self._dir.cleanup()


class CheckLayers(unittest.TestCase):
    def setUp(self):
        self.tree = Tree()
        self.addCleanup(self.tree.close)

    def assertFails(self, *expected):
        rc, out = self.tree.check()
        self.assertEqual(rc, 1, out)
        self.assertEqual(out[:-1], list(expected))
        self.assertRegex(out[-1], r"^check-layers: \d+ problem")

    def test_clean_tree_passes(self):
        rc, out = self.tree.check()
        self.assertEqual(rc, 0, out)
        self.assertRegex(out[-1], r"^check-layers: 18 files, \d+ includes, none crosses")

    def test_core_including_io_fails_with_file_line_parts_and_header(self):
        self.tree.write("src/core/batch_jobs.cpp", "// jobs", "#include <map>", "", '#include "io/text_scanner.hpp"')
        self.assertFails("src/core/batch_jobs.cpp:4: part core may not include io (io/text_scanner.hpp)")

    def test_each_forbidden_include_is_reported_in_file_and_line_order(self):
        self.tree.write("src/core/builtin_models.cpp", '#include "geometry/weld.hpp"',
                        '  #  include "inkshade/batch.hpp"')
        self.tree.write("src/render/batch_runner.cpp", '#include "inkshade/style.hpp"', '#include "inkshade/io.hpp"')
        self.assertFails(
            "src/core/builtin_models.cpp:1: part core may not include geometry (geometry/weld.hpp)",
            "src/core/builtin_models.cpp:2: part core may not include batch (inkshade/batch.hpp)",
            "src/render/batch_runner.cpp:1: part render may not include styles (inkshade/style.hpp)",
            "src/render/batch_runner.cpp:2: part render may not include io (inkshade/io.hpp)")

    def test_public_headers_belong_to_their_part(self):
        # style.hpp (styles) may include shading.hpp (render), but not renderer.hpp's part above it:
        # a core header may not include a styles one.
        self.tree.write("include/inkshade/mesh.hpp", "#pragma once", '#include "inkshade/style.hpp"')
        self.assertFails("include/inkshade/mesh.hpp:2: part core may not include styles (inkshade/style.hpp)")

    def test_angle_bracket_public_headers_count_too(self):
        self.tree.write("src/gpu/context.cpp", "#include <inkshade/renderer.hpp>")
        self.assertFails("src/gpu/context.cpp:1: part gpu may not include render (inkshade/renderer.hpp)")

    def test_unmapped_public_header_fails(self):
        self.tree.write("include/inkshade/novel.hpp", "#pragma once")
        rc, out = self.tree.check()
        self.assertEqual(rc, 1, out)
        self.assertIn("include/inkshade/novel.hpp:1: inkshade/novel.hpp belongs to no part", out[0])

    def test_scene_rules_hold_before_its_folder_exists(self):
        self.assertFalse((self.tree.root / "src/scene").exists())
        self.tree.write("src/styles/style.cpp", '#include "scene/request.hpp"')
        self.assertFails("src/styles/style.cpp:1: part styles may not include scene (scene/request.hpp)")

    def test_scene_may_not_include_batch(self):
        self.tree.write("src/scene/request.cpp", '#include "inkshade/style.hpp"', '#include "batch/jobs.hpp"')
        self.assertFails("src/scene/request.cpp:2: part scene may not include batch (batch/jobs.hpp)")

    def test_relative_include_resolves_beside_the_file(self):
        self.tree.write("src/core/helper.hpp", "#pragma once")
        self.tree.write("src/core/color.cpp", '#include "helper.hpp"', '#include "../geometry/weld.hpp"')
        self.assertFails("src/core/color.cpp:2: part core may not include geometry (../geometry/weld.hpp)")

    def test_viewer_may_not_include_the_cli(self):
        self.tree.write("apps/viewer/viewer.cpp", '#include "viewer.hpp"', '#include "../inkshade/commands.hpp"')
        self.assertFails("apps/viewer/viewer.cpp:2: part viewer may not include cli (../inkshade/commands.hpp)")

    def test_gl_is_render_s_alone(self):
        self.tree.write("src/styles/preview.cpp", '#include "gpu/shader_program.hpp"')
        self.tree.write("src/batch/runner.cpp", '#include "inkshade/renderer.hpp"', '#include "gpu/gl_context.hpp"')
        self.assertFails("src/batch/runner.cpp:2: part batch may not include gpu (gpu/gl_context.hpp)",
                         "src/styles/preview.cpp:1: part styles may not include gpu (gpu/shader_program.hpp)")

    def test_library_may_not_include_a_front_end(self):
        self.tree.write("src/batch/runner.cpp", '#include "viewer/viewer.hpp"')
        self.assertFails("src/batch/runner.cpp:1: part batch may not include viewer (viewer/viewer.hpp)")

    def test_front_ends_may_not_include_gpu(self):
        self.tree.write("apps/viewer/canvas.cpp", '#include "viewer.hpp"', '#include "gpu/gl_handle.hpp"')
        self.tree.write("python/module.cpp", '#include "inkshade/batch.hpp"', '#include "gpu/framebuffer.hpp"')
        self.assertFails("apps/viewer/canvas.cpp:2: part viewer may not include gpu (gpu/gl_handle.hpp)",
                         "python/module.cpp:2: part python may not include gpu (gpu/framebuffer.hpp)")

    def test_opengl_headers_are_gpu_s(self):
        # <epoxy/...> and "epoxy/..." alike; render may (the clean tree's renderer.cpp does).
        self.tree.write("apps/viewer/viewer.cpp", '#include "viewer.hpp"', "#include <epoxy/gl.h>")
        self.tree.write("apps/inkshade/render_command.cpp", '#include "epoxy/egl.h"')
        self.tree.write("src/styles/style.cpp", '#include "inkshade/style.hpp"', "#  include <epoxy/gl.h>")
        self.assertFails("src/styles/style.cpp:2: part styles may not include gpu (epoxy/gl.h)",
                         "apps/inkshade/render_command.cpp:1: part cli may not include gpu (epoxy/egl.h)",
                         "apps/viewer/viewer.cpp:2: part viewer may not include gpu (epoxy/gl.h)")

    def test_front_ends_include_public_headers_only(self):
        self.tree.write("apps/inkshade/info_command.cpp", '#include "commands.hpp"', '#include "inkshade/io.hpp"',
                        '#include "geometry/weld.hpp"')
        self.tree.write("python/module.cpp", '#include "io/text_scanner.hpp"')
        hint = " (or list it in FRONT_END_EXCEPTIONS of scripts/check-layers with the reason)"
        self.assertFails("apps/inkshade/info_command.cpp:3: part cli may include the library's public headers only, "
                         "not geometry/weld.hpp" + hint,
                         "python/module.cpp:1: part python may include the library's public headers only, "
                         "not io/text_scanner.hpp" + hint)

    def test_an_exception_is_for_its_file_only(self):
        self.tree.write("apps/viewer/viewer.cpp", '#include "batch/jobs.hpp"')
        rc, out = self.tree.check()
        self.assertEqual(rc, 1, out)
        self.assertTrue(out[0].startswith("apps/viewer/viewer.cpp:1: part viewer may include the library's public "
                                          "headers only, not batch/jobs.hpp"), out)
        self.assertEqual(len(out), 2, out)

    def test_front_ends_reach_the_renderer_through_scene(self):
        self.tree.write("include/inkshade/scene.hpp", "#pragma once", '#include "inkshade/renderer.hpp"')
        self.tree.write("apps/viewer/viewer.cpp", '#include "inkshade/scene.hpp"', '#include "inkshade/renderer.hpp"')
        rc, out = self.tree.check()
        self.assertEqual(rc, 1, out)
        self.assertEqual(out[:-1], ["apps/viewer/viewer.cpp:2: part viewer may not include inkshade/renderer.hpp: "
                                    "front ends draw through scene.hpp (render_scene, draw_scene_lines) (or list it "
                                    "in FRONT_END_EXCEPTIONS of scripts/check-layers with the reason)"])
        self.tree.exceptions[("apps/viewer/viewer.cpp", "inkshade/renderer.hpp")] = "a renderer across frames"
        rc, out = self.tree.check()
        self.assertEqual(rc, 0, out)

    def test_an_exception_no_include_uses_fails(self):
        self.tree.exceptions[("apps/inkshade/main.cpp", "core/name_suggestion.hpp")] = "did you mean"
        self.tree.write("apps/inkshade/view_command.cpp", '#include "commands.hpp"', '#include "viewer/viewer.hpp"')
        self.assertFails("apps/inkshade/main.cpp:1: the exception for core/name_suggestion.hpp matches no include "
                         "that needs it (remove it from FRONT_END_EXCEPTIONS)",
                         "apps/inkshade/view_command.cpp:1: the exception for batch/jobs.hpp matches no include "
                         "that needs it (remove it from FRONT_END_EXCEPTIONS)")

    def test_an_exception_needs_a_reason_and_may_not_name_gl(self):
        self.tree.exceptions[("apps/viewer/viewer.cpp", "io/text_scanner.hpp")] = " "
        rc, out = self.tree.check()
        self.assertEqual((rc, out), (1, ["scripts/check-layers: the exception for io/text_scanner.hpp in "
                                         "apps/viewer/viewer.cpp gives no reason"]))
        del self.tree.exceptions[("apps/viewer/viewer.cpp", "io/text_scanner.hpp")]
        for header in ("gpu/gl_handle.hpp", "epoxy/gl.h"):
            self.tree.exceptions[("apps/viewer/viewer.cpp", header)] = "a texture"
            rc, out = self.tree.check()
            self.assertEqual((rc, out), (1, [f"scripts/check-layers: the exception for {header} in "
                                             "apps/viewer/viewer.cpp names GL, which front ends never include"]))
            del self.tree.exceptions[("apps/viewer/viewer.cpp", header)]

    def test_unknown_source_folder_fails(self):
        self.tree.write("src/extra/thing.cpp", '#include "inkshade/mesh.hpp"')
        rc, out = self.tree.check()
        self.assertEqual(rc, 1, out)
        self.assertIn("src/extra/thing.cpp:1: src/extra is no part", out[0])

    def test_include_text_in_comments_is_not_an_include(self):
        self.tree.write("src/gpu/program.cpp", '// Expands `#include "file"` lines: #include "io/x.hpp"',
                        '/* #include "io/x.hpp" */')
        rc, out = self.tree.check()
        self.assertEqual(rc, 0, out)


class Rules(unittest.TestCase):
    def test_rules_print_and_have_no_cycle(self):
        r = subprocess.run([sys.executable, str(SCRIPT), "--rules"], capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stdout)
        self.assertIn("core     src/core/        may include: (nothing)", r.stdout)
        self.assertIn("scene    src/scene/", r.stdout)

    def test_a_cycle_in_the_rules_is_refused(self):
        module = load_script()
        self.assertIsNone(module.check_rules())
        module.ALLOWED["core"] = ["io"]  # io may include core already
        self.assertEqual(module.check_rules(), "the rules have a cycle: core -> io -> core")

if __name__ == "__main__":
    unittest.main()
