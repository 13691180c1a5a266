// `inkshade render --scene FILE` (docs/threejs.md): the same scene through the JSON importer and
// through the equivalent command line gives byte-identical PNGs; options given on the command
// line override the scene's; bad scenes are one-line errors naming the file and field, exit 2.
#include <gtest/gtest.h>

#include "cli/run_cli.hpp"
#include "inkshade/image.hpp"

namespace inkshade::test {
namespace {

// A MeshPhongMaterial torus knot under a directional and an ambient light, perspective camera.
// Light colours are linear arrays (as three.js's Color.fromArray takes them), so the command
// line can give the same values; material colours are sRGB hex as three.js users type them.
const char* kPhongScene = R"({
  "mesh": "builtin:torus-knot",
  "material": {"type": "MeshPhongMaterial", "color": "#ff8800", "specular": "#444444", "shininess": 50,
               "emissive": "#100000"},
  "lights": [
    {"type": "AmbientLight", "color": [0.2, 0.2, 0.25], "intensity": 1.5},
    {"type": "DirectionalLight", "color": [1, 0.9, 0.8], "intensity": 3, "position": [3, 4, 5], "target": [0, 0.5, 0]}
  ],
  "camera": {"type": "PerspectiveCamera", "fov": 40, "near": 0.5, "far": 50, "position": [1, 2, 7], "target": [0, 0, 0]},
  "background": "#223344",
  "size": [160, 120],
  "antialias": true
})";

const char* kPhongFlags =
    "builtin:torus-knot --shading threejs-phong --set color=#ff8800 --set specular=#444444 --set shininess=50 "
    "--set emissive=#100000 --ambient 0.2,0.2,0.25 --set ambient-intensity=1.5 --light-type directional "
    "--light-color 1,0.9,0.8 --set light-intensity=3 --light-pos 3,4,5 --light-target 0,0.5,0 "
    "--fov 40 --near 0.5 --far 50 --eye 1,2,7 --target 0,0,0 --background '#223344' --size 160x120 --samples 4";

// A MeshToonMaterial with a gradient map and an OutlineEffect, a point light and an orthographic
// camera, without antialiasing (three.js's default).
const char* kToonScene = R"({
  "mesh": "builtin:teapot",
  "material": {"type": "MeshToonMaterial", "color": "#66aaff", "gradientMap": [0.25, 0.6, 1.0]},
  "lights": [
    {"type": "PointLight", "color": [1, 1, 1], "intensity": 60, "position": [2, 5, 4], "decay": 2},
    {"type": "AmbientLight", "intensity": 0.5}
  ],
  "camera": {"type": "OrthographicCamera", "left": -2.5, "right": 2.5, "top": 2, "bottom": -2, "near": 0.1,
             "far": 40, "position": [4, 4, 8], "target": [0, 1, 0]},
  "outline": {"thickness": 0.008, "color": [0.1, 0, 0.2], "alpha": 0.8},
  "background": "#ffffff",
  "size": [150, 120]
})";

// The toon style's outline cannot be given by flags alone: a style file carries the [[lines]].
const char* kToonStyle = R"(
[shading]
model = "threejs-toon"
color = "#66aaff"
use-gradient-map = true
gradient-map = [0.25, 0.6, 1.0]

[[lines]]
type = "threejs-outline"
thickness = 0.008
color = [0.1, 0, 0.2]
alpha = 0.8
)";

const char* kToonFlags =
    "builtin:teapot --light-type point --light-color 1,1,1 --set light-intensity=60 --set light-decay=2 "
    "--light-pos 2,5,4 --ambient 1,1,1 --set ambient-intensity=0.5 --ortho --ortho-height 4 --near 0.1 --far 40 "
    "--eye 4,4,8 --target 0,1,0 --background '#ffffff' --size 150x120 --samples 1";

TEST(ThreejsSceneCli, SceneAndEquivalentFlagsGiveByteIdenticalImages) {
    TempDir dir;
    const std::string scene = dir.write("phong.json", kPhongScene);
    auto a = run_cli("render --scene " + scene + " -o " + dir.file("scene.png"));
    ASSERT_EQ(a.status, 0) << a.err;
    auto b = run_cli(std::string("render ") + kPhongFlags + " -o " + dir.file("flags.png"));
    ASSERT_EQ(b.status, 0) << b.err;
    const std::string png = slurp(dir.file("scene.png"));
    EXPECT_EQ(png, slurp(dir.file("flags.png"))) << "scene and flags differ";
    // Not a trivial image: the right size, the background and the orange knot both present.
    const Image img = read_png(dir.file("scene.png"));
    EXPECT_EQ(img.width, 160);
    EXPECT_EQ(img.height, 120);
    EXPECT_EQ(int(img.pixel(0, 0)[0]), 0x22);
    int orange = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) orange += img.pixel(x, y)[0] > 150 && img.pixel(x, y)[2] < 60;
    EXPECT_GT(orange, 500);
}

