"""The cases the reference test renders in Inkshade and in three-vrm: each writes its input files
into a folder and says how each side renders them. A VRM case's textures are
{slot: (texel(x, y), glTF sampler or None[, KHR_texture_transform])}, 16x16 texels.

A case is a dict: name, size (w, h), kind "vrm" (a VRM file: camera 0, the file's light) or
"scene" (a three.js scene JSON with an MToonMaterial), and file (the name in the folder)."""
import json
import math
import os

import vrm_writer as vw

SIZE = (256, 256)

# A perspective and an orthographic camera looking at the origin, and the three glTF lights.
PERSPECTIVE = {"type": "perspective", "yfov": 0.62, "eye": [0.9, 1.0, 3.4], "target": [0, 0, 0]}
ORTHOGRAPHIC = {"type": "orthographic", "ymag": 1.0, "eye": [2.4, 1.6, 2.6], "target": [0, 0, 0]}
DIRECTIONAL = {"type": "directional", "intensity": 3.0, "color": [1.0, 0.95, 0.9],
               "eye": [2.6, 1.8, 0.2], "target": [0, 0, 0]}
POINT = {"type": "point", "intensity": 15.0, "range": 6.0, "color": [0.95, 1.0, 0.9],
         "eye": [1.4, 1.6, 1.9], "target": [0, 0, 0]}
SPOT = {"type": "spot", "intensity": 40.0, "inner": 0.08, "outer": 0.2, "color": [1.0, 1.0, 1.0],
        "eye": [0.6, 2.6, 2.4], "target": [0.1, 0.0, 0.0]}

# VRMC_materials_mtoon values: a lit and a shade colour, a narrow toon band, a rim half lit.
MTOON = {"baseColorFactor": [0.9, 0.45, 0.25], "shadeColorFactor": [0.25, 0.15, 0.45],
         "shadingToonyFactor": 0.85, "shadingShiftFactor": -0.1, "giEqualizationFactor": 0.9,
         "parametricRimColorFactor": [0.3, 0.4, 0.6], "parametricRimFresnelPowerFactor": 3.0,
         "parametricRimLiftFactor": 0.05, "rimLightingMixFactor": 0.5,
         "outlineWidthMode": "none", "outlineWidthFactor": 0.0, "outlineColorFactor": [0.1, 0.05, 0.2],
         "outlineLightingMixFactor": 1.0}

# glTF sampler enums (glTF 2.0 section 5.26).
NEAREST, LINEAR, REPEAT, CLAMP = 9728, 9729, 10497, 33071


