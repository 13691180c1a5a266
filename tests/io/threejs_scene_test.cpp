// The three.js-like scene JSON (docs/threejs.md): three.js's names, defaults and colour
// conventions, and one-line errors naming the file and the field.
#include <gtest/gtest.h>

#include <cmath>

#include "inkshade/color.hpp"
#include "inkshade/error.hpp"
#include "inkshade/threejs_scene.hpp"
#include "support/temp_dir.hpp"

namespace inkshade {
namespace {

ThreejsScene parse(const std::string& json) { return parse_threejs_scene(json, "scene.json"); }

// The message of the InputError parsing `json` throws ("" when it parses).
std::string error_of(const std::string& json) {
    try {
        parse(json);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

const char* kMinimal = R"({"mesh": "builtin:sphere", "material": {"type": "MeshLambertMaterial"}})";

TEST(ThreejsScene, MaterialTypesMapToModelsWithSrgbColours) {
    ThreejsScene s = parse(R"({"mesh": "builtin:sphere", "material": {"type": "MeshPhongMaterial",
        "color": 16746496, "specular": "#333", "shininess": 50, "emissive": [0.25, 0, 0], "emissiveIntensity": 2}})");
    EXPECT_EQ(s.model, "threejs-phong");
    // 0xff8800 and "#333" are sRGB as typed; the linear array is encoded to sRGB for the parameter.
    EXPECT_EQ(s.params.at("color"), (ParamValue{1.0f, 0x88 / 255.0f, 0.0f}));
    EXPECT_EQ(s.params.at("specular"), (ParamValue{0x33 / 255.0f, 0x33 / 255.0f, 0x33 / 255.0f}));
    EXPECT_NEAR(srgb_to_linear(s.params.at("emissive")[0]), 0.25f, 1e-5f);
    EXPECT_EQ(s.params.at("shininess"), ParamValue{50.0f});
    EXPECT_EQ(s.params.at("emissive-intensity"), ParamValue{2.0f});
    EXPECT_EQ(s.param_fields.at("shininess"), "material.shininess");
    for (auto [type, model] : {std::pair{"MeshBasicMaterial", "threejs-basic"},
                               {"MeshLambertMaterial", "threejs-lambert"},
                               {"MeshToonMaterial", "threejs-toon"},
                               {"MeshNormalMaterial", "threejs-normal"}})
        EXPECT_EQ(parse(std::string(R"({"mesh": "m.obj", "material": {"type": ")") + type + "\"}}").model, model);
}

// three-vrm's MToonMaterial by its field names: the factors become mtoon's parameters (colours
// linear, as THREE.Color holds them), `color` the base colour; fields without an effect in such a
// scene are accepted; those the model lacks are one-line errors unless at three-vrm's default.
TEST(ThreejsScene, MToonMaterialFieldsMapOntoTheMtoonModel) {
    ThreejsScene s = parse(R"({"mesh": "m.obj", "material": {"type": "MToonMaterial", "color": "#ff8800",
        "shadeColorFactor": [0.3, 0.2, 0.45], "shadingShiftFactor": -0.1, "shadingToonyFactor": 0.6,
        "parametricRimColorFactor": 16777215, "parametricRimFresnelPowerFactor": 2, "parametricRimLiftFactor": 0.05,
        "rimLightingMixFactor": 0.5, "giEqualizationFactor": 0.9, "matcapFactor": [1, 1, 1],
        "outlineWidthMode": "none", "outlineWidthFactor": 0.02, "emissive": "#000000", "emissiveIntensity": 1,
        "uvAnimationScrollXSpeedFactor": 0, "transparentWithZWrite": false}})");
    EXPECT_EQ(s.model, "mtoon");
    ASSERT_TRUE(s.base_color);
    EXPECT_NEAR(s.base_color->g, srgb_to_linear(0x88 / 255.0f), 1e-6f);  // "#ff8800" is sRGB, decoded
    EXPECT_EQ(s.params.at("shade-color"), (ParamValue{0.3f, 0.2f, 0.45f}));
    EXPECT_EQ(s.params.at("rim-color"), (ParamValue{1.0f, 1.0f, 1.0f}));
    EXPECT_EQ(s.params.at("shading-shift"), ParamValue{-0.1f});
    EXPECT_EQ(s.params.at("shading-toony"), ParamValue{0.6f});
    EXPECT_EQ(s.params.at("rim-fresnel-power"), ParamValue{2.0f});
    EXPECT_EQ(s.params.at("rim-lift"), ParamValue{0.05f});
    EXPECT_EQ(s.params.at("rim-lighting-mix"), ParamValue{0.5f});
    EXPECT_EQ(s.params.at("convention"), ParamValue{1.0f});  // threejs
    EXPECT_EQ(s.params.at("shadows"), ParamValue{0.0f});     // three.js renders none by default
    EXPECT_EQ(s.param_fields.at("shading-toony"), "material.shadingToonyFactor");
    EXPECT_EQ(s.params.at("matcap-color"), (ParamValue{1.0f, 1.0f, 1.0f}));
    EXPECT_EQ(s.params.at("outline-width-mode"), ParamValue{0.0f});  // "none"
    EXPECT_EQ(s.params.at("outline-width"), ParamValue{0.02f});

