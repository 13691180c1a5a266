"""The Python module against the CLI: same pictures, same lines, clear errors.

Run by ctest with PYTHONPATH at the built module and INKSHADE_BIN at the CLI; needs only
Debian's python3 and python3-numpy (the PNG reader below is the standard library's zlib).
"""
import json
import os
import struct
import subprocess
import tempfile
import unittest
import zlib

import numpy as np

import inkshade

INKSHADE_BIN = os.environ["INKSHADE_BIN"]


def read_png(path):
    """RGBA, non-interlaced PNG (what inkshade writes) -> (h, w, 4) uint8, or uint16 for a 16-bit
    file, independent of inkshade."""
    with open(path, "rb") as f:
        data = f.read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat, width = 8, b"", 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
            assert depth in (8, 16) and colour == 6, "expected RGBA8 or RGBA16"
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = zlib.decompress(idat)
    bpp = 4 * depth // 8  # bytes a pixel: the filters' left neighbour
    stride = width * bpp
    out = np.zeros((height, stride), dtype=np.int32)
    prev = np.zeros(stride, dtype=np.int32)
    for y in range(height):
        f = raw[y * (stride + 1)]
        line = np.frombuffer(raw, dtype=np.uint8, count=stride, offset=y * (stride + 1) + 1).astype(np.int32)
        row = np.zeros(stride, dtype=np.int32)
        for x in range(stride):  # the five PNG filters (RFC 2083 section 6)
            a = row[x - bpp] if x >= bpp else 0
            b = prev[x]
            c = prev[x - bpp] if x >= bpp else 0
            if f == 0:
                p = 0
            elif f == 1:
                p = a
            elif f == 2:
                p = b
            elif f == 3:
                p = (a + b) // 2
            else:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                p = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
            row[x] = (line[x] + p) & 255
        out[y] = row
        prev = row
    if depth == 16:  # big-endian samples
        return (out[:, 0::2] * 256 + out[:, 1::2]).reshape(height, width, 4).astype(np.uint16)
    return out.reshape(height, width, 4).astype(np.uint8)


class ModuleTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.mesh = inkshade.load_mesh("builtin:torus")
        cls.renderer = inkshade.Renderer()
        cls.renderer.set_mesh(cls.mesh)

    def cli(self, *args):
        result = subprocess.run([INKSHADE_BIN, *args], capture_output=True, text=True)
        self.assertEqual(result.returncode, 0, result.stderr)

    def test_render_equals_the_cli_png(self):
        with tempfile.TemporaryDirectory() as tmp:
            png = os.path.join(tmp, "a.png")
            self.cli("render", "builtin:torus", "--style", "anime", "--size", "96x64", "--azimuth", "60",
                     "--elevation", "30", "--set", "cel.shade-color=0.2,0.1,0.3", "-o", png)
            image = self.renderer.render("anime", set=["cel.shade-color=0.2,0.1,0.3"], size=(96, 64),
                                         azimuth=60, elevation=30)
            self.assertEqual(image.shape, (64, 96, 4))
            self.assertEqual(image.dtype, np.uint8)
            np.testing.assert_array_equal(image, read_png(png))
            # Not a blank picture: the torus covers a good part of it.
            self.assertGreater(int((image[:, :, :3] != 255).any(axis=2).sum()), 96 * 64 // 8)

    def test_bit_depth_16_equals_the_cli_png(self):
        with tempfile.TemporaryDirectory() as tmp:
            png = os.path.join(tmp, "a.png")
            self.cli("render", "builtin:torus", "--size", "48x40", "--bit-depth", "16", "-o", png)
            image = self.renderer.render("lambert", size=(48, 40), bit_depth=16)
            self.assertEqual(image.dtype, np.uint16)
            expected = read_png(png)
            self.assertEqual(expected.dtype, np.uint16)
            np.testing.assert_array_equal(image, expected)
            with self.assertRaisesRegex(ValueError, "bit_depth: expected 8 or 16, got 12"):
                self.renderer.render("lambert", size=(8, 8), bit_depth=12)

    def test_batch_bit_depth_comes_from_the_option_table(self):
        """--bit-depth reaches `inkshade batch` (flag and column) and inkshade.batch(bit_depth=) through
        the option table alone: the same 16-bit PNG as `inkshade render --bit-depth 16`."""
        with tempfile.TemporaryDirectory() as tmp:
            png = os.path.join(tmp, "a.png")
            self.cli("render", "builtin:torus", "--size", "48x40", "--azimuth", "60", "--elevation", "30",
                     "--bit-depth", "16", "-o", png)
            expected = read_png(png)
            self.assertEqual(expected.dtype, np.uint16)
            manifest = os.path.join(tmp, "jobs.csv")
            with open(manifest, "w") as f:
                f.write("model,name,views,size,bit-depth\n"
                        "builtin:torus,column,60:30,48x40,16\n"
                        "builtin:torus,default,60:30,48x40,\n")

            def job(folder, name):
                stem = os.path.join(tmp, folder, name, "lambert", "az060_el30")
                with open(stem + ".json") as f:
                    return read_png(stem + ".png"), json.load(f)
            self.cli("batch", manifest, "-o", os.path.join(tmp, "cli"), "-q", "--bit-depth", "16")
            summary = inkshade.batch(os.path.join(tmp, "py"), manifest=manifest, bit_depth=16)
            self.assertEqual(summary["done"], 2)
            for folder in ("cli", "py"):
                for name in ("column", "default"):
                    image, meta = job(folder, name)
                    np.testing.assert_array_equal(image, expected, f"{folder}/{name}")
                    self.assertEqual(meta["bit_depth"], 16)
            # Without the flag the column alone asks for 16 bits; the other job is 8 bits again, a
            # new job hash, so resume renders it again and keeps the column's job.
            result = subprocess.run([INKSHADE_BIN, "batch", manifest, "-o", os.path.join(tmp, "cli")],
                                    capture_output=True, text=True)
            self.assertEqual(result.returncode, 0, result.stderr)
            self.assertIn("1 done, 1 skipped", result.stdout)
            image, meta = job("cli", "default")
            self.assertEqual(image.dtype, np.uint8)
            self.assertNotIn("bit_depth", meta)
            with open(manifest, "w") as f:
                f.write("model,bit-depth\nbuiltin:torus,12\n")
            result = subprocess.run([INKSHADE_BIN, "batch", manifest, "--dry-run"], capture_output=True, text=True)
            self.assertEqual(result.returncode, 2)
            self.assertEqual(result.stderr, f"inkshade: {manifest}:2: bit-depth: expected 8 or 16, got 12\n")
            with self.assertRaisesRegex(ValueError, "bit_depth: expected 8 or 16, got 12"):
                inkshade.batch(os.path.join(tmp, "py"), manifest=manifest, bit_depth=12)

    def test_one_request_gives_the_same_bytes_in_every_front_end(self):
        """`inkshade render`/`lines`, `inkshade batch`, inkshade.batch and Renderer.render/svg."""
        with tempfile.TemporaryDirectory() as tmp:
            options = ["builtin:torus", "--style", "ink-vector", "--size", "80x64", "--azimuth", "60",
                       "--elevation", "30"]
            png, svg = os.path.join(tmp, "cli.png"), os.path.join(tmp, "cli.svg")
            self.cli("render", *options, "-o", png)
            self.cli("lines", *options, "-o", svg)
            manifest = os.path.join(tmp, "jobs.jsonl")
            with open(manifest, "w") as f:
                f.write('{"model": "builtin:torus", "views": "60:30", "styles": "ink-vector", "size": "80x64", '
                        '"format": "png,svg"}\n')
            self.cli("batch", manifest, "-o", os.path.join(tmp, "cli-batch"), "-q")
            summary = inkshade.batch(os.path.join(tmp, "py-batch"), manifest=manifest)
            self.assertEqual(summary["done"], 1)

            def read(path, mode="rb"):
                with open(path, mode) as f:
                    return f.read()
            for batch in ("cli-batch", "py-batch"):
                stem = os.path.join(tmp, batch, "torus", "ink-vector", "az060_el30")
                self.assertEqual(read(stem + ".png"), read(png), batch)
                self.assertEqual(read(stem + ".svg"), read(svg), batch)
            view = dict(size=(80, 64), azimuth=60, elevation=30)
            np.testing.assert_array_equal(self.renderer.render("ink-vector", **view), read_png(png))
            self.assertEqual(self.renderer.svg(style="ink-vector", **view), read(svg, "r"))

    def test_svg_without_object_space_lines_draws_what_the_cli_draws(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "a.svg")
            self.cli("lines", "builtin:torus", "--style", "anime", "--size", "64x64", "-o", path)
            with open(path) as f:
                expected = f.read()
        svg = self.renderer.svg(style="anime", size=(64, 64))
        self.assertIn('id="contour"', svg)
        self.assertEqual(svg, expected)

    def test_lines_are_the_cli_json(self):
        import json
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "l.json")
            self.cli("lines", "builtin:torus", "--lines", "contour", "--size", "128x128", "--elevation", "50",
                     "-o", os.path.join(tmp, "l.svg"), "--lines-json", path)
            with open(path) as f:
                expected = json.load(f)
        lines = self.renderer.lines(["contour"], size=(128, 128), elevation=50)
        self.assertTrue(lines)
        self.assertTrue(all(l["type"] == "contour" for l in lines))
        want = [p for layer in expected["layers"] for p in layer["paths"]]
        self.assertEqual(len(lines), len(want))
        for got, exp in zip(lines, want):
            np.testing.assert_allclose(got["points"], np.array(exp["points"]), atol=1e-3)
            self.assertEqual(got["closed"], exp["closed"])

    def test_lines_json_detail_is_the_clis(self):
        """lines_json_detail='full' gives each path the arrays --lines-json-detail full writes; the
        batch format lines-json writes STEM.lines.json."""
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "l.json")
            self.cli("lines", "builtin:torus", "--lines", "contour", "--size", "128x128", "--elevation", "50",
                     "-o", os.path.join(tmp, "l.svg"), "--lines-json", path, "--lines-json-detail", "full")
            with open(path) as f:
                expected = json.load(f)
            manifest = os.path.join(tmp, "jobs.csv")
            with open(manifest, "w") as f:
                f.write("model,name,styles,size\nbuiltin:torus,t,ink-vector,64x48\n")
            summary = inkshade.batch(os.path.join(tmp, "ds"), manifest=manifest, formats=["lines-json"],
                                     lines_json_detail="full")
            self.assertEqual(summary["done"], 1)
            with open(os.path.join(tmp, "ds", "t", "ink-vector", "az035_el20.lines.json")) as f:
                self.assertIn("barycentric", json.load(f)["layers"][0]["paths"][0])
        lines = self.renderer.lines(["contour"], size=(128, 128), elevation=50, lines_json_detail="full")
        want = [p for layer in expected["layers"] for p in layer["paths"]]
        self.assertEqual(len(lines), len(want))
        for got, exp in zip(lines, want):
            self.assertEqual(got["world"].shape, (len(exp["points"]), 3))
            self.assertEqual(got["face"].dtype, np.int32)
            np.testing.assert_array_equal(got["face"], exp["face"])
            for key in ("world", "barycentric", "tangent", "normal"):
                np.testing.assert_allclose(got[key], np.array(exp[key]), atol=1e-6)
        self.assertNotIn("world", self.renderer.lines(["contour"], size=(128, 128), elevation=50)[0])
        with self.assertRaisesRegex(ValueError, "lines_json_detail"):
            self.renderer.lines(["contour"], lines_json_detail="most")

    def test_lines_carry_occlusion_levels(self):
        # A torus from 20 degrees above its plane: its inner contour passes behind the tube (two
        # surfaces in front) and runs on behind its own sheet past the cusps (one).
        view = dict(size=(160, 120), up_axis="z", elevation=20)
        lines = self.renderer.lines(["contour"], occlusion_levels="0-", **view)
        self.assertEqual({l["level"] for l in lines}, {0, 1, 2})
        self.assertTrue(all(l["hidden"] == (l["level"] > 0) for l in lines))
        only_one = self.renderer.lines(["contour"], occlusion_levels="1", **view)
        self.assertTrue(only_one)
        self.assertEqual({l["level"] for l in only_one}, {1})
        svg = self.renderer.svg(["contour"], occlusion_levels="0-1", **view)
        self.assertIn('id="contour-hidden-1"', svg)
        self.assertNotIn('id="contour-hidden-2"', svg)
        with self.assertRaisesRegex(ValueError, "occlusion levels: expected A-B"):
            self.renderer.lines(["contour"], occlusion_levels="3-1", **view)

    def test_svg_has_layers(self):
        svg = self.renderer.svg(["contour", "crease"], size=(64, 64))
        self.assertIn('id="contour"', svg)
        self.assertTrue(svg.startswith("<?xml"))

    def test_listings(self):
        self.assertIn("anime", inkshade.styles())
        self.assertIn("suggestive", inkshade.line_types())
        self.assertIn("shininess", inkshade.shading_models()["phong"]["params"])
        self.assertEqual(self.mesh.triangle_count > 0, True)

    def test_batch_renders_resumes_and_matches_render(self):
        with tempfile.TemporaryDirectory() as tmp:
            manifest = os.path.join(tmp, "jobs.csv")
            with open(manifest, "w") as f:
                f.write("model,views,styles,size\nbuiltin:torus,0:0;90:30,lambert,48x32\n")
            events = []
            summary = inkshade.batch(os.path.join(tmp, "out"), manifest=manifest, progress=events.append)
            self.assertEqual((summary["total"], summary["done"], summary["failed"]), (2, 2, 0))
            self.assertEqual(len(events), 2)
            self.assertEqual({e["status"] for e in events}, {"done"})
            pngs = sorted(os.path.join(root, n) for root, _, names in os.walk(os.path.join(tmp, "out"))
                          for n in names if n.endswith(".png"))
            self.assertEqual(len(pngs), 2)
            view = [p for p in pngs if "az090" in p][0]
            np.testing.assert_array_equal(read_png(view), self.renderer.render("lambert", size=(48, 32),
                                                                               azimuth=90, elevation=30))
            again = inkshade.batch(os.path.join(tmp, "out"), manifest=manifest)
            self.assertEqual((again["done"], again["skipped"]), (0, 2))
        with self.assertRaisesRegex(ValueError, "exactly one of"):
            inkshade.batch("/tmp/x")

    def test_batch_layouts_as_the_cli_takes_them(self):
        """layout=, shard_size=, shard_prefix= and transforms_json= as batch's --layout, --shard-size,
        --shard-prefix and --transforms-json: the shard holds the folder layout's files, byte for byte."""
        import tarfile
        with tempfile.TemporaryDirectory() as tmp:
            manifest = os.path.join(tmp, "jobs.csv")
            with open(manifest, "w") as f:
                f.write("model,views,styles,size\nbuiltin:torus,0:0;90:30,lambert,48x32\n")
            folder = os.path.join(tmp, "folder")
            self.assertEqual(inkshade.batch(folder, manifest=manifest, transforms_json=True)["done"], 2)
            with open(os.path.join(folder, "torus", "lambert", "transforms.json")) as f:
                self.assertEqual(len(json.load(f)["frames"]), 2)
            shards = os.path.join(tmp, "shards")
            summary = inkshade.batch(shards, manifest=manifest, layout="webdataset", shard_size="10MB",
                                     shard_prefix="torus", shard=(1, 1))
            self.assertEqual(summary["done"], 2)
            self.assertEqual(os.listdir(shards), ["torus-1of1-000000.tar"])
            with tarfile.open(os.path.join(shards, "torus-1of1-000000.tar")) as tar:
                pngs = {m.name: tar.extractfile(m).read() for m in tar.getmembers() if m.name.endswith(".png")}
            self.assertEqual(len(pngs), 2)
            for name, data in pngs.items():
                with open(os.path.join(folder, name), "rb") as f:
                    self.assertEqual(f.read(), data, name)
            with self.assertRaisesRegex(ValueError, "only with layout='folder'"):
                inkshade.batch(shards, manifest=manifest, layout="webdataset", transforms_json=True)
            with self.assertRaisesRegex(ValueError, "expected folder or webdataset"):
                inkshade.batch(shards, manifest=manifest, layout="tar")
            with self.assertRaisesRegex(ValueError, "shard-size"):
                inkshade.batch(shards, manifest=manifest, layout="webdataset", shard_size="0")

    def test_batch_occlusion_levels_and_light_intensity(self):
        """occlusion_levels= gives the SVG the lines command gives; light_intensity= reaches the job."""
        with tempfile.TemporaryDirectory() as tmp:
            manifest = os.path.join(tmp, "jobs.csv")
            with open(manifest, "w") as f:
                f.write("model,views,styles,size,up-axis\nbuiltin:torus,20:20,ink-vector,96x72,z\n")
            summary = inkshade.batch(os.path.join(tmp, "out"), manifest=manifest, formats=["svg"],
                                     occlusion_levels="0-1", light_intensity=2.5)
            self.assertEqual((summary["done"], summary["failed"]), (1, 0))
            stem = os.path.join(tmp, "out", "torus", "ink-vector", "az020_el20")
            with open(stem + ".svg") as f:
                svg = f.read()
            self.assertIn('<g id="contour-hidden-1"', svg)
            ref = os.path.join(tmp, "l.svg")
            subprocess.run([os.environ["INKSHADE_BIN"], "lines", "builtin:torus", "--style", "ink-vector", "--size",
                            "96x72", "--up-axis", "z", "--azimuth", "20", "--elevation", "20",
                            "--occlusion-levels", "0-1", "-o", ref], check=True)
            with open(ref) as f:
                self.assertEqual(svg, f.read())
            with open(stem + ".json") as f:
                meta = json.load(f)
            self.assertEqual(meta["occlusion_levels"], [0, 1])
            self.assertEqual(meta["light_intensity"], 2.5)
        with self.assertRaisesRegex(ValueError, "occlusion levels"):
            inkshade.batch("/tmp/x", models="/tmp", occlusion_levels="3-1")

    def test_gltf_camera_and_lights_are_the_clis(self):
        """camera= and lights= as `inkshade render --camera --lights file` and a batch view camera=NAME."""
        import base64
        import json
        import warnings
        positions = [-1, -1, 0, 1, -1, 0, 0, 1, 0.5]
        data = struct.pack("<9f", *positions)
        doc = {
            "asset": {"version": "2.0"},
            "buffers": [{"byteLength": len(data),
                         "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
            "bufferViews": [{"buffer": 0, "byteLength": len(data)}],
            "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                           "min": [-1, -1, 0], "max": [1, 1, 0.5]}],
            "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
            "cameras": [{"type": "perspective", "name": "Cam",
                         "perspective": {"yfov": 0.8, "aspectRatio": 2.0, "znear": 0.1}}],
            "extensions": {"KHR_lights_punctual": {"lights": [
                {"type": "point", "name": "Lamp", "intensity": 20}, {"type": "directional", "name": "Fill"}]}},
            "nodes": [{"mesh": 0}, {"camera": 0, "translation": [0.5, 0.2, 4]},
                      {"extensions": {"KHR_lights_punctual": {"light": 0}}, "translation": [0, 0, 2]},
                      {"extensions": {"KHR_lights_punctual": {"light": 1}}}],
            "scenes": [{"nodes": [0, 1, 2, 3]}], "scene": 0}
        with tempfile.TemporaryDirectory() as tmp:
            model = os.path.join(tmp, "scene.gltf")
            with open(model, "w") as f:
                json.dump(doc, f)
            mesh = inkshade.load_mesh(model)
            self.assertEqual(mesh.cameras, ["Cam"])
            self.assertEqual(mesh.lights, ["Lamp", "Fill"])
            renderer = inkshade.Renderer()
            renderer.set_mesh(mesh)
            png = os.path.join(tmp, "cli.png")
            self.cli("render", model, "--camera", "Cam", "--lights", "file", "--style", "threejs-lambert",
                     "--size", "512x256", "-o", png)
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always")
                image = renderer.render("threejs-lambert", camera="Cam", lights="file")  # aspect 2: 512x256
            self.assertEqual([str(w.message) for w in caught],
                             ["the mesh: 2 lights; Inkshade shades with one, the first: 'Lamp' (point)"])
            np.testing.assert_array_equal(image, read_png(png))
            self.assertEqual(renderer.render("lambert", camera=0, size=(64, 64)).shape, (64, 64, 4))
            with self.assertRaisesRegex(ValueError, "^camera: the mesh has no camera 'cma' "
                                        r"\(did you mean 'Cam'\?\); its cameras: 0 'Cam'$"):
                renderer.render("lambert", camera="cma")
            with self.assertRaisesRegex(ValueError, "^camera and fov are alternatives"):
                renderer.render("lambert", camera="Cam", fov=20)
            self.cli("render", model, "--camera", "Cam", "--size", "512x512", "-o", png)
            summary = inkshade.batch(os.path.join(tmp, "out"), models=tmp, views="camera=Cam")
            self.assertEqual(summary["done"], 1)
            with open(os.path.join(tmp, "out", "scene", "lambert", "camera-Cam.png"), "rb") as f, \
                    open(png, "rb") as g:
                self.assertEqual(f.read(), g.read())

    def test_bad_input_raises_value_error(self):
        with self.assertRaisesRegex(ValueError, "nope.obj"):
            inkshade.load_mesh("/nope.obj")
        with self.assertRaisesRegex(ValueError, "unknown keyword 'szie'"):
            self.renderer.render("lambert", szie=(8, 8))
        with self.assertRaisesRegex(ValueError, "no-such-style"):
            self.renderer.render("no-such-style")
        with self.assertRaisesRegex(ValueError, "size"):
            self.renderer.render("lambert", size=(0, 8))
        with self.assertRaisesRegex(ValueError, r"^fov: expected degrees in \(0, 180\)$"):
            self.renderer.render("lambert", fov=0)  # checked as the CLI checks --fov, not clamped
        with self.assertRaisesRegex(ValueError, r"^set hull.width=2: .*'hull'"):
            self.renderer.render("cel", set=["hull.width=2"])
        with self.assertRaisesRegex(ValueError, r"^types: 'hull' is drawn in the image"):
            self.renderer.lines(["hull"])
        with self.assertRaisesRegex(ValueError, r"^up_axis: expected x, y, z"):
            self.renderer.render("lambert", up_axis="w")
        self.assertEqual(self.renderer.render("lambert", size=(8, 8), up_axis="z").shape, (8, 8, 4))
        with self.assertRaisesRegex(ValueError, r"^light_type: expected directional or point"):
            self.renderer.render("lambert", light_type="spot")
        with self.assertRaisesRegex(ValueError, "no mesh"):
            inkshade.Renderer().render("lambert")


class AovTest(unittest.TestCase):
    """render(aov=[...]) and batch(aov=[...]): arrays without copies, the CLI's files."""

    @classmethod
    def setUpClass(cls):
        cls.r = inkshade.Renderer()
        cls.r.set_mesh(inkshade.load_mesh("builtin:sphere:rings=128,segments=256"))

    def test_arrays_types_and_no_copies(self):
        out = self.r.render("anime", size=(96, 64), aov=["depth", "normal", "id", "material", "mask", "lines"])
        self.assertEqual(out["image"].shape, (64, 96, 4))
        expected = {"depth": (np.float32, (64, 96)), "normal": (np.float32, (64, 96, 3)),
                    "id": (np.uint32, (64, 96)), "material": (np.uint32, (64, 96)), "mask": (np.uint8, (64, 96)),
                    "lines-hull": (np.uint8, (64, 96)), "lines-rim-contour": (np.uint8, (64, 96))}
        for name, (dtype, shape) in expected.items():
            self.assertEqual(out[name].dtype, dtype, name)
            self.assertEqual(out[name].shape, shape, name)
            self.assertFalse(out[name].flags["OWNDATA"], name)  # a view of the renderer's buffer
        fg = out["depth"] > 0
        self.assertTrue(np.array_equal(fg, out["id"] > 0))
        self.assertTrue(np.all(out["mask"][fg & (out["mask"] < 255)] > 0))
        n = np.linalg.norm(out["normal"][fg], axis=1)
        self.assertLess(np.max(np.abs(n - 1)), 1e-4)
        self.assertEqual(out["camera"]["image"], {"width": 96, "height": 64})

    def test_depth_reprojects_to_the_sphere(self):
        # The recipe of docs/aov.md.
        out = self.r.render(size=(160, 120), azimuth=20, elevation=30, aov=["depth"])
        depth, cam = out["depth"], out["camera"]
        K = np.array(cam["K"])
        cam_to_world = np.linalg.inv(np.array(cam["world_to_camera_opencv"]))
        v, u = np.nonzero(depth > 0)
        d = depth[v, u]
        x = (u + 0.5 - K[0, 2]) / K[0, 0] * d
        y = (v + 0.5 - K[1, 2]) / K[1, 1] * d
        points = (cam_to_world @ np.stack([x, y, d, np.ones_like(d)]))[:3].T
        self.assertAlmostEqual(np.linalg.norm(points, axis=1).mean(), 1.0, delta=0.005)

    def test_same_as_cli_files(self):
        with tempfile.TemporaryDirectory() as tmp:
            png = os.path.join(tmp, "a.png")
            result = subprocess.run([INKSHADE_BIN, "render", "builtin:sphere:rings=128,segments=256", "-o", png,
                                     "--size", "64x48", "--aov", "camera"], capture_output=True, text=True)
            self.assertEqual(result.returncode, 0, result.stderr)
            with open(os.path.join(tmp, "a.camera.json")) as f:
                self.assertEqual(json.load(f), self.r.render(size=(64, 48), aov=["camera"])["camera"])

    def test_surface_fields(self):
        # docs/aov.md's surface fields on the unit sphere: k1 = k2 = kr = 1, n.v from the camera,
        # pdir as unit 2-vectors, the camera's p90 factors numpy's.
        names = ["depth", "ndotv", "kr", "k1", "k2", "pdir1", "shading-scales"]
        out = self.r.render(size=(96, 64), azimuth=20, elevation=30, aov=names)
        fg = out["depth"] > 0
        for name in ("ndotv", "kr", "k1", "k2", "shading-s0", "shading-s4"):
            self.assertEqual((out[name].dtype, out[name].shape), (np.float32, (64, 96)), name)
            self.assertFalse(np.any(out[name][~fg]), name)  # 0 on the background
        self.assertEqual(out["pdir1"].shape, (64, 96, 2))
        self.assertLess(np.max(np.abs(np.linalg.norm(out["pdir1"][fg], axis=1) - 1)), 1e-4)
        for name in ("kr", "k1", "k2"):
            self.assertLess(np.max(np.abs(out[name][fg] - 1)), 0.01, name)
        cam = out["camera"]
        K = np.array(cam["K"])
        cam_to_world = np.linalg.inv(np.array(cam["world_to_camera_opencv"]))
        v, u = np.nonzero(fg)
        d = out["depth"][v, u]
        x = (u + 0.5 - K[0, 2]) / K[0, 0] * d
        y = (v + 0.5 - K[1, 2]) / K[1, 1] * d
        p = (cam_to_world @ np.stack([x, y, d, np.ones_like(d)]))[:3].T
        view = np.array(cam["eye"]) - p
        ndotv = np.sum(p / np.linalg.norm(p, axis=1)[:, None] * view / np.linalg.norm(view, axis=1)[:, None], axis=1)
        self.assertLess(np.max(np.abs(out["ndotv"][v, u] - ndotv)), 2e-3)
        for name in ("kr", "k1", "k2"):
            self.assertAlmostEqual(cam["fields"]["p90"][name], np.percentile(np.abs(out[name][fg]), 90), places=5)

    def test_bad_name_and_batch(self):
        with self.assertRaisesRegex(ValueError, r"^aov: unknown AOV 'nromal' .*\(did you mean 'normal'\?\)$"):
            self.r.render(aov=["nromal"])
        with tempfile.TemporaryDirectory() as tmp:
            jobs = os.path.join(tmp, "jobs.csv")
            with open(jobs, "w") as f:
                f.write('model,name,size,aov\nbuiltin:sphere,a,32x32,"mask"\nbuiltin:torus,b,32x32,\n')
            summary = inkshade.batch(os.path.join(tmp, "ds"), manifest=jobs, aov=["depth"])
            self.assertEqual(summary["done"], 2)
            files = sorted(os.listdir(os.path.join(tmp, "ds", "a", "lambert")))
            self.assertIn("az035_el20.mask.png", files)
            self.assertNotIn("az035_el20.depth.exr", files)
            self.assertIn("az035_el20.depth.exr", os.listdir(os.path.join(tmp, "ds", "b", "lambert")))


def posed_glb(path):
    """A VRM 1.0 file built here: a box on a node that the animation "spin" turns about +z (0 to
    90 degrees over 2 s), with a morph target "lift" bound by the expression "happy"."""
    corners = [(x, y, z) for x in (-1, 1) for y in (-1, 1) for z in (-0.2, 0.2)]
    faces = [0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4, 2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5]
    lift = [(0, 0.5 if y > 0 else 0, 0) for x, y, z in corners]
    half = 0.7071067811865476
    chunks = [
        struct.pack("<24f", *[c for p in corners for c in p]),
        struct.pack("<36H", *faces),
        struct.pack("<24f", *[c for p in lift for c in p]),
        struct.pack("<2f", 0, 2),
        struct.pack("<8f", 0, 0, 0, 1, 0, 0, half, half),
    ]
    views, offset = [], 0
    for chunk in chunks:
        views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(chunk)})
        offset += len(chunk)
    binary = b"".join(chunks)
    doc = {
        "asset": {"version": "2.0"},
        "extensionsUsed": ["VRMC_vrm"],
        "extensions": {"VRMC_vrm": {"specVersion": "1.0", "expressions": {
            "preset": {"happy": {"morphTargetBinds": [{"node": 0, "index": 0, "weight": 1.0}]}}}}},
        "buffers": [{"byteLength": len(binary)}],
        "bufferViews": views,
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 8, "type": "VEC3",
             "min": [-1, -1, -0.2], "max": [1, 1, 0.2]},
            {"bufferView": 1, "componentType": 5123, "count": 36, "type": "SCALAR"},
            {"bufferView": 2, "componentType": 5126, "count": 8, "type": "VEC3"},
            {"bufferView": 3, "componentType": 5126, "count": 2, "type": "SCALAR"},
            {"bufferView": 4, "componentType": 5126, "count": 2, "type": "VEC4"},
        ],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "targets": [{"POSITION": 2}]}],
                    "extras": {"targetNames": ["lift"]}}],
        "nodes": [{"mesh": 0}],
        "scenes": [{"nodes": [0]}],
        "scene": 0,
        "animations": [{"name": "spin", "samplers": [{"input": 3, "output": 4}],
                        "channels": [{"sampler": 0, "target": {"node": 0, "path": "rotation"}}]}],
    }
    text = json.dumps(doc).encode()
    text += b" " * (-len(text) % 4)
    glb = struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(text) + 8 + len(binary))
    glb += struct.pack("<I4s", len(text), b"JSON") + text + struct.pack("<I4s", len(binary), b"BIN\0") + binary
    with open(path, "wb") as f:
        f.write(glb)


