"""Small VRM files for the reference test: one mesh with one MToon material, one glTF camera and
one KHR_lights_punctual light, as VRM 1.0 (VRMC_materials_mtoon) or VRM 0.x (extensions.VRM,
shader VRM/MToon) GLB. Python's standard library only; the PNG textures are written by hand.

The files carry no humanoid: three-vrm then builds no VRM object but still replaces the
materials by MToonMaterial and adds the outline (MToonMaterialLoaderPlugin works per material),
and Inkshade reads the materials the same way."""
import json
import math
import struct

import png_file


def png(width, height, texel):
    """An RGB or RGBA PNG's bytes, texel(x, y) -> (r, g, b) or (r, g, b, a), row 0 at the top."""
    channels = len(texel(0, 0))
    return png_file.encode(width, height, bytes(c for y in range(height) for x in range(width) for c in texel(x, y)), channels)


class Mesh:
    """Positions, unit normals, uvs, counter-clockwise triangles and optional linear vertex
    colours (written as COLOR_0)."""

    def __init__(self, p, n, uv, t, colors=None):
        self.p, self.n, self.uv, self.t, self.colors = p, n, uv, t, colors


def _grid(rows, cols, point, u_scale=1.0):
    """A (rows+1) x (cols+1) vertex grid over (i/rows, j/cols), closed by duplicated seams;
    normals are the area-weighted face normals at each vertex, welded across the seams."""
    p = [point(i / rows, j / cols) for i in range(rows + 1) for j in range(cols + 1)]
    uv = [(u_scale * j / cols, i / rows) for i in range(rows + 1) for j in range(cols + 1)]
    t = []
    for i in range(rows):
        for j in range(cols):
            a, b = i * (cols + 1) + j, (i + 1) * (cols + 1) + j
            t += [(a, b, a + 1), (a + 1, b, b + 1)]
    acc = {}
    key = lambda v: tuple(round(c, 6) for c in v)
    for tri in t:
        a, b, c = (p[k] for k in tri)
        e1, e2 = [y - x for x, y in zip(a, b)], [y - x for x, y in zip(a, c)]
        fn = (e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0])
        for k in tri:
            s = acc.setdefault(key(p[k]), [0.0, 0.0, 0.0])
            for d in range(3):
                s[d] += fn[d]
    n = []
    for v in p:
        s = acc[key(v)]
        ln = math.sqrt(sum(c * c for c in s)) or 1.0
        n.append(tuple(c / ln for c in s))
    t = [tri for tri in t if len({key(p[k]) for k in tri}) == 3]  # the poles' degenerate triangles
    return Mesh(p, n, uv, t)


def sphere(rows=24, cols=48, u_scale=1.0, phase=0.0):
    """The unit sphere; u runs 0..u_scale around it (beyond 1 the sampler's wrap shows) from the
    longitude `phase` (radians; 0 is +x, -pi/2 faces +z)."""
    def point(a, b):
        th, ph = math.pi * a, 2 * math.pi * b + phase
        return (math.sin(th) * math.cos(ph), math.cos(th), -math.sin(th) * math.sin(ph))
    return _grid(rows, cols, point, u_scale)


def blob(rows=32, cols=64):
    """A bumpy closed surface with the irregular relief of a scanned object (there is no scan in
    the repository): the unit sphere with a few fixed low-frequency bumps."""
    def point(a, b):
        th, ph = math.pi * a, 2 * math.pi * b
        d = (math.sin(th) * math.cos(ph), math.cos(th), -math.sin(th) * math.sin(ph))
        r = (1 + 0.18 * math.sin(3 * d[0] + 1) * math.sin(2 * d[1] + 0.5) + 0.12 * math.cos(4 * d[2] - d[0])
             + 0.06 * math.sin(5 * d[1] + 3 * d[0]))
        return (0.7 * r * d[0], 0.85 * r * d[1], 0.6 * r * d[2])
    return _grid(rows, cols, point)