    // Emission, the shading shift texture's scale, the normal map's scale and the UV animation.
    const ThreejsScene em = parse(R"({"mesh": "m.obj", "material": {"type": "MToonMaterial",
        "emissive": [0.5, 0.25, 0], "emissiveIntensity": 2, "shadingShiftTextureScale": 0.5, "normalScale": [2, -2],
        "uvAnimationScrollXSpeedFactor": 0.25, "uvAnimationScrollYSpeedFactor": -0.5,
        "uvAnimationRotationSpeedFactor": 1.5}})");
    EXPECT_EQ(em.params.at("emissive"), (ParamValue{0.5f, 0.25f, 0.0f}));
    EXPECT_EQ(em.params.at("emissive-intensity"), ParamValue{2.0f});
    EXPECT_EQ(em.params.at("shading-shift-texture-scale"), ParamValue{0.5f});
    EXPECT_EQ(em.params.at("normal-scale"), ParamValue{2.0f});
    EXPECT_EQ(em.params.at("uv-animation-scroll-x-speed"), ParamValue{0.25f});
    EXPECT_EQ(em.params.at("uv-animation-scroll-y-speed"), ParamValue{-0.5f});
    EXPECT_EQ(em.params.at("uv-animation-rotation-speed"), ParamValue{1.5f});
    EXPECT_EQ(em.param_fields.at("emissive"), "material.emissive");
    // Hex text is sRGB, decoded as THREE.Color holds it.
    EXPECT_EQ(parse(R"({"mesh": "m.obj", "material": {"type": "MToonMaterial", "emissive": "#808080"}})")
                  .params.at("emissive")[0],
              srgb_to_linear(128.0f / 255.0f));

    // The outline: outlineWidthMode by three-vrm's strings, the colour linear as THREE.Color holds it.
    const ThreejsScene o = parse(R"({"mesh": "m.obj", "material": {"type": "MToonMaterial",
        "outlineWidthMode": "screenCoordinates", "outlineWidthFactor": 0.004, "outlineColorFactor": "#ff0000",
        "outlineLightingMixFactor": 0.25}})");
    EXPECT_EQ(o.params.at("outline-width-mode"), ParamValue{2.0f});
    EXPECT_EQ(o.params.at("outline-width"), ParamValue{0.004f});
    EXPECT_EQ(o.params.at("outline-color"), (ParamValue{1.0f, 0.0f, 0.0f}));
    EXPECT_EQ(o.params.at("outline-lighting-mix"), ParamValue{0.25f});
    EXPECT_EQ(o.param_fields.at("outline-width-mode"), "material.outlineWidthMode");
    EXPECT_EQ(
        parse(R"({"mesh": "m.obj", "material": {"type": "MToonMaterial", "outlineWidthMode": "worldCoordinates"}})")
            .params.at("outline-width-mode"),
        ParamValue{1.0f});

    const std::string m = R"({"mesh": "m.obj", "material": {"type": "MToonMaterial", )";
    const auto error = [&](const std::string& fields) {
        try {
            parse(m + fields + "}}");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(error(R"("outlineWidthMode": "screen")"),
              "scene.json: material.outlineWidthMode: expected \"none\", \"worldCoordinates\" or "
              "\"screenCoordinates\", got \"screen\"");
    EXPECT_EQ(error(R"("matcapTexture": 0)"),
              "scene.json: material.matcapTexture: a scene file cannot give a "
              "texture (the mesh file's own textures are used)");
    EXPECT_NE(error(R"("normalMap": {"uuid": "x"})").find("material.normalMap: a scene file cannot give a texture"),
              std::string::npos);
    EXPECT_NE(error(R"("v0CompatShade": true)").find("material.v0CompatShade: not supported by Inkshade's mtoon"),
              std::string::npos);
    EXPECT_NE(error(R"("normalScale": [1, 1])").find("material.normalScale: expected [x, y] with y = -x"),
              std::string::npos);
    EXPECT_NE(error(R"("shadeColor": [0, 0, 0])").find("material.shadeColor: unknown field (allowed: type, name"),
              std::string::npos);
    EXPECT_NE(error(R"("shadingToonyFactor": "hard")").find("material.shadingToonyFactor: expected a number"),
              std::string::npos);
}

TEST(ThreejsScene, ToonGradientMapSwitchesTheMapOn) {
    ThreejsScene s =
        parse(R"({"mesh": "m.obj", "material": {"type": "MeshToonMaterial", "gradientMap": [0.2, 0.6, 1]}})");
    EXPECT_EQ(s.params.at("use-gradient-map"), ParamValue{1.0f});
    EXPECT_EQ(s.params.at("gradient-map"), (ParamValue{0.2f, 0.6f, 1.0f}));
    EXPECT_EQ(parse(R"({"mesh": "m.obj", "material": {"type": "MeshToonMaterial"}})").params.count("use-gradient-map"),
              0u);
}

TEST(ThreejsScene, LightsBecomeLinearColoursAndIntensities) {
    ThreejsScene s = parse(R"({"mesh": "m.obj", "material": {"type": "MeshLambertMaterial"}, "lights": [
        {"type": "AmbientLight", "color": "#404040", "intensity": 2},
        {"type": "PointLight", "color": [1, 0.5, 0.25], "intensity": 40, "position": [1, 2, 3], "decay": 1.5, "distance": 9}]})");
    EXPECT_EQ(s.light_type, LightType::Point);
    EXPECT_EQ(*s.light_position, glm::vec3(1, 2, 3));
    EXPECT_EQ(s.light_color, glm::vec3(1, 0.5f, 0.25f));             // arrays are linear (Color.fromArray)
    EXPECT_NEAR(s.ambient.r, srgb_to_linear(0x40 / 255.0f), 1e-6f);  // hex is sRGB, decoded
    EXPECT_EQ(s.params.at("ambient-intensity"), ParamValue{2.0f});
    EXPECT_EQ(s.params.at("light-intensity"), ParamValue{40.0f});
    EXPECT_EQ(s.params.at("light-decay"), ParamValue{1.5f});
    EXPECT_EQ(s.params.at("light-distance"), ParamValue{9.0f});
}