class PoseTest(unittest.TestCase):
    """time=, animation=, morph=, expression= on load_mesh and on render, as the CLI's options."""

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.model = os.path.join(cls.tmp.name, "box.vrm")
        posed_glb(cls.model)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def cli_png(self, *options):
        png = os.path.join(self.tmp.name, "cli.png")
        # --style lambert: the avatar is a VRM, whose default look is vrm (Python's too without a style)
        result = subprocess.run([INKSHADE_BIN, "render", self.model, "--style", "lambert", "--size", "64x48", *options,
                                 "-o", png],
                                capture_output=True, text=True)
        self.assertEqual(result.returncode, 0, result.stderr)
        return read_png(png)

    def test_render_without_a_style_takes_the_files_default_look(self):
        # A VRM file's default look is the vrm style, in Python as in `inkshade render FILE`.
        r = inkshade.Renderer()
        r.set_mesh(inkshade.load_mesh(self.model))
        png = os.path.join(self.tmp.name, "plain.png")
        result = subprocess.run([INKSHADE_BIN, "render", self.model, "--size", "64x48", "-o", png],
                                capture_output=True, text=True)
        self.assertEqual(result.returncode, 0, result.stderr)
        plain = r.render(size=(64, 48))
        np.testing.assert_array_equal(plain, read_png(png))
        np.testing.assert_array_equal(plain, r.render("vrm", size=(64, 48)))
        self.assertFalse(np.array_equal(plain, r.render("lambert", size=(64, 48))))

    def test_render_keywords_are_the_clis_options(self):
        r = inkshade.Renderer()
        r.set_mesh(inkshade.load_mesh(self.model))
        rest = r.render("lambert", size=(64, 48))
        np.testing.assert_array_equal(rest, self.cli_png())
        spun = r.render("lambert", size=(64, 48), animation="spin", time=1.0)
        np.testing.assert_array_equal(spun, self.cli_png("--animation", "spin", "--time", "1"))
        self.assertFalse(np.array_equal(spun, rest))
        # The mesh keeps the pose; time= alone samples the same animation again.
        np.testing.assert_array_equal(r.render("lambert", size=(64, 48), time=2.0),
                                      self.cli_png("--animation", "spin", "--time", "2"))
        happy = r.render("lambert", size=(64, 48), animation=0, time=0.5, expression={"happy": 1.0},
                         morph=["lift=0.5"])
        np.testing.assert_array_equal(happy, self.cli_png("--animation", "0", "--time", "0.5", "--expression",
                                                          "happy=1", "--morph", "lift=0.5"))
        svg = r.svg(["contour"], size=(64, 48), animation="spin", time=1.0)
        self.assertIn("<path", svg)

    def test_load_mesh_takes_the_pose(self):
        r = inkshade.Renderer()
        r.set_mesh(inkshade.load_mesh(self.model, animation="spin", time=1.0, morph={"lift": 1.0}))
        np.testing.assert_array_equal(r.render("lambert", size=(64, 48)),
                                      self.cli_png("--animation", "spin", "--time", "1", "--morph", "lift=1"))
        with self.assertRaisesRegex(ValueError, r"no animation 'spn' \(did you mean 'spin'\?\)"):
            inkshade.load_mesh(self.model, animation="spn")
        with self.assertRaisesRegex(ValueError, r"^expression: happy: expression weights are in \[0, 1\], got 2$"):
            inkshade.load_mesh(self.model, expression={"happy": 2})
        with self.assertRaisesRegex(ValueError, r"^morph: expected NAME=WEIGHT, got 'lift'$"):
            r.render("lambert", morph=["lift"])
        with self.assertRaisesRegex(ValueError, "no morph target 'lfit'"):
            r.render("lambert", morph={"lfit": 1})
        with self.assertRaisesRegex(ValueError, "unknown keyword 'pose'"):
            inkshade.load_mesh(self.model, pose=1)
        # A .vrma path is a VRM animation file, which needs a VRM humanoid (the box has none).
        with self.assertRaisesRegex(ValueError, "has no VRM humanoid, which the VRM animation 'walk.vrma' needs"):
            inkshade.load_mesh(self.model, animation="walk.vrma")

    def test_batch_samples_an_animation(self):
        manifest = os.path.join(self.tmp.name, "frames.csv")
        with open(manifest, "w") as f:
            f.write("model,name,time\n" + self.model + ",t1,1\n" + self.model + ",t2,\n")
        out = os.path.join(self.tmp.name, "frames")
        summary = inkshade.batch(out, manifest=manifest, size=(64, 48), views="35:20", styles=["lambert"],
                                 animation="spin", time=2.0)
        self.assertEqual(summary["done"], 2, summary["failures"])
        for stem, t in (("t1", "1"), ("t2", "2")):  # t2 takes the default time
            np.testing.assert_array_equal(read_png(os.path.join(out, stem, "lambert", "az035_el20.png")),
                                          self.cli_png("--animation", "spin", "--time", t))