def torus_knot(rows=128, cols=12, p=2, q=3, radius=0.55, tube=0.17):
    """three.js's TorusKnotGeometry curve (p, q) with a round tube, rows along the curve."""
    def curve(u):
        a = u * p * 2 * math.pi
        qu = q / p * a
        r = radius * (2 + math.cos(qu)) * 0.5
        return (r * math.cos(a), r * math.sin(a), radius * math.sin(qu) * 0.5)

    def point(a, b):
        c0, c1 = curve(a), curve(a + 0.001)
        tg = [y - x for x, y in zip(c0, c1)]
        bn = [x + y for x, y in zip(c0, c1)]
        bn = (tg[1] * bn[2] - tg[2] * bn[1], tg[2] * bn[0] - tg[0] * bn[2], tg[0] * bn[1] - tg[1] * bn[0])
        nm = (bn[1] * tg[2] - bn[2] * tg[1], bn[2] * tg[0] - bn[0] * tg[2], bn[0] * tg[1] - bn[1] * tg[0])
        bl, nl = math.sqrt(sum(c * c for c in bn)), math.sqrt(sum(c * c for c in nm))
        v = 2 * math.pi * b
        cx, cy = -tube * math.cos(v), tube * math.sin(v)
        return tuple(c + cx * m / nl + cy * w / bl for c, m, w in zip(c0, nm, bn))
    return _grid(rows, cols, point)


def look_at(eye, target, up=(0.0, 1.0, 0.0)):
    """The rotation quaternion (x, y, z, w) of a glTF node at `eye` whose -z looks at `target`
    (glTF cameras and lights look down their node's -z)."""
    f = [t - e for e, t in zip(eye, target)]
    fl = math.sqrt(sum(c * c for c in f))
    z = [-c / fl for c in f]
    x = [up[1] * z[2] - up[2] * z[1], up[2] * z[0] - up[0] * z[2], up[0] * z[1] - up[1] * z[0]]
    xl = math.sqrt(sum(c * c for c in x))
    x = [c / xl for c in x]
    y = [z[1] * x[2] - z[2] * x[1], z[2] * x[0] - z[0] * x[2], z[0] * x[1] - z[1] * x[0]]
    m00, m11, m22 = x[0], y[1], z[2]  # columns x, y, z of the rotation matrix
    tr = m00 + m11 + m22
    if tr > 0:
        s = 2 * math.sqrt(tr + 1)
        return [(y[2] - z[1]) / s, (z[0] - x[2]) / s, (x[1] - y[0]) / s, s / 4]
    if m00 > m11 and m00 > m22:
        s = 2 * math.sqrt(1 + m00 - m11 - m22)
        return [s / 4, (y[0] + x[1]) / s, (z[0] + x[2]) / s, (y[2] - z[1]) / s]
    if m11 > m22:
        s = 2 * math.sqrt(1 + m11 - m00 - m22)
        return [(y[0] + x[1]) / s, s / 4, (z[1] + y[2]) / s, (z[0] - x[2]) / s]
    s = 2 * math.sqrt(1 + m22 - m00 - m11)
    return [(z[0] + x[2]) / s, (z[1] + y[2]) / s, s / 4, (x[1] - y[0]) / s]


class _Glb:
    """Buffer views and accessors of one GLB binary chunk."""

    def __init__(self):
        self.blob, self.views, self.accessors = bytearray(), [], []

    def view(self, data):
        self.blob.extend(b"\0" * (-len(self.blob) % 4))
        self.views.append({"buffer": 0, "byteOffset": len(self.blob), "byteLength": len(data)})
        self.blob.extend(data)
        return len(self.views) - 1

    def floats(self, rows, kind, bounds=False):
        flat = [c for v in rows for c in v]
        a = {"bufferView": self.view(struct.pack("<%df" % len(flat), *flat)), "componentType": 5126,
             "count": len(rows), "type": kind}
        if bounds:
            a["min"] = [min(v[k] for v in rows) for k in range(3)]
            a["max"] = [max(v[k] for v in rows) for k in range(3)]
        self.accessors.append(a)
        return len(self.accessors) - 1

    def indices(self, tris):
        flat = [i for t in tris for i in t]
        self.accessors.append({"bufferView": self.view(struct.pack("<%dI" % len(flat), *flat)),
                               "componentType": 5125, "count": len(flat), "type": "SCALAR"})
        return len(self.accessors) - 1

    def write(self, path, doc):
        self.blob.extend(b"\0" * (-len(self.blob) % 4))
        doc["buffers"] = [{"byteLength": len(self.blob)}]
        doc["bufferViews"], doc["accessors"] = self.views, self.accessors
        text = json.dumps(doc).encode()
        text += b" " * (-len(text) % 4)
        head = struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(text) + 8 + len(self.blob))
        with open(path, "wb") as f:
            f.write(head + struct.pack("<I4s", len(text), b"JSON") + text +
                    struct.pack("<I4s", len(self.blob), b"BIN\0") + bytes(self.blob))


