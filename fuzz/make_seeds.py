#!/usr/bin/env python3
"""Writes the seed corpora fuzz/corpus/<target>/ (small valid files of every format, the same
shapes as the test files in tests/io/*.hpp). Run from anywhere: python3 fuzz/make_seeds.py.
The files are checked in; rerun only to change them."""
import base64
import json
import math
import os
import struct
import zlib

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus")
MARK = b"\n#%%\n"  # splits an input into the model and the files next to it (fuzz_common.hpp)

CUBE_V = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
CUBE_Q = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (2, 3, 7, 6), (0, 4, 7, 3), (1, 2, 6, 5)]
CUBE_T = [t for q in CUBE_Q for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))]


def write(target, name, data):
    d = os.path.join(ROOT, target)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, name), "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


def png(w, h, rgba):
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    raw = b"".join(b"\0" + bytes(rgba[4 * w * y:4 * w * (y + 1)]) for y in range(h))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 6, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


TEX = png(2, 2, [255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255])


def torus(n=16, m=8, R=1.0, r=0.4):
    """(vertices, triangles) of a torus: curved everywhere, so every line type finds something."""
    v = []
    for i in range(n):
        for j in range(m):
            a, b = 2 * math.pi * i / n, 2 * math.pi * j / m
            v.append(((R + r * math.cos(b)) * math.cos(a), r * math.sin(b), (R + r * math.cos(b)) * math.sin(a)))
    t = []
    for i in range(n):
        for j in range(m):
            a, b = i * m + j, ((i + 1) % n) * m + j
            c, d = ((i + 1) % n) * m + (j + 1) % m, i * m + (j + 1) % m
            t += [(a, d, c), (a, c, b)]
    return v, t


def fmt(x):
    return ("%.4f" % x).rstrip("0").rstrip(".") or "0"


# --- OBJ ------------------------------------------------------------------------------------
def obj(v, faces, extra=""):
    s = "# seed\no shape\n" + extra
    s += "".join("v %s %s %s\n" % tuple(map(fmt, p)) for p in v)
    s += "".join("f " + " ".join(str(i + 1) for i in f) + "\n" for f in faces)
    return s


def cube_obj():
    return obj(CUBE_V, CUBE_Q)


def write_obj():
    write("obj", "cube.obj", cube_obj())
    mtl = "newmtl red\nKd 1 0 0\nmap_Kd t.png\nnewmtl blue\nKd 0 0 1\n"
    faces = "".join("usemtl %s\nf %d/%d/1 %d/%d/1 %d/%d/1 %d/%d/1\n" % ((["red", "blue"][k % 2],) + sum(((i + 1, j + 1) for j, i in enumerate(q)), ()))
                    for k, q in enumerate(CUBE_Q))
    s = "mtllib m.mtl\n" + "".join("v %d %d %d\n" % p for p in CUBE_V) + "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\n" + faces
    write("obj", "cube_mtl_texture.obj", s.encode() + MARK + mtl.encode() + MARK + TEX)
    write("obj", "negative_indices.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nv 1 1 0\nf 2 4 3\nvn 0 0 1\nf 1//1 2//1 3//1\n")
    write("obj", "polygon_tags.obj", "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 1 1 0 0 0 1\nv 0 1 0 1 1 1\nv 0.5 1.5 0 1 1 0\n"
          "g group\ns 1\nf 1 2 3 5 4\nl 1 2\np 3\nt crease 2/1/0 1 2 1.5\n")
    write("obj", "soup.obj", obj([CUBE_V[i] for t in CUBE_T for i in t], [(3 * k, 3 * k + 1, 3 * k + 2) for k in range(len(CUBE_T))]))


# --- STL ------------------------------------------------------------------------------------
def ascii_stl(tris):
    s = "solid cube\n"
    for t in tris:
        s += "  facet normal 0 0 0\n    outer loop\n"
        s += "".join("      vertex %s %s %s\n" % tuple(map(fmt, p)) for p in t)
        s += "    endloop\n  endfacet\n"
    return s + "endsolid cube\n"


def binary_stl(tris, header=b"binary cube"):
    out = header.ljust(80, b" ") + struct.pack("<I", len(tris))
    for t in tris:
        out += struct.pack("<3f", 0, 0, 0) + b"".join(struct.pack("<3f", *p) for p in t) + b"\0\0"
    return out