class SpringBonesTest(unittest.TestCase):
    """spring_bones= and the time on render, load_mesh and batch, as the CLI's --spring-bones and
    --time: the sample avatar's ponytail (scripts/avatar-sample --spring-hair)."""

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.model = os.path.join(cls.tmp.name, "ponytail.vrm")
        script = os.path.join(os.path.dirname(__file__), "..", "..", "scripts", "avatar-sample")
        subprocess.run(["python3", script, "--spring-hair", cls.model], check=True)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def cli_png(self, *options):
        png = os.path.join(self.tmp.name, "cli.png")
        # --style lambert: a VRM's default look is vrm; these renders compare lambert
        result = subprocess.run([INKSHADE_BIN, "render", self.model, "--style", "lambert", "--size", "64x48",
                                 "--azimuth", "115", *options,
                                 "-o", png], capture_output=True, text=True)
        self.assertEqual(result.returncode, 0, result.stderr)
        return read_png(png)

    def test_render_and_load_mesh_take_spring_bones_and_the_time(self):
        r = inkshade.Renderer()
        r.set_mesh(inkshade.load_mesh(self.model))
        swung = r.render("lambert", size=(64, 48), azimuth=115, animation="sway", time=2.0)
        np.testing.assert_array_equal(swung, self.cli_png("--animation", "sway", "--time", "2"))
        rigid = r.render("lambert", size=(64, 48), azimuth=115, animation="sway", time=2.0, spring_bones="off")
        np.testing.assert_array_equal(rigid, self.cli_png("--animation", "sway", "--time", "2", "--spring-bones", "off"))
        self.assertFalse(np.array_equal(swung, rigid))
        # The time alone lets the ponytail fall under gravity.
        r.set_mesh(inkshade.load_mesh(self.model, time=1.0))
        fallen = r.render("lambert", size=(64, 48), azimuth=115)
        np.testing.assert_array_equal(fallen, self.cli_png("--time", "1"))
        self.assertFalse(np.array_equal(fallen, self.cli_png()))
        with self.assertRaisesRegex(ValueError, "spring_bones: expected on or off"):
            r.render("lambert", spring_bones="maybe")

    def test_batch_column(self):
        manifest = os.path.join(self.tmp.name, "springs.csv")
        with open(manifest, "w") as f:
            f.write("model,name,spring-bones\n" + self.model + ",on,on\n" + self.model + ",off,off\n")
        out = os.path.join(self.tmp.name, "springs")
        summary = inkshade.batch(out, manifest=manifest, size=(64, 48), views="115:20", styles=["lambert"],
                                 animation="sway", time=2.0)
        self.assertEqual(summary["done"], 2, summary["failures"])
        for stem in ("on", "off"):
            np.testing.assert_array_equal(read_png(os.path.join(out, stem, "lambert", "az115_el20.png")),
                                          self.cli_png("--elevation", "20", "--animation", "sway", "--time", "2",
                                                       "--spring-bones", stem))