TEST(ThreejsSceneCli, ToonOutlineSceneAndEquivalentStyleAndFlagsGiveByteIdenticalImages) {
    TempDir dir;
    const std::string scene = dir.write("toon.json", kToonScene), style = dir.write("toon.toml", kToonStyle);
    auto a = run_cli("render --scene " + scene + " -o " + dir.file("scene.png"));
    ASSERT_EQ(a.status, 0) << a.err;
    auto b = run_cli("render --style " + style + " " + kToonFlags + " -o " + dir.file("flags.png"));
    ASSERT_EQ(b.status, 0) << b.err;
    EXPECT_EQ(slurp(dir.file("scene.png")), slurp(dir.file("flags.png"))) << "scene and flags differ";
    // The outline is there: dark purple-ish pixels (sRGB of the linear outline colour over white).
    const Image img = read_png(dir.file("scene.png"));
    int outline = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            outline += img.pixel(x, y)[1] < 80 && img.pixel(x, y)[2] > img.pixel(x, y)[1];
    EXPECT_GT(outline, 50);
}

// three-vrm's MToonMaterial with a screen-coordinates outline under a point light with intensity,
// decay and distance and an orthographic camera: the scene and the flags it stands for (the mtoon model's threejs
// convention is its default; the scene turns shadows off as three.js does by default).
const char* kMtoonScene = R"({
  "mesh": "builtin:torus-knot",
  "material": {"type": "MToonMaterial", "color": [0.9, 0.6, 0.4], "shadeColorFactor": [0.3, 0.2, 0.45],
               "shadingShiftFactor": -0.1, "shadingToonyFactor": 0.7, "parametricRimColorFactor": [0.5, 0.4, 0.3],
               "parametricRimFresnelPowerFactor": 2, "parametricRimLiftFactor": 0.05, "rimLightingMixFactor": 0.5,
               "giEqualizationFactor": 0.9, "outlineWidthMode": "screenCoordinates", "outlineWidthFactor": 0.02,
               "outlineColorFactor": [0.1, 0.05, 0.2], "outlineLightingMixFactor": 0.5,
               "emissive": [0.05, 0.02, 0], "emissiveIntensity": 2, "shadingShiftTextureScale": 0.5,
               "normalScale": [2, -2], "uvAnimationScrollXSpeedFactor": 0.3, "uvAnimationScrollYSpeedFactor": -0.1,
               "uvAnimationRotationSpeedFactor": 0.2},
  "lights": [
    {"type": "PointLight", "color": [1, 0.9, 0.8], "intensity": 30, "position": [2, 3, 4], "decay": 1.5,
     "distance": 12},
    {"type": "AmbientLight", "color": [0.2, 0.2, 0.25]}
  ],
  "camera": {"type": "OrthographicCamera", "left": -2, "right": 2, "top": 1.5, "bottom": -1.5, "near": 0.1,
             "far": 40, "position": [3, 2, 6], "target": [0, 0, 0]},
  "background": "#ffffff",
  "size": [160, 120]
})";

const char* kMtoonFlags =
    "builtin:torus-knot --shading mtoon --base-color 0.9,0.6,0.4 --set shade-color=0.3,0.2,0.45 "
    "--set shading-shift=-0.1 --set shading-toony=0.7 --set rim-color=0.5,0.4,0.3 --set rim-fresnel-power=2 "
    "--set rim-lift=0.05 --set rim-lighting-mix=0.5 --set shadows=false --set outline-width-mode=screen-coordinates "
    "--set outline-width=0.02 --set outline-color=0.1,0.05,0.2 --set outline-lighting-mix=0.5 "
    "--set emissive=0.05,0.02,0 --set emissive-intensity=2 --set shading-shift-texture-scale=0.5 "
    "--set normal-scale=2 --set uv-animation-scroll-x-speed=0.3 --set uv-animation-scroll-y-speed=-0.1 "
    "--set uv-animation-rotation-speed=0.2 --light-type point "
    "--light-color 1,0.9,0.8 --light-intensity 30 --light-decay 1.5 --light-distance 12 --light-pos 2,3,4 "
    "--ambient 0.2,0.2,0.25 --ortho --ortho-height 3 --near 0.1 --far 40 --eye 3,2,6 --target 0,0,0 "
    "--background '#ffffff' --size 160x120 --samples 1";