def write_stl():
    tris = [[CUBE_V[i] for i in t] for t in CUBE_T]
    write("stl", "cube_ascii.stl", ascii_stl(tris))
    write("stl", "cube_binary.stl", binary_stl(tris))
    write("stl", "solid_header_binary.stl", binary_stl(tris[:4], b"solid but binary"))
    write("stl", "two_solids.stl", ascii_stl(tris[:2]) + ascii_stl(tris[2:4]).replace("cube", "b"))


# --- PLY ------------------------------------------------------------------------------------
def ply_header(fmt_name, vprops, nv, nf, extra="", face="property list uchar int vertex_indices\n"):
    return ("ply\nformat %s 1.0\n%selement vertex %d\n" % (fmt_name, extra, nv) +
            "".join("property %s %s\n" % p for p in vprops) + "element face %d\n%send_header\n" % (nf, face))


def write_ply():
    xyz = [("float", "x"), ("float", "y"), ("float", "z")]
    s = ply_header("ascii", xyz, 8, 6, "comment unit cube\n")
    s += "".join("%d %d %d\n" % p for p in CUBE_V) + "".join("4 %d %d %d %d\n" % q for q in CUBE_Q)
    write("ply", "cube_ascii.ply", s)
    for name, fmt_name, e in (("cube_le.ply", "binary_little_endian", "<"), ("cube_be.ply", "binary_big_endian", ">")):
        b = ply_header(fmt_name, xyz, 8, 6).encode()
        b += b"".join(struct.pack(e + "3f", *p) for p in CUBE_V)
        b += b"".join(struct.pack(e + "B4i", 4, *q) for q in CUBE_Q)
        write("ply", name, b)
    props = xyz + [("float", "nx"), ("float", "ny"), ("float", "nz"), ("uchar", "red"), ("uchar", "green"), ("uchar", "blue"),
                   ("float", "u"), ("float", "v"), ("double", "quality")]
    s = ply_header("ascii", props, 4, 2, "comment TextureFile t.png\nobj_info seed\n",
                   "property list uchar uint vertex_indices\nproperty uchar flags\n")
    s += "0 0 0 0 0 1 255 0 0 0 0 1\n1 0 0 0 0 1 0 255 0 1 0 1\n1 1 0 0 0 1 0 0 255 1 1 1\n0 1 0 0 0 1 9 9 9 0 1 1\n"
    s += "3 0 1 2 0\n3 0 2 3 0\n"
    write("ply", "quad_attributes_texture.ply", s.encode() + MARK + TEX)
    b = ply_header("binary_little_endian", [("double", "x"), ("double", "y"), ("double", "z"), ("ushort", "red"),
                                            ("ushort", "green"), ("ushort", "blue")], 3, 1, "",
                   "property list ushort short vertex_index\nelement edge 1\nproperty int a\nproperty int b\n")
    data = b.encode() + b"".join(struct.pack("<3d3H", x, y, 0, 65535, 0, 0) for x, y in ((0, 0), (1, 0), (0, 1)))
    data += struct.pack("<H3h", 3, 0, 1, 2) + struct.pack("<2i", 0, 1)
    write("ply", "triangle_double_ushort.ply", data)


# --- OFF ------------------------------------------------------------------------------------
def write_off():
    s = "OFF\n# unit cube\n8 6 12\n" + "".join("%d %d %d\n" % p for p in CUBE_V) + "".join("4 %d %d %d %d\n" % q for q in CUBE_Q)
    write("off", "cube.off", s)
    write("off", "coff.off", "COFF 3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n3 0 1 2 255 255 255\n")
    write("off", "noff.off", "NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n")
    write("off", "stcoff.off", "STCOFF\n3 1\n0 0 0 1 0 0 0 0\n1 0 0 0 1 0 1 0\n0 1 0 0 0 1 0.5 1\n3 0 1 2\n")