TEST(ThreejsScene, DefaultsAreThreejsDefaults) {
    ThreejsScene s = parse(R"({"mesh": "m.obj", "material": {"type": "MeshLambertMaterial"},
        "lights": [{"type": "DirectionalLight"}], "camera": {"type": "PerspectiveCamera", "position": [0, 0, 5]}})");
    // DirectionalLight: white, intensity 1, at (0, 1, 0) aiming at the origin.
    EXPECT_EQ(s.light_color, glm::vec3(1.0f));
    EXPECT_EQ(s.params.at("light-intensity"), ParamValue{1.0f});
    EXPECT_EQ(*s.light_position, glm::vec3(0, 1, 0));
    EXPECT_EQ(*s.light_target, glm::vec3(0.0f));
    EXPECT_EQ(s.ambient, glm::vec3(0.0f));  // no AmbientLight
    // PerspectiveCamera(50, aspect, 0.1, 2000) looking at the origin; black opaque clear; no antialias.
    EXPECT_EQ(s.camera->fov_degrees, 50.0f);
    EXPECT_EQ(s.camera->near_plane, 0.1f);
    EXPECT_EQ(s.camera->far_plane, 2000.0f);
    EXPECT_EQ(s.camera->target, glm::vec3(0.0f));
    EXPECT_EQ(s.background, glm::vec4(0, 0, 0, 1));
    EXPECT_FALSE(s.antialias);
    EXPECT_FALSE(s.outline.has_value());
    // No direct light at all: light-intensity 0 (ambient only).
    EXPECT_EQ(parse(kMinimal).params.at("light-intensity"), ParamValue{0.0f});
}