def checker(x, y):
    """16x16 texels: 2-texel checks of cream and teal, a red texel column at the right edge so
    the wrap mode shows where u passes 1."""
    if x == 15:
        return (200, 30, 30)
    return (240, 230, 200) if (x // 2 + y // 2) % 2 == 0 else (40, 120, 130)


def textured_sphere():
    """u runs 0..3 around the sphere, passing 1 (where the red column is) at the front right."""
    return vw.sphere(u_scale=3.0, phase=-math.pi)


def coloured_sphere():
    """The sphere with linear vertex colours (COLOR_0) that vary over it."""
    mesh = vw.sphere()
    mesh.colors = [(0.5 + 0.5 * p[0], 0.6, 0.5 + 0.5 * p[1]) for p in mesh.p]
    return mesh


def _vrm_case(name, mesh, camera, light, mtoon=None, textures=None, vrm0=None, size=SIZE, node=None, material=None):
    def write(folder):
        made = {slot: {"png": vw.png(16, 16, spec[0]), "sampler": spec[1], "transform": spec[2] if len(spec) > 2 else None}
                for slot, spec in (textures or {}).items()}
        vw.write_vrm(os.path.join(folder, name + ".vrm"), mesh(), mtoon, camera, light, size, made, vrm0, node, material)
    return {"name": name, "kind": "vrm", "file": name + ".vrm", "size": size, "write": write}


def _smooth(f):
    """A 16x16 texel(x, y) from f(u, v) -> (r, g, b) in 0..1 at the texel centres."""
    return lambda x, y: tuple(int(round(255 * min(1.0, max(0.0, c)))) for c in f((x + 0.5) / 16, (y + 0.5) / 16))


def _bumps(u, v):
    """A tangent-space normal map of soft bumps (glTF: +y up the image, encoded 0.5 + 0.5 n)."""
    du, dv = 0.9 * math.sin(8 * math.pi * u), -0.9 * math.sin(4 * math.pi * v)
    ln = math.sqrt(1 + du * du + dv * dv)
    return (0.5 - 0.5 * du / ln, 0.5 - 0.5 * dv / ln, 0.5 + 0.5 / ln)


SMOOTH = {"magFilter": LINEAR, "minFilter": LINEAR, "wrapS": REPEAT, "wrapT": REPEAT}
MAPS = {"normal": (_smooth(_bumps), SMOOTH),
        "matcap": (_smooth(lambda u, v: (0.6 * math.exp(-((u - 0.35) ** 2 + (v - 0.3) ** 2) / 0.02),) * 3), SMOOTH),
        "emissive": (_smooth(lambda u, v: (0.0, 0.5 * max(0.0, math.sin(2 * math.pi * v)) ** 8, 0.2 * u)), SMOOTH),
        "shadeMultiply": (_smooth(lambda u, v: (1.0, 0.5 + 0.5 * v, 1.0 - 0.5 * u)), SMOOTH)}


def _outline(mode, width):
    return dict(MTOON, outlineWidthMode=mode, outlineWidthFactor=width, outlineLightingMixFactor=0.5)


# VRM 0.x MToon properties (three-vrm's VRMMaterialsV0CompatPlugin ports them to MToon 1.0).
VRM0 = {"floatProperties": {"_ShadeToony": 0.9, "_ShadeShift": 0.0, "_RimFresnelPower": 2.0, "_RimLift": 0.1,
                            "_RimLightingMix": 0.5, "_OutlineWidthMode": 1, "_OutlineWidth": 1.5,
                            "_OutlineColorMode": 1, "_OutlineLightingMix": 0.5, "_IndirectLightIntensity": 0.1},
        "vectorProperties": {"_Color": [0.85, 0.8, 0.95, 1.0], "_ShadeColor": [0.45, 0.3, 0.6, 1.0],
                             "_RimColor": [0.2, 0.25, 0.3, 1.0], "_OutlineColor": [0.15, 0.1, 0.2, 1.0],
                             "_EmissionColor": [0, 0, 0, 1]}}


def _scene_case(name):
    """A three.js scene JSON: MToonMaterial with only `color`, a directional and an ambient light."""
    scene = {"mesh": name + ".glb",
             "material": {"type": "MToonMaterial", "color": [0.8, 0.55, 0.35]},
             "lights": [{"type": "AmbientLight", "color": [0.4, 0.45, 0.5], "intensity": 1.0},
                        {"type": "DirectionalLight", "color": [1, 1, 1], "intensity": 2.5,
                         "position": [2.6, 1.8, 0.2], "target": [0, 0, 0]}],
             "camera": {"type": "PerspectiveCamera", "fov": 36, "near": 0.1, "far": 100,
                        "position": [0.9, 1.0, 3.4], "target": [0, 0, 0]},
             "background": "transparent", "size": list(SIZE)}

    def write(folder):
        vw.write_glb(os.path.join(folder, name + ".glb"), vw.blob())
        with open(os.path.join(folder, name + ".json"), "w") as f:
            json.dump(scene, f, indent=1)
    return {"name": name, "kind": "scene", "file": name + ".json", "size": SIZE, "write": write}


CASES = [
    _vrm_case("directional_perspective", vw.sphere, PERSPECTIVE, DIRECTIONAL, MTOON),
    _vrm_case("point_perspective", vw.torus_knot, PERSPECTIVE, POINT, MTOON),
    _vrm_case("spot_orthographic", vw.blob, ORTHOGRAPHIC, SPOT, MTOON),
    # A wide image (the camera's aspectRatio is the image's) and a turned, unevenly scaled mesh
    # node (normals through the inverse transpose).
    _vrm_case("directional_wide_scaled_node", vw.blob, PERSPECTIVE, DIRECTIONAL, MTOON, size=(320, 200),
              node={"rotation": [0.0, 0.3826834, 0.0, 0.9238795], "scale": [1.3, 0.8, 1.0]}),
    _vrm_case("directional_orthographic", vw.torus_knot, ORTHOGRAPHIC, DIRECTIONAL, MTOON),
    _vrm_case("texture_nearest_repeat", textured_sphere, PERSPECTIVE, DIRECTIONAL,
              dict(MTOON, baseColorFactor=[1, 1, 1]),
              {"base": (checker, {"magFilter": NEAREST, "minFilter": NEAREST, "wrapS": REPEAT, "wrapT": REPEAT})}),
    _vrm_case("texture_linear_clamp", textured_sphere, PERSPECTIVE, DIRECTIONAL,
              dict(MTOON, baseColorFactor=[1, 1, 1]),
              {"base": (checker, {"magFilter": LINEAR, "minFilter": LINEAR, "wrapS": CLAMP, "wrapT": CLAMP})}),
    # KHR_texture_transform with a rotation and an uneven scale, where the extension's order
    # (scale first) and three.js's setUvTransform (rotation first) differ.
    _vrm_case("texture_transform_rotated", textured_sphere, PERSPECTIVE, DIRECTIONAL, dict(MTOON, baseColorFactor=[1, 1, 1]),
              {"base": (checker, {"magFilter": LINEAR, "minFilter": LINEAR, "wrapS": REPEAT, "wrapT": REPEAT},
                        {"offset": [0.2, 0.3], "rotation": 0.4, "scale": [1.5, 2.0]})}),
    # alphaMode MASK on a double-sided material: holes cut by the texture's alpha show the inside,
    # lit with the normal turned (three.js's DoubleSide).
    _vrm_case("alpha_mask_double_sided", vw.sphere, PERSPECTIVE, DIRECTIONAL, MTOON,
              {"base": (lambda x, y: (255, 255, 255, 255 if (x // 4 + y // 4) % 2 else 0), SMOOTH)},
              material={"alphaMode": "MASK", "alphaCutoff": 0.5, "doubleSided": True}),
    # COLOR_0 on an MToon mesh: three-vrm's MToonMaterial ignores it (ignoreVertexColor true).
    _vrm_case("vertex_colors", coloured_sphere, PERSPECTIVE, DIRECTIONAL, MTOON),
    # MToon's maps: a normal map, a matcap, an emissive and a shade multiply texture (LINEAR, no mipmaps).
    _vrm_case("maps_normal_matcap_emissive", vw.sphere, PERSPECTIVE, DIRECTIONAL,
              dict(MTOON, emissiveFactor=[1, 1, 1], matcapFactor=[1, 1, 1]), MAPS),
    _vrm_case("outline_world", vw.torus_knot, PERSPECTIVE, DIRECTIONAL, _outline("worldCoordinates", 0.02)),
    _vrm_case("outline_screen", vw.torus_knot, PERSPECTIVE, DIRECTIONAL, _outline("screenCoordinates", 0.01)),
    _vrm_case("vrm0_outline_world", vw.blob, PERSPECTIVE, DIRECTIONAL, vrm0=VRM0),
    # VRM 0.x _MainTex offset and scale ([offset s, offset t, scale s, scale t]), which three-vrm
    # ports to KHR_texture_transform with t turned over.
    _vrm_case("vrm0_texture_offset_scale", textured_sphere, PERSPECTIVE, DIRECTIONAL,
              vrm0=dict(VRM0, vectorProperties=dict(VRM0["vectorProperties"], _Color=[1, 1, 1, 1],
                                                     _MainTex=[0.25, 0.1, 2.0, 1.5])),
              textures={"base": (checker, {"magFilter": LINEAR, "minFilter": LINEAR, "wrapS": REPEAT, "wrapT": REPEAT})}),
    _scene_case("scene_mtoon_color_only"),
]

# Cases that differ from three-vrm for a known reason being fixed, with the reason. The test
# passes while they fail and fails once one passes, so that it leaves this list.
PENDING = {
}