def _camera(camera, aspect):
    """A glTF camera object from {"type": "perspective", "yfov": RAD, ...} or
    {"type": "orthographic", "ymag": H, ...}; xmag = ymag · aspect."""
    if camera["type"] == "perspective":
        return {"type": "perspective", "perspective": {"yfov": camera["yfov"], "aspectRatio": aspect,
                                                       "znear": camera.get("znear", 0.1), "zfar": camera.get("zfar", 100)}}
    return {"type": "orthographic", "orthographic": {"xmag": camera["ymag"] * aspect, "ymag": camera["ymag"],
                                                     "znear": camera.get("znear", 0.1), "zfar": camera.get("zfar", 100)}}


def _light(light):
    """A KHR_lights_punctual light from {"type", "color", "intensity", "range", "inner", "outer"}."""
    out = {"type": light["type"], "color": light.get("color", [1, 1, 1]), "intensity": light["intensity"]}
    if "range" in light:
        out["range"] = light["range"]
    if light["type"] == "spot":
        out["spot"] = {"innerConeAngle": light["inner"], "outerConeAngle": light["outer"]}
    return out


_META1 = {"name": "Inkshade reference case", "version": "1", "authors": ["Inkshade"],
          "licenseUrl": "https://vrm.dev/licenses/1.0/", "avatarPermission": "everyone",
          "commercialUsage": "corporation", "allowRedistribution": True, "modification": "allowModification"}


# Where a texture slot goes: the glTF material's own textures, or VRMC_materials_mtoon's.
_GLTF_SLOTS = {"normal": "normalTexture", "emissive": "emissiveTexture"}
_MTOON_SLOTS = {"matcap": "matcapTexture", "shadeMultiply": "shadeMultiplyTexture",
                "rimMultiply": "rimMultiplyTexture", "shadingShift": "shadingShiftTexture"}


def _add_textures(g, doc, textures):
    """Images, samplers and textures for {slot: {"png": bytes, "sampler": dict or None,
    "transform": KHR_texture_transform or None}}; returns {slot: glTF textureInfo}."""
    index = {}
    for slot, tex in textures.items():
        doc.setdefault("images", []).append({"bufferView": g.view(tex["png"]), "mimeType": "image/png"})
        entry = {"source": len(doc["images"]) - 1}
        if tex.get("sampler") is not None:
            doc.setdefault("samplers", []).append(tex["sampler"])
            entry["sampler"] = len(doc["samplers"]) - 1
        doc.setdefault("textures", []).append(entry)
        index[slot] = {"index": len(doc["textures"]) - 1}
        if tex.get("transform") is not None:
            index[slot]["extensions"] = {"KHR_texture_transform": tex["transform"]}
            doc["extensionsUsed"].append("KHR_texture_transform")
    return index