TEST(ThreejsScene, CamerasMapZoomAndOrthographicFrustum) {
    ThreejsScene p = parse(R"({"mesh": "m.obj", "material": {"type": "MeshBasicMaterial"},
        "camera": {"type": "PerspectiveCamera", "fov": 60, "zoom": 2, "position": [1, 2, 3], "target": [0, 1, 0], "up": [0, 0, 1]}})");
    // three.js: fov' = 2 atan(tan(fov / 2) / zoom).
    EXPECT_NEAR(p.camera->fov_degrees, 2.0f * glm::degrees(std::atan(std::tan(glm::radians(30.0f)) / 2.0f)), 1e-4f);
    EXPECT_EQ(p.camera->position, glm::vec3(1, 2, 3));
    EXPECT_EQ(p.camera->up, glm::vec3(0, 0, 1));
    ThreejsScene o = parse(R"({"mesh": "m.obj", "material": {"type": "MeshBasicMaterial"},
        "camera": {"type": "OrthographicCamera", "left": -4, "right": 4, "top": 3, "bottom": -3, "zoom": 2, "position": [0, 0, 9]}})");
    EXPECT_TRUE(o.camera->orthographic);
    EXPECT_EQ(o.camera->ortho_height, 3.0f);  // (top - bottom) / zoom
}

TEST(ThreejsScene, BackgroundOutlineSizeAndAntialias) {
    ThreejsScene s = parse(R"({"mesh": "m.obj", "material": {"type": "MeshToonMaterial"}, "background": "#336699",
        "outline": {"thickness": 0.01, "color": [0.5, 0, 0], "alpha": 0.5}, "size": [640, 480], "antialias": true})");
    EXPECT_EQ(s.background, glm::vec4(0x33 / 255.0f, 0x66 / 255.0f, 0x99 / 255.0f, 1.0f));  // cleared as typed
    EXPECT_EQ(s.outline->at("thickness"), ParamValue{0.01f});
    EXPECT_EQ(s.outline->at("color"), (ParamValue{0.5f, 0.0f, 0.0f}));  // linear, as OutlineEffect's array
    EXPECT_EQ(s.outline->at("alpha"), ParamValue{0.5f});
    EXPECT_EQ(*s.size, glm::ivec2(640, 480));
    EXPECT_TRUE(s.antialias);
    EXPECT_EQ(parse(R"({"mesh": "m.obj", "material": {"type": "MeshBasicMaterial"}, "background": "transparent"})")
                  .background.a,
              0.0f);
}