# --- glTF / GLB -----------------------------------------------------------------------------
class Gltf:
    def __init__(self):
        self.doc = {"asset": {"version": "2.0"}}
        self.bin = b""

    def view(self, data, stride=0):
        self.bin += b"\0" * (-len(self.bin) % 4)
        v = {"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data)}
        if stride:
            v["byteStride"] = stride
        self.bin += data
        self.doc.setdefault("bufferViews", []).append(v)
        return len(self.doc["bufferViews"]) - 1

    def accessor(self, view, ctype, count, typ, **extra):
        a = {"componentType": ctype, "count": count, "type": typ}
        if view is not None:
            a["bufferView"] = view
        a.update(extra)
        self.doc.setdefault("accessors", []).append(a)
        return len(self.doc["accessors"]) - 1

    def floats(self, values, typ, comps):
        return self.accessor(self.view(struct.pack("<%df" % len(values), *values)), 5126, len(values) // comps, typ)

    def u16(self, values):
        return self.accessor(self.view(struct.pack("<%dH" % len(values), *values)), 5123, len(values), "SCALAR")

    def mesh(self, attributes, indices=None, material=None, mode=None):
        p = {"attributes": attributes}
        if indices is not None:
            p["indices"] = indices
        if material is not None:
            p["material"] = material
        if mode is not None:
            p["mode"] = mode
        self.doc.setdefault("meshes", []).append({"primitives": [p]})
        return len(self.doc["meshes"]) - 1

    def node(self, n):
        self.doc.setdefault("nodes", []).append(n)
        return len(self.doc["nodes"]) - 1

    def padded(self):
        return self.bin + b"\0" * (-len(self.bin) % 4)

    def gltf(self, uri=None):
        d = dict(self.doc)
        b = self.padded()
        d["buffers"] = [{"byteLength": len(b), "uri": uri or "data:application/octet-stream;base64," + base64.b64encode(b).decode()}]
        return json.dumps(d, separators=(",", ":")).encode()

    def glb(self):
        d = dict(self.doc)
        b = self.padded()
        if b:
            d["buffers"] = [{"byteLength": len(b)}]
        j = json.dumps(d, separators=(",", ":")).encode()
        j += b" " * (-len(j) % 4)
        out = struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(j) + (8 + len(b) if b else 0)) + struct.pack("<II", len(j), 0x4E4F534A) + j
        if b:
            out += struct.pack("<II", len(b), 0x004E4942) + b
        return out


def textured_quad(image_in_buffer=True):
    g = Gltf()
    pos = g.floats([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0], "VEC3", 3)
    uv = g.floats([0, 1, 1, 1, 1, 0, 0, 0], "VEC2", 2)
    idx = g.u16([0, 1, 2, 0, 2, 3])
    if image_in_buffer:
        g.doc["images"] = [{"bufferView": g.view(TEX), "mimeType": "image/png"}]
    else:
        g.doc["images"] = [{"uri": "data:image/png;base64," + base64.b64encode(TEX).decode()}]
    g.doc["textures"] = [{"source": 0}]
    g.doc["materials"] = [{"pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.25, 1, 1], "baseColorTexture": {"index": 0}}}]
    m = g.mesh({"POSITION": pos, "TEXCOORD_0": uv}, idx, 0)
    g.doc["scenes"] = [{"nodes": [g.node({"mesh": m})]}]
    g.doc["scene"] = 0
    return g


def hierarchy():
    """Strip + fan primitives, u8 indices, a sparse accessor, COLOR_0, normals and a node tree."""
    g = Gltf()
    pos = g.floats([0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0], "VEC3", 3)
    nrm = g.floats([0, 0, 1] * 4, "VEC3", 3)
    col = g.accessor(g.view(bytes([255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 9, 9, 9, 255])), 5121, 4, "VEC4", normalized=True)
    idx = g.accessor(g.view(bytes([0, 1, 2, 3])), 5121, 4, "SCALAR")
    sparse = g.accessor(None, 5126, 4, "VEC3", sparse={
        "count": 1, "indices": {"bufferView": g.view(bytes([3, 0, 0, 0])), "componentType": 5121},
        "values": {"bufferView": g.view(struct.pack("<3f", 1, 1, 0.5))}})
    strip = g.mesh({"POSITION": pos, "NORMAL": nrm, "COLOR_0": col}, idx, None, 5)
    fan = g.mesh({"POSITION": sparse}, None, None, 6)
    lines = g.mesh({"POSITION": pos}, None, None, 1)
    g.doc["materials"] = [{"extensions": {"VRMC_materials_mtoon": {"shadeColorFactor": [0.5, 0.5, 0.5]}}}]
    g.doc["meshes"][fan]["primitives"][0]["material"] = 0
    c2 = g.node({"mesh": lines, "matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1]})
    c1 = g.node({"mesh": fan, "translation": [2, 0, 0], "rotation": [0, 0.7071, 0, 0.7071], "scale": [1, 2, 1], "children": [c2]})
    root = g.node({"mesh": strip, "children": [c1]})
    g.doc["scenes"] = [{"nodes": [root]}]
    return g


def vrm0():
    g = textured_quad()
    g.doc["extensionsUsed"] = ["VRM"]
    g.doc["extensions"] = {"VRM": {"materialProperties": [{
        "shader": "VRM/MToon", "floatProperties": {"_ShadeShift": 0.1, "_ShadeToony": 0.8, "_OutlineWidthMode": 1, "_OutlineWidth": 0.5},
        "vectorProperties": {"_Color": [1, 1, 1, 1], "_ShadeColor": [0.5, 0.5, 0.5, 1]}, "textureProperties": {"_MainTex": 0}}]}}
    return g


def posed():
    """What the pose code reads: a strip skinned to two joints (JOINTS_0, WEIGHTS_0,
    inverseBindMatrices), a named morph target bound by a VRM 1.0 expression, an animation of
    rotation (LINEAR), translation (STEP) and weights (CUBICSPLINE), a camera, a spot and a point
    light, a sampler and a KHR_texture_transform."""
    g = textured_quad()
    pos = g.floats([0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 2, 0, 1, 2, 0], "VEC3", 3)
    joints = g.accessor(g.view(bytes([0, 1, 0, 0] * 2 + [0, 1, 0, 0] * 2 + [1, 0, 0, 0] * 2)), 5121, 6, "VEC4")
    weights = g.floats([1, 0, 0, 0] * 2 + [0.5, 0.5, 0, 0] * 2 + [1, 0, 0, 0] * 2, "VEC4", 4)
    morph = g.floats([0, 0, 0.5] * 6, "VEC3", 3)
    idx = g.u16([0, 1, 2, 1, 3, 2, 2, 3, 4, 3, 5, 4])
    strip = g.mesh({"POSITION": pos, "JOINTS_0": joints, "WEIGHTS_0": weights}, idx, 0)
    g.doc["meshes"][strip]["primitives"][0]["targets"] = [{"POSITION": morph}]
    g.doc["meshes"][strip]["extras"] = {"targetNames": ["smile"]}
    ibm = g.floats([1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1], "MAT4", 16)
    upper = g.node({"name": "upper", "translation": [0, 1, 0]})
    lower = g.node({"name": "lower", "children": [upper]})
    body = g.node({"name": "body", "mesh": strip, "skin": 0})
    g.doc["skins"] = [{"joints": [lower, upper], "inverseBindMatrices": ibm, "skeleton": lower}]
    times = g.floats([0, 1, 2], "SCALAR", 1)
    turns = g.floats([0, 0, 0, 1, 0, 0, 0.3827, 0.9239, 0, 0, 0.7071, 0.7071], "VEC4", 4)
    hops = g.floats([0, 0, 0, 0, 0.5, 0, 0, 0, 0], "VEC3", 3)
    cubic = g.floats([0, 0, 0, 0, 1, 0, 0, 0, 0], "SCALAR", 1)
    g.doc["animations"] = [{"name": "wave", "samplers": [
        {"input": times, "output": turns},
        {"input": times, "output": hops, "interpolation": "STEP"},
        {"input": times, "output": cubic, "interpolation": "CUBICSPLINE"}], "channels": [
        {"sampler": 0, "target": {"node": upper, "path": "rotation"}},
        {"sampler": 1, "target": {"node": lower, "path": "translation"}},
        {"sampler": 2, "target": {"node": body, "path": "weights"}}]}]
    g.doc["samplers"] = [{"magFilter": 9728, "minFilter": 9986, "wrapS": 33071, "wrapT": 33648}]
    g.doc["textures"][0]["sampler"] = 0
    g.doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"] = {
        "KHR_texture_transform": {"offset": [0.5, 0], "rotation": 0.3, "scale": [2, 2], "texCoord": 0}}
    g.doc["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1, "zfar": 100}}]
    g.doc["extensions"] = {"KHR_lights_punctual": {"lights": [
        {"type": "spot", "name": "key", "intensity": 20, "range": 9, "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.6}},
        {"type": "point", "name": "fill", "color": [1, 0.5, 0.2]}]},
        "VRMC_vrm": {"specVersion": "1.0", "expressions": {"preset": {
            "happy": {"morphTargetBinds": [{"node": body, "index": 0, "weight": 1}], "overrideBlink": "block"}},
            "custom": {"smirk": {"morphTargetBinds": [{"node": body, "index": 0, "weight": 0.5}], "isBinary": True}}}}}
    g.doc["extensionsUsed"] = ["KHR_lights_punctual", "KHR_texture_transform", "VRMC_vrm"]
    cam = g.node({"camera": 0, "translation": [0, 1, 4]})
    lights = [g.node({"extensions": {"KHR_lights_punctual": {"light": i}}, "translation": [0, 3, 3]}) for i in (0, 1)]
    g.doc["scenes"][0]["nodes"] += [lower, body, cam] + lights
    return g


HUMAN_BONES = [  # three-vrm's required bones, parent first, with a place (metres, +y up)
    ("hips", None, [0, 1, 0]), ("spine", "hips", [0, 0.1, 0]), ("head", "spine", [0, 0.5, 0]),
    ("leftUpperLeg", "hips", [0.1, -0.05, 0]), ("leftLowerLeg", "leftUpperLeg", [0, -0.45, 0]),
    ("leftFoot", "leftLowerLeg", [0, -0.45, 0]), ("rightUpperLeg", "hips", [-0.1, -0.05, 0]),
    ("rightLowerLeg", "rightUpperLeg", [0, -0.45, 0]), ("rightFoot", "rightLowerLeg", [0, -0.45, 0]),
    ("leftUpperArm", "spine", [0.2, 0.35, 0]), ("leftLowerArm", "leftUpperArm", [0.25, 0, 0]),
    ("leftHand", "leftLowerArm", [0.25, 0, 0]), ("rightUpperArm", "spine", [-0.2, 0.35, 0]),
    ("rightLowerArm", "rightUpperArm", [-0.25, 0, 0]), ("rightHand", "rightLowerArm", [-0.25, 0, 0])]


def skeleton(g, extra=None):
    """The human bones as nodes (children set), returns {bone: node}."""
    nodes = {}
    for bone, parent, t in HUMAN_BONES:
        nodes[bone] = g.node(dict({"name": bone, "translation": t}, **(extra or {})))
        if parent:
            g.doc["nodes"][nodes[parent]].setdefault("children", []).append(nodes[bone])
    return nodes


def rigged_avatar():
    """A VRM 1.0 avatar for the pose code: the humanoid (every required bone), a morph target
    bound by the expression happy, an expression look-at, a roll constraint, and a two-joint
    spring with a sphere collider."""
    g = Gltf()
    bones = skeleton(g)
    pos = g.floats([0, 0, 0, 0.2, 0, 0, 0, 0.3, 0], "VEC3", 3)
    body = g.mesh({"POSITION": pos}, None)
    g.doc["meshes"][body]["primitives"][0]["targets"] = [{"POSITION": g.floats([0, 0, 0.1] * 3, "VEC3", 3)}]
    g.doc["meshes"][body]["extras"] = {"targetNames": ["smile"]}
    g.doc["nodes"][bones["head"]]["mesh"] = body
    hair = g.node({"name": "hair", "translation": [0, 0.1, -0.1]})
    tip = g.node({"name": "tip", "translation": [0, -0.15, 0]})
    g.doc["nodes"][hair]["children"] = [tip]
    g.doc["nodes"][bones["head"]].setdefault("children", []).append(hair)
    twist = g.node({"name": "twist", "translation": [0, 0.05, 0],
                    "extensions": {"VRMC_node_constraint": {"specVersion": "1.0", "constraint": {
                        "roll": {"source": bones["leftLowerArm"], "rollAxis": "X", "weight": 0.5}}}}})
    g.doc["nodes"][bones["leftUpperArm"]]["children"].append(twist)
    g.doc["extensions"] = {
        "VRMC_vrm": {"specVersion": "1.0", "meta": {"name": "seed"},
                     "humanoid": {"humanBones": {b: {"node": n} for b, n in bones.items()}},
                     "expressions": {"preset": {"happy": {"morphTargetBinds": [{"node": bones["head"], "index": 0, "weight": 1}]}}},
                     "lookAt": {"type": "expression", "offsetFromHeadBone": [0, 0.06, 0],
                                "rangeMapHorizontalOuter": {"inputMaxValue": 90, "outputScale": 1}}},
        "VRMC_springBone": {"specVersion": "1.0",
                            "colliders": [{"node": bones["head"], "shape": {"sphere": {"offset": [0, 0, 0], "radius": 0.1}}}],
                            "colliderGroups": [{"colliders": [0]}],
                            "springs": [{"joints": [{"node": hair, "hitRadius": 0.02, "stiffness": 1, "gravityPower": 1,
                                                     "gravityDir": [0, -1, 0], "dragForce": 0.4}, {"node": tip}],
                                         "colliderGroups": [0]}]}}
    g.doc["extensionsUsed"] = ["VRMC_vrm", "VRMC_springBone", "VRMC_node_constraint"]
    g.doc["scenes"] = [{"nodes": [bones["hips"]]}]
    return g


def clip():
    """A VRM animation: the spine turning, the hips rising, happy and the look-at target keyed."""
    g = Gltf()
    bones = skeleton(g)
    happy = g.node({"name": "happy"})
    look = g.node({"name": "lookAt", "translation": [0, 1.6, 1]})
    times = g.floats([0, 1, 2], "SCALAR", 1)
    turn = g.floats([0, 0, 0, 1, 0, 0.3827, 0, 0.9239, 0, 0, 0, 1], "VEC4", 4)
    rise = g.floats([0, 1, 0, 0, 1.1, 0, 0, 1, 0], "VEC3", 3)
    weight = g.floats([0, 0, 0, 1, 0, 0, 0, 0, 0], "VEC3", 3)
    aim = g.floats([0, 1.6, 1, 1, 1.6, 1, -1, 1.6, 1], "VEC3", 3)
    g.doc["animations"] = [{"samplers": [{"input": times, "output": o} for o in (turn, rise, weight, aim)], "channels": [
        {"sampler": 0, "target": {"node": bones["spine"], "path": "rotation"}},
        {"sampler": 1, "target": {"node": bones["hips"], "path": "translation"}},
        {"sampler": 2, "target": {"node": happy, "path": "translation"}},
        {"sampler": 3, "target": {"node": look, "path": "translation"}}]}]
    g.doc["extensions"] = {"VRMC_vrm_animation": {
        "specVersion": "1.0", "humanoid": {"humanBones": {b: {"node": n} for b, n in bones.items()}},
        "expressions": {"preset": {"happy": {"node": happy}}}, "lookAt": {"node": look}}}
    g.doc["extensionsUsed"] = ["VRMC_vrm_animation"]
    g.doc["scenes"] = [{"nodes": [bones["hips"], happy, look]}]
    return g


def write_vrma():
    # Byte 0: the time (bits 0-4, quarter seconds), spring bones off at bit 7; then the avatar,
    # "\n#%%\n", the clip.
    write("vrma", "rig_at_1.25s.bin", bytes([5]) + rigged_avatar().glb() + MARK + clip().glb())
    write("vrma", "rig_at_2.5s_no_springs.bin", bytes([138]) + rigged_avatar().glb() + MARK + clip().glb())


def write_gltf():
    # Byte 0 picks the extension in fuzz_gltf (even: .gltf, odd: .glb).
    write("gltf", "quad_embedded.gltf", b"\0" + textured_quad(False).gltf())
    write("gltf", "quad.glb", b"\1" + textured_quad().glb())
    g = textured_quad()
    write("gltf", "quad_external_bin.gltf", b"\0" + g.gltf("b.bin") + MARK + g.padded())
    write("gltf", "hierarchy.glb", b"\1" + hierarchy().glb())
    write("gltf", "hierarchy.gltf", b"\0" + hierarchy().gltf())
    write("gltf", "vrm0.glb", b"\1" + vrm0().glb())
    # Byte 0's other bits pose the file (fuzz_pose): 117 = glb, pose 58 (the animation at 3.75 s,
    # the morph at 1.5, the expression at 0.5); 82 = gltf, pose 41 (no animation, the morph at 1.25).
    write("gltf", "posed.glb", bytes([117]) + posed().glb())
    write("gltf", "posed.gltf", bytes([82]) + posed().gltf())
    # 43 = glb, pose 21: 2.25 s of spring bones, the expression at 0 (the rig has no animation).
    write("gltf", "rig_springs.glb", bytes([43]) + rigged_avatar().glb())


# --- styles ---------------------------------------------------------------------------------
def write_style():
    presets = os.path.join(os.path.dirname(ROOT), "..", "src", "styles", "presets")
    for name in sorted(os.listdir(presets)):
        if name.endswith(".toml"):
            with open(os.path.join(presets, name), "rb") as f:
                write("style", name, f.read())
    write("style", "overrides.toml", b'background = "#ffffff"\n[light]\ncolor = [1, 1, 1]\n[shading]\nmodel = "phong"\n'
          b'[[lines]]\ntype = "contour"\n' + MARK + b"shininess=64\ncontour.width=2\nphong.base-color=#ff8800\n")


# --- mesh pipeline --------------------------------------------------------------------------
def write_mesh_pipeline():
    # Byte 0: format (0 obj, 1 stl, 2 ply, 3 off, 4 gltf, 5 glb); byte 1: view and options.
    v, t = torus()
    off = "OFF\n%d %d 0\n" % (len(v), len(t)) + "".join("%s %s %s\n" % tuple(map(fmt, p)) for p in v)
    off += "".join("3 %d %d %d\n" % f for f in t)
    write("mesh_pipeline", "torus.off", b"\3\0" + off.encode())
    write("mesh_pipeline", "torus_hidden.off", b"\3\x65" + off.encode())
    write("mesh_pipeline", "cube.obj", b"\0\x21" + cube_obj().encode())
    write("mesh_pipeline", "cube.stl", b"\1\x0a" + binary_stl([[CUBE_V[i] for i in f] for f in CUBE_T]))
    with open(os.path.join(ROOT, "ply", "cube_le.ply"), "rb") as f:
        write("mesh_pipeline", "cube.ply", b"\2\x92" + f.read())
    write("mesh_pipeline", "quad.glb", b"\5\x13" + textured_quad().glb())
    write("mesh_pipeline", "hierarchy.gltf", b"\4\x44" + hierarchy().gltf())


# --- batch manifests ------------------------------------------------------------------------
def write_manifest():
    # Byte 0 picks the source name in fuzz_manifest (0 jobs.csv, 1 jobs.jsonl, 2 jobs.txt).
    write("manifest", "jobs.csv", b"\0" + b"# jobs\nmodel,name,views,styles,size,format,fov,ortho\n"
          b"builtin:teapot,pot,orbit4x2,\"lambert,cel\",256x256,png,35,false\n"
          b"models/chair.obj,,turntable:8:30,toon,640x480,\"png,svg\",30,true\n"
          b"\"a,b.stl\",quoted,\"10:20;eye=1,2,3 target=0,0,0 up=0,1,0 name=front\",gooch,64,svg,,\n")
    write("manifest", "output.csv", b"\0" + b"model,output,view,style\r\nbuiltin:sphere,out/one,45:10:3,phong\r\n")
    write("manifest", "jobs.jsonl", b"\1" + b'{"model": "builtin:torus", "views": "orbit8x3", "styles": "ink,anime", "size": "128x96"}\n'
          b'\n# comment\n{"model": "scan.ply", "name": "scan", "view": "0:0", "style": "technical", "format": "svg", "fov": 20, "ortho": true}\n'
          b'{"model": "m.glb", "output": "single/m", "views": "eye=0,0,5"}\n')
    write("manifest", "jobs_by_content.txt", b"\2" + b'{"model": "builtin:teapot"}\n')


# --- view scripts (inkshade view --script) ---------------------------------------------------
def write_view_script():
    write("view_script", "every_command.txt",
          "# every command once\ngui off\nframes 2\nkey F\nkey 3\nset levels=0.2,0.5,0.9\n"
          "set outline.color=#ff8800  # a colour is no comment\nstyle cel-002\nlight-pos 1,2.5,-3\n"
          "orbit 30 -15\nzoom 0.8\nopen builtin:torus\nscreenshot shot.png\nsave-frame frame.png\n"
          "save-style saved.toml\ngui on\nquit\n")
    write("view_script", "crlf_and_blanks.txt", "\tframes 1\r\n\r\n   # indented comment\r\nscreenshot a b.png\r\n")


if __name__ == "__main__":
    write_obj()
    write_stl()
    write_ply()
    write_off()
    write_gltf()
    write_vrma()
    write_style()
    write_mesh_pipeline()
    write_manifest()
    write_view_script()