TEST(ThreejsSceneCli, MToonMaterialSceneAndEquivalentFlagsGiveByteIdenticalImages) {
    TempDir dir;
    const std::string scene = dir.write("mtoon.json", kMtoonScene);
    auto a = run_cli("render --scene " + scene + " -o " + dir.file("scene.png"));
    ASSERT_EQ(a.status, 0) << a.err;
    EXPECT_EQ(a.err, "");
    auto b = run_cli(std::string("render ") + kMtoonFlags + " -o " + dir.file("flags.png"));
    ASSERT_EQ(b.status, 0) << b.err;
    EXPECT_EQ(slurp(dir.file("scene.png")), slurp(dir.file("flags.png"))) << "scene and flags differ";
    // The light counts: with intensity 1 (the flag over the scene) the knot is much darker.
    auto dim = run_cli("render --scene " + scene + " --light-intensity 1 -o " + dir.file("dim.png"));
    ASSERT_EQ(dim.status, 0) << dim.err;
    const Image lit = read_png(dir.file("scene.png")), dark = read_png(dir.file("dim.png"));
    long sum_lit = 0, sum_dark = 0;
    for (int y = 0; y < lit.height; ++y)
        for (int x = 0; x < lit.width; ++x) sum_lit += lit.pixel(x, y)[0], sum_dark += dark.pixel(x, y)[0];
    EXPECT_GT(sum_lit, sum_dark + 20 * 255) << "intensity 30 looks like intensity 1";
    // The emission counts too: without it (the flag over the scene) the knot is darker.
    auto unlit = run_cli("render --scene " + scene + " --set emissive=0,0,0 -o " + dir.file("no-emission.png"));
    ASSERT_EQ(unlit.status, 0) << unlit.err;
    const Image plain = read_png(dir.file("no-emission.png"));
    long sum_plain = 0;
    for (int y = 0; y < plain.height; ++y)
        for (int x = 0; x < plain.width; ++x) sum_plain += plain.pixel(x, y)[0];
    EXPECT_GT(sum_lit, sum_plain + 20 * 255) << "emissive changes nothing";
}

TEST(ThreejsSceneCli, CommandLineOptionsOverrideTheScene) {
    TempDir dir;
    const std::string scene = dir.write("phong.json", kPhongScene);
    auto r = run_cli("render --scene " + scene + " --size 64x48 --set color=#0000ff --background white -o " +
                     dir.file("a.png"));
    ASSERT_EQ(r.status, 0) << r.err;
    const Image img = read_png(dir.file("a.png"));
    EXPECT_EQ(img.width, 64);
    EXPECT_EQ(img.height, 48);
    EXPECT_EQ(int(img.pixel(0, 0)[0]), 255);
    int blue = 0, orange = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const uint8_t* p = img.pixel(x, y);
            blue += p[2] > 100 && p[0] < 80;
            orange += p[0] > 150 && p[2] < 60;
        }
    EXPECT_GT(blue, 50);
    EXPECT_EQ(orange, 0);
}

TEST(ThreejsSceneCli, BadScenesAreOneLineErrorsNamingFileAndField) {
    TempDir dir;
    struct Case {
        const char* name;
        const char* json;
        const char* field;
    };
    for (const Case& c :
         {Case{"syntax.json", "{\"mesh\": ", "not valid JSON"},
          Case{"material.json", R"({"mesh": "builtin:sphere", "material": {"type": "MeshFancyMaterial"}})",
               "material.type"},
          Case{"range.json",
               R"({"mesh": "builtin:sphere", "material": {"type": "MeshPhongMaterial", "shininess": -5}})",
               "material.shininess"},
          Case{"outline.json",
               R"({"mesh": "builtin:sphere", "material": {"type": "MeshToonMaterial"}, "outline": {"alpha": 2}})",
               "outline.alpha"}}) {
        const std::string path = dir.write(c.name, c.json);
        auto r = run_cli("render --scene " + path + " -o " + dir.file("a.png"));
        EXPECT_EQ(r.status, 2) << c.name;
        EXPECT_EQ(line_count(r.err), 1) << r.err;
        EXPECT_NE(r.err.find("inkshade: " + path + ": "), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(c.field), std::string::npos) << r.err;
    }
    auto missing = run_cli("render -o " + dir.file("a.png"));
    EXPECT_EQ(missing.status, 2);
    EXPECT_EQ(line_count(missing.err), 1) << missing.err;
    EXPECT_NE(missing.err.find("MODEL"), std::string::npos) << missing.err;
}

}  // namespace
}  // namespace inkshade::test