TEST(ThreejsScene, ErrorsNameTheFileAndTheField) {
    struct Case {
        std::string json, field;
    };
    const std::string m = R"("mesh": "m.obj", )";
    for (
        const Case& c : std::vector<Case>{
            {"{", "not valid JSON"},
            {R"({"mesh": "m.obj", "size": [1e400, 1]})", "not valid JSON (number overflow"},  // found by fuzzing
            {R"({"material": {"type": "MeshBasicMaterial"}})", "mesh"},
            {"{" + m + R"("material": {"type": "MeshStandardMaterial"}})", "material.type"},
            {"{" + m + R"("material": {"type": "MeshLambertMaterial", "colour": "#fff"}})", "material.colour"},
            {"{" + m + R"("material": {"type": "MeshLambertMaterial", "color": "red"}})", "material.color"},
            {"{" + m + R"("material": {"type": "MeshLambertMaterial", "color": [2, 0, 0]}})", "material.color"},
            {"{" + m + R"("material": {"type": "MeshPhongMaterial", "shininess": "high"}})", "material.shininess"},
            {"{" + m + R"("material": {"type": "MeshBasicMaterial"}, "lights": [{"type": "SpotLight"}]})",
             "lights[0].type"},
            {"{" + m +
                 R"("material": {"type": "MeshBasicMaterial"}, "lights": [{"type": "PointLight"}, {"type": "DirectionalLight"}]})",
             "lights[1]"},
            {"{" + m +
                 R"("material": {"type": "MeshBasicMaterial"}, "lights": [{"type": "AmbientLight", "intensity": -1}]})",
             "lights[0].intensity"},
            {"{" + m + R"("material": {"type": "MeshBasicMaterial"}, "camera": {"type": "PerspectiveCamera"}})",
             "camera.position"},
            {"{" + m +
                 R"("material": {"type": "MeshBasicMaterial"}, "camera": {"type": "PerspectiveCamera", "fov": 0, "position": [0, 0, 1]}})",
             "camera.fov"},
            {"{" + m +
                 R"("material": {"type": "MeshBasicMaterial"}, "camera": {"type": "OrthographicCamera", "left": 0, "position": [0, 0, 1]}})",
             "camera.left"},
            {"{" + m + R"("material": {"type": "MeshBasicMaterial"}, "size": [0, 10]})", "size"},
            {"{" + m + R"("material": {"type": "MeshBasicMaterial"}, "outline": {"width": 2}})", "outline.width"},
            {"{" + m + R"("material": {"type": "MeshBasicMaterial"}, "fog": true})", "fog"},
            // Keys and values with line breaks are quoted with '?' (found by fuzzing).
            {"{" + m + R"("material": {"type": "MeshBasicMaterial"}, "\nfog": true})", "?fog: unknown field"},
            {"{" + m + R"("material": {"type": "Mesh\r\nMaterial"}})", "'Mesh??Material'"},
        }) {
        const std::string what = error_of(c.json);
        EXPECT_EQ(what.rfind("scene.json: ", 0), 0u) << c.json << " -> " << what;
        EXPECT_NE(what.find(c.field), std::string::npos) << c.json << " -> " << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
}

TEST(ThreejsScene, LoadResolvesRelativeMeshPathsAgainstTheSceneFolder) {
    test::TempDir dir;
    const std::string path =
        dir.write("scene.json", R"({"mesh": "models/bunny.obj", "material": {"type": "MeshBasicMaterial"}})");
    EXPECT_EQ(load_threejs_scene(path).mesh, dir.file("models/bunny.obj"));
    const std::string builtin = dir.write("b.json", kMinimal);
    EXPECT_EQ(load_threejs_scene(builtin).mesh, "builtin:sphere");
    EXPECT_THROW(load_threejs_scene(dir.file("missing.json")), InputError);
}

}  // namespace
}  // namespace inkshade