if __name__ == "__main__":
    unittest.main()


class LineSetTest(unittest.TestCase):
    """A style with line sets through Renderer.svg, lines and render(lineset_ids=True)."""

    STYLE = ('[shading]\nmodel = "lambert"\n'
             '[[lineset]]\nname = "left"\nobjects = "Left"\n[[lineset.lines]]\ntype = "crease"\nwidth = 2.0\n'
             '[[lineset]]\nname = "right"\nobjects = "Right*"\n[[lineset.lines]]\ntype = "crease"\n')

    @staticmethod
    def cube_obj(name, x):
        corners = [(x + (i & 1), (i >> 1) & 1, (i >> 2) & 1) for i in range(8)]
        quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
        return corners, quads, name

    def test_each_set_draws_the_faces_it_selects(self):
        with tempfile.TemporaryDirectory() as tmp:
            obj, style = os.path.join(tmp, "parts.obj"), os.path.join(tmp, "sets.toml")
            with open(obj, "w") as f:
                for k, (name, x) in enumerate((("Left", -1.5), ("RightPart", 0.5))):
                    corners, quads, _ = self.cube_obj(name, x)
                    f.write(f"o {name}\n")
                    f.writelines(f"v {a} {b} {c}\n" for a, b, c in corners)
                    f.writelines("f " + " ".join(str(8 * k + i + 1) for i in q) + "\n" for q in quads)
            with open(style, "w") as f:
                f.write(self.STYLE)
            r = inkshade.Renderer()
            r.set_mesh(inkshade.load_mesh(obj))
            view = dict(size=(160, 80), elevation=20, azimuth=20)
            svg = r.svg(style=style, **view)
            self.assertIn('<g id="lineset-left"', svg)
            self.assertIn('<g id="right-crease"', svg)
            lines = r.lines(style=style, **view)
            sets = {l["lineset"] for l in lines}
            self.assertEqual(sets, {"left", "right"})
            for l in lines:  # the left cube projects left of the image's centre
                side = l["points"][:, 0] < 80
                self.assertTrue(np.all(side) if l["lineset"] == "left" else not np.any(side))
            out = r.render(style, lineset_ids=True, **view)
            self.assertGreater(np.count_nonzero(out["lineset-left"][:, :80] > 128), 50)
            self.assertEqual(np.count_nonzero(out["lineset-left"][:, 80:] > 128), 0)
            self.assertEqual(np.count_nonzero(out["lineset-right"][:, :80] > 128), 0)