def write_vrm(path, mesh, mtoon, camera, light, size, textures=None, vrm0=None, mesh_node=None, gltf_material=None):
    """Writes a GLB: `mesh` with one material, the camera node and the light node.

    mtoon: VRMC_materials_mtoon fields plus the glTF material's "baseColorFactor" and optional
    "emissiveFactor" (VRM 1.0), or None with `vrm0` the materialProperties entry (VRM 0.x:
    floatProperties, vectorProperties; a "base" texture becomes _MainTex). camera/light: dicts for
    _camera/_light plus "eye", "target". textures: {slot: {"png": bytes, "sampler": glTF sampler
    or None, "transform": KHR_texture_transform or None}}, slots "base", "normal", "emissive", "matcap", "shadeMultiply", "rimMultiply",
    "shadingShift". mesh_node: extra glTF node fields (rotation, scale); gltf_material: extra glTF
    material fields (alphaMode, alphaCutoff, doubleSided). size: (width, height)."""
    g = _Glb()
    prim = {"attributes": {"POSITION": g.floats(mesh.p, "VEC3", True), "NORMAL": g.floats(mesh.n, "VEC3"),
                           "TEXCOORD_0": g.floats(mesh.uv, "VEC2")}, "indices": g.indices(mesh.t), "material": 0}
    if getattr(mesh, "colors", None):
        prim["attributes"]["COLOR_0"] = g.floats(mesh.colors, "VEC3")
    doc = {"asset": {"version": "2.0", "generator": "Inkshade tests/reference/vrm_writer.py"},
           "extensionsUsed": ["KHR_lights_punctual"],
           "extensions": {"KHR_lights_punctual": {"lights": [_light(light)]}},
           "meshes": [{"primitives": [prim]}],
           "cameras": [_camera(camera, size[0] / size[1])],
           "nodes": [dict({"mesh": 0}, **(mesh_node or {})),
                     {"camera": 0, "translation": camera["eye"], "rotation": look_at(camera["eye"], camera["target"])},
                     {"translation": light["eye"], "rotation": look_at(light["eye"], light["target"]),
                      "extensions": {"KHR_lights_punctual": {"light": 0}}}],
           "scenes": [{"nodes": [0, 1, 2]}], "scene": 0}
    material = dict({"name": "surface", "pbrMetallicRoughness": {"metallicFactor": 0}}, **(gltf_material or {}))
    index = _add_textures(g, doc, textures or {})
    if vrm0 is None:
        ext = dict(mtoon)
        material["pbrMetallicRoughness"]["baseColorFactor"] = ext.pop("baseColorFactor") + [1]
        if "emissiveFactor" in ext:
            material["emissiveFactor"] = ext.pop("emissiveFactor")
        if "base" in index:
            material["pbrMetallicRoughness"]["baseColorTexture"] = index["base"]
        for slot, key in _GLTF_SLOTS.items():
            if slot in index:
                material[key] = index[slot]
        for slot, key in _MTOON_SLOTS.items():
            if slot in index:
                ext[key] = index[slot]
        material["extensions"] = {"VRMC_materials_mtoon": dict({"specVersion": "1.0"}, **ext)}
        doc["extensionsUsed"] += ["VRMC_vrm", "VRMC_materials_mtoon"]
        doc["extensions"]["VRMC_vrm"] = {"specVersion": "1.0", "meta": _META1}
    else:
        props = {"name": "surface", "shader": "VRM/MToon", "renderQueue": 2000, "keywordMap": {},
                 "tagMap": {"RenderType": "Opaque"}, "textureProperties": {}}
        props.update(vrm0)
        if "base" in index:
            props["textureProperties"] = {"_MainTex": index["base"]["index"]}
        doc["extensionsUsed"] += ["VRM"]
        doc["extensions"]["VRM"] = {"exporterVersion": "Inkshade", "specVersion": "0.0",
                                    "meta": {"title": "Inkshade reference case", "version": "1"},
                                    "materialProperties": [props]}
    doc["materials"] = [material]
    g.write(path, doc)


def write_glb(path, mesh):
    """A plain glTF mesh without material, camera or light (the three.js scene JSON case)."""
    g = _Glb()
    prim = {"attributes": {"POSITION": g.floats(mesh.p, "VEC3", True), "NORMAL": g.floats(mesh.n, "VEC3")},
            "indices": g.indices(mesh.t)}
    g.write(path, {"asset": {"version": "2.0", "generator": "Inkshade tests/reference/vrm_writer.py"},
                   "meshes": [{"primitives": [prim]}], "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})
