// glTF 2.0 / GLB / VRM reading: geometry under node transforms, attributes, materials,
// textures, VRM MToon parameters, and one-line errors for damaged files.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/constants.hpp>

#include "io/gltf_files.hpp"
#include "io/mesh_files.hpp"
#include "io/readers.hpp"
#include "support/temp_dir.hpp"
#include "support/expect_near.hpp"

namespace inkshade::test {
namespace {

using nlohmann::json;

glm::vec3 face_normal(const Mesh& m, size_t t) {
    const glm::uvec3 f = m.triangles[t];
    return glm::normalize(glm::cross(m.positions[f.y] - m.positions[f.x], m.positions[f.z] - m.positions[f.x]));
}

bool has_warning(const Mesh& m, const std::string& phrase) {
    for (const std::string& w : m.warnings)
        if (w.find(phrase) != std::string::npos && w.find('\n') == std::string::npos) return true;
    return false;
}

void expect_quad_texture(const Mesh& m) {
    ASSERT_EQ(m.materials.size(), 1u);
    const Material& mat = m.materials[0];
    EXPECT_EQ(mat.diffuse, glm::vec3(0.5f, 0.25f, 1.0f));
    ASSERT_TRUE(mat.texture);
    EXPECT_EQ(mat.texture->width, 2);
    EXPECT_EQ(mat.texture->height, 2);
    EXPECT_EQ(mat.texture->rgba, kTexturePixels);
}

// One triangle in z = 0 facing +z with a +z normal; returns the mesh index.
int triangle_mesh(GltfBuilder& g) {
    int pos = g.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
    int nrm = g.floats({0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3", 3);
    return g.mesh({{"POSITION", pos}, {"NORMAL", nrm}});
}

TEST(GltfReader, TexturedQuadInGlbHasPositionsUvsBaseColourAndTexture) {
    TempDir dir;
    Mesh m = load_mesh(dir.write("quad.glb", textured_quad().glb()));
    ASSERT_EQ(m.vertex_count(), 4u);
    ASSERT_EQ(m.triangle_count(), 2u);
    EXPECT_EQ(m.positions[2], glm::vec3(1, 1, 0));
    EXPECT_EQ(m.triangles[1], glm::uvec3(0, 2, 3));
    // glTF's uv origin is the image's top-left; Mesh::uvs put v = 0 at the bottom.
    ASSERT_EQ(m.uvs.size(), 4u);
    EXPECT_EQ(m.uvs[0], glm::vec2(0, 0));
    EXPECT_EQ(m.uvs[2], glm::vec2(1, 1));
    ASSERT_EQ(m.face_materials, (std::vector<uint32_t>{0, 0}));
    expect_quad_texture(m);
    EXPECT_TRUE(m.warnings.empty());
    for (size_t t = 0; t < 2; ++t) expect_near(face_normal(m, t), glm::vec3(0, 0, 1));
}

TEST(GltfReader, GltfWithDataUrisLoadsTheSameQuad) {
    TempDir dir;
    GltfBuilder g = textured_quad(false);
    g.doc["images"][0]["uri"] = "data:image/png;base64," + base64(png_bytes(2, 2, kTexturePixels));
    Mesh m = load_mesh(dir.write("quad.gltf", g.gltf_embedded()));
    EXPECT_EQ(m.triangle_count(), 2u);
    expect_quad_texture(m);
    // The same JSON named .glb (a renamed file) is recognised by its content.
    EXPECT_EQ(load_mesh(dir.write("renamed.glb", g.gltf_embedded())).triangle_count(), 2u);
}

TEST(GltfReader, GltfWithBinFileAndImageFileInSubdirectory) {
    TempDir dir;
    std::filesystem::create_directories(dir.path() / "assets" / "tex");
    GltfBuilder g = textured_quad(false);
    g.doc["images"][0]["uri"] = "tex/quad%20one.png";  // URIs are percent-encoded (section 3.3)
    dir.write("assets/tex/quad one.png", png_bytes(2, 2, kTexturePixels));
    dir.write("assets/quad.bin", g.padded_bin());
    Mesh m = load_mesh(dir.write("assets/quad.gltf", g.json_with_buffer("quad.bin")));
    EXPECT_EQ(m.triangle_count(), 2u);
    expect_quad_texture(m);
    EXPECT_EQ(m.materials[0].texture->source, dir.file("assets/tex/quad one.png"));
}

TEST(GltfReader, MissingOrCorruptTextureIsAWarningAndTheBaseColourStays) {
    TempDir dir;
    Mesh m = load_mesh(dir.write("quad.gltf", textured_quad(false).gltf_embedded()));  // quad.png absent
    ASSERT_EQ(m.materials.size(), 1u);
    EXPECT_FALSE(m.materials[0].texture);
    EXPECT_EQ(m.materials[0].diffuse, glm::vec3(0.5f, 0.25f, 1.0f));
    EXPECT_TRUE(has_warning(m, dir.file("quad.gltf") + ": texture 'quad.png' not loaded (file not found)"))
        << ::testing::PrintToString(m.warnings);

    dir.write("quad.png", "not a png at all");
    Mesh bad = load_mesh(dir.file("quad.gltf"));
    EXPECT_FALSE(bad.materials[0].texture);
    EXPECT_TRUE(has_warning(bad, "texture 'quad.png' not loaded (not a decodable image"))
        << ::testing::PrintToString(bad.warnings);

    GltfBuilder g = textured_quad();
    g.doc["bufferViews"][3]["byteLength"] = 1000000;  // the PNG's bufferView runs past the buffer
    Mesh past = load_mesh(dir.write("past.glb", g.glb()));
    EXPECT_FALSE(past.materials[0].texture);
    EXPECT_TRUE(has_warning(past, "is past the end of buffer 0")) << ::testing::PrintToString(past.warnings);
}

TEST(GltfReader, NodeHierarchyAppliesTranslationRotationScaleAndMatrix) {
    TempDir dir;
    GltfBuilder g;
    int mesh = triangle_mesh(g);
    const float s = std::sqrt(0.5f);
    // a: rotate 90 degrees about z, then scale 2 (T * R * S applies S first).
    int a = g.node({{"mesh", mesh}, {"rotation", {0, 0, s, s}}, {"scale", {2, 2, 2}}});
    // b: a column-major matrix translating by (0, 5, 0).
    int b = g.node({{"mesh", mesh}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 5, 0, 1}}});
    int root = g.node({{"translation", {10, 0, 0}}, {"children", {a, b}}});
    g.scene({root});
    Mesh m = io::read_gltf(dir.write("tree.glb", g.glb()));
    ASSERT_EQ(m.vertex_count(), 6u);
    ASSERT_EQ(m.triangle_count(), 2u);
    expect_near(m.positions[0], {10, 0, 0});
    expect_near(m.positions[1], {10, 2, 0});  // (1,0,0) scaled 2, rotated to +y, moved +10 x
    expect_near(m.positions[2], {8, 0, 0});   // (0,1,0) -> (0,2,0) -> (-2,0,0)
    expect_near(m.positions[3], {10, 5, 0});
    expect_near(m.positions[4], {11, 5, 0});
    expect_near(m.positions[5], {10, 6, 0});
    ASSERT_EQ(m.normals.size(), 6u);
    expect_near(m.normals[1], {0, 0, 1});
}

TEST(GltfReader, NodesWithoutASceneAreAllRead) {
    TempDir dir;
    GltfBuilder g;
    int mesh = triangle_mesh(g);
    g.node({{"mesh", mesh}});
    g.node({{"mesh", mesh}, {"translation", {0, 0, 3}}});
    Mesh m = io::read_gltf(dir.write("noscene.glb", g.glb()));
    ASSERT_EQ(m.triangle_count(), 2u);
    expect_near(m.positions[3], {0, 0, 3});
}

TEST(GltfReader, MirrorTransformKeepsFrontFacesCounterClockwise) {
    TempDir dir;
    GltfBuilder g;
    int mesh = triangle_mesh(g);
    g.scene({g.node({{"mesh", mesh}, {"scale", {-1, 1, 1}}})});
    Mesh m = io::read_gltf(dir.write("mirror.glb", g.glb()));
    ASSERT_EQ(m.triangle_count(), 1u);
    expect_near(m.positions[1], {-1, 0, 0});
    // The mirrored triangle still faces +z (where its normals point): the winding was flipped.
    expect_near(face_normal(m, 0), {0, 0, 1});
    expect_near(m.normals[0], {0, 0, 1});
    EXPECT_EQ(m.triangles[0], glm::uvec3(0, 2, 1));
}

TEST(GltfReader, NormalsUseTheInverseTranspose) {
    TempDir dir;
    GltfBuilder g;
    const float s = std::sqrt(0.5f);
    int pos = g.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
    int nrm = g.floats({s, s, 0, s, s, 0, s, s, 0}, "VEC3", 3);
    int mesh = g.mesh({{"POSITION", pos}, {"NORMAL", nrm}});
    g.scene({g.node({{"mesh", mesh}, {"scale", {2, 1, 1}}})});
    Mesh m = io::read_gltf(dir.write("stretch.glb", g.glb()));
    expect_near(m.normals[0], glm::normalize(glm::vec3(0.5f, 1, 0)));  // not normalize(2, 1, 0)
}

TEST(GltfReader, IndexTypesAndNonIndexedPrimitives) {
    TempDir dir;
    for (int type : {kUByte, kUShort, kUInt, -1}) {
        GltfBuilder g;
        int pos = g.floats({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}, "VEC3", 3);
        int idx = -1;
        if (type == kUByte) idx = g.data(std::vector<uint8_t>{0, 1, 2, 2, 1, 3}, kUByte, 1, "SCALAR");
        if (type == kUShort) idx = g.data(std::vector<uint16_t>{0, 1, 2, 2, 1, 3}, kUShort, 1, "SCALAR");
        if (type == kUInt) idx = g.data(std::vector<uint32_t>{0, 1, 2, 2, 1, 3}, kUInt, 1, "SCALAR");
        g.scene({g.node({{"mesh", g.mesh({{"POSITION", pos}}, idx)}})});
        Mesh m = io::read_gltf(dir.write("idx.glb", g.glb()));
        if (type < 0) {
            EXPECT_EQ(m.triangle_count(), 1u);  // 4 vertices, no indices: one triangle (0 1 2), one corner left over
            EXPECT_TRUE(has_warning(m, "not a multiple of 3"));
        } else {
            ASSERT_EQ(m.triangle_count(), 2u) << type;
            EXPECT_EQ(m.triangles[1], glm::uvec3(2, 1, 3)) << type;
        }
    }
}

TEST(GltfReader, StripsAndFansAreTriangulatedCounterClockwise) {
    TempDir dir;
    for (int mode : {kStrip, kFan}) {
        GltfBuilder g;
        // strip order 0 1 2 3 zig-zags; fan order goes round the quad.
        std::vector<float> p = mode == kStrip ? std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}
                                              : std::vector<float>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
        int pos = g.floats(p, "VEC3", 3);
        g.scene({g.node({{"mesh", g.mesh({{"POSITION", pos}}, -1, -1, mode)}})});
        Mesh m = io::read_gltf(dir.write("strip.glb", g.glb()));
        ASSERT_EQ(m.triangle_count(), 2u) << mode;
        for (size_t t = 0; t < 2; ++t) expect_near(face_normal(m, t), {0, 0, 1});
    }
}

TEST(GltfReader, VertexColoursAreNormalizedAndMultiplyTheBaseColour) {
    TempDir dir;
    GltfBuilder g;
    int pos = g.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
    int col = g.data(std::vector<uint8_t>{255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 51, 255}, kUByte, 4, "VEC4", true);
    int mat = g.material({0.5f, 1, 1, 1});
    int coloured = g.mesh({{"POSITION", pos}, {"COLOR_0", col}}, -1, mat);
    int pos2 = g.floats({0, 0, 1, 1, 0, 1, 0, 1, 1}, "VEC3", 3);
    int col16 = g.data(std::vector<uint16_t>{65535, 65535, 0, 0, 0, 0, 0, 0, 0}, kUShort, 3, "VEC3", true);
    int coloured16 = g.mesh({{"POSITION", pos2}, {"COLOR_0", col16}});
    int plain = g.mesh({{"POSITION", pos2}}, -1, mat);
    g.scene({g.node({{"mesh", coloured}}), g.node({{"mesh", coloured16}}), g.node({{"mesh", plain}})});
    Mesh m = io::read_gltf(dir.write("colours.glb", g.glb()));
    ASSERT_EQ(m.colors.size(), 9u);
    EXPECT_EQ(m.colors[0], glm::vec3(0.5f, 0, 0));
    EXPECT_EQ(m.colors[1], glm::vec3(0, 1, 0));
    expect_near(m.colors[2], {0, 0, 0.2f});
    EXPECT_EQ(m.colors[3], glm::vec3(1, 1, 0));     // default material: base colour 1
    EXPECT_EQ(m.colors[8], glm::vec3(0.5f, 1, 1));  // no COLOR_0: its material's colour
}

TEST(GltfReader, SparseAccessorReplacesSelectedElements) {
    TempDir dir;
    GltfBuilder g;
    int pos = g.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
    int idx_view = g.view(std::vector<uint16_t>{2, 0}.data(), 4);
    std::vector<float> values = {0, 3, 0};
    int val_view = g.view(values.data(), 12);
    g.doc["accessors"][pos]["sparse"] = {{"count", 1},
                                         {"indices", {{"bufferView", idx_view}, {"componentType", kUShort}}},
                                         {"values", {{"bufferView", val_view}}}};
    g.scene({g.node({{"mesh", g.mesh({{"POSITION", pos}})}})});
    Mesh m = io::read_gltf(dir.write("sparse.glb", g.glb()));
    EXPECT_EQ(m.positions[2], glm::vec3(0, 3, 0));
    EXPECT_EQ(m.positions[1], glm::vec3(1, 0, 0));
}

json vrm0_material_properties() {
    return json::array({{{"name", "skin"},
                         {"shader", "VRM/MToon"},
                         {"floatProperties",
                          {{"_ShadeShift", 0.2},
                           {"_ShadeToony", 0.5},
                           {"_RimFresnelPower", 3.0},
                           {"_RimLift", 0.1},
                           {"_RimLightingMix", 0.5},
                           {"_OutlineWidth", 2.0},
                           {"_OutlineWidthMode", 1},
                           {"_OutlineColorMode", 1},
                           {"_OutlineLightingMix", 0.25}}},
                         {"vectorProperties",
                          {{"_Color", {0.5, 1, 1, 1}},
                           {"_ShadeColor", {0.5, 0.5, 1, 1}},
                           {"_RimColor", {1, 0, 0, 1}},
                           {"_OutlineColor", {0, 0.5, 0, 1}}}},
                         {"textureProperties", json::object()}}});
}

TEST(GltfReader, VrmZeroMToonParametersAreConvertedAsThreeVrmDoes) {
    TempDir dir;
    GltfBuilder g = textured_quad();
    g.doc["extensions"]["VRM"] = {{"materialProperties", vrm0_material_properties()}};
    Mesh m = load_mesh(dir.write("avatar.vrm", g.glb()));
    ASSERT_EQ(m.materials.size(), 1u);
    const auto& p = m.materials[0].mtoon;
    ASSERT_FALSE(p.empty());
    const float g22 = std::pow(0.5f, 2.2f);  // VRM 0.x colours are gamma-encoded
    expect_near(m.materials[0].diffuse, {g22, 1, 1});
    ASSERT_EQ(p.at("shade-color").size(), 3u);
    EXPECT_NEAR(p.at("shade-color")[0], g22, 1e-6f);
    EXPECT_NEAR(p.at("shade-color")[2], 1.0f, 1e-6f);
    // toony' = lerp(0.5, 1, 0.5 + 0.5 * 0.2) = 0.8; shift' = -0.2 - (1 - 0.8) = -0.4
    EXPECT_NEAR(p.at("shading-toony")[0], 0.8f, 1e-6f);
    EXPECT_NEAR(p.at("shading-shift")[0], -0.4f, 1e-6f);
    EXPECT_EQ(p.at("rim-color"), (std::vector<float>{1, 0, 0}));
    EXPECT_FLOAT_EQ(p.at("rim-fresnel-power")[0], 3.0f);
    EXPECT_FLOAT_EQ(p.at("rim-lift")[0], 0.1f);
    EXPECT_FLOAT_EQ(p.at("rim-lighting-mix")[0], 0.5f);
    EXPECT_FLOAT_EQ(p.at("outline-width-mode")[0], 1.0f);
    EXPECT_FLOAT_EQ(p.at("outline-width")[0], 0.02f);  // centimetres to metres
    EXPECT_NEAR(p.at("outline-color")[1], g22, 1e-6f);
    EXPECT_FLOAT_EQ(p.at("outline-lighting-mix")[0], 0.25f);
    ASSERT_TRUE(m.materials[0].texture);  // the glTF base colour texture stays
}

TEST(GltfReader, VrmOneMToonExtensionIsRead) {
    TempDir dir;
    GltfBuilder g = textured_quad();
    g.doc["materials"][0]["extensions"]["VRMC_materials_mtoon"] = {{"specVersion", "1.0"},
                                                                   {"shadeColorFactor", {0.25, 0.5, 0.75}},
                                                                   {"shadingShiftFactor", -0.1},
                                                                   {"shadingToonyFactor", 0.95},
                                                                   {"parametricRimColorFactor", {0, 1, 0}},
                                                                   {"parametricRimFresnelPowerFactor", 4},
                                                                   {"parametricRimLiftFactor", 0.3},
                                                                   {"rimLightingMixFactor", 0.7},
                                                                   {"outlineWidthMode", "screenCoordinates"},
                                                                   {"outlineWidthFactor", 0.005},
                                                                   {"outlineColorFactor", {1, 0, 1}}};
    Mesh m = load_mesh(dir.write("avatar.vrm", g.glb()));
    const auto& p = m.materials[0].mtoon;
    EXPECT_EQ(p.at("shade-color"), (std::vector<float>{0.25f, 0.5f, 0.75f}));
    EXPECT_FLOAT_EQ(p.at("shading-shift")[0], -0.1f);
    EXPECT_FLOAT_EQ(p.at("shading-toony")[0], 0.95f);
    EXPECT_EQ(p.at("rim-color"), (std::vector<float>{0, 1, 0}));
    EXPECT_FLOAT_EQ(p.at("rim-fresnel-power")[0], 4.0f);
    EXPECT_FLOAT_EQ(p.at("rim-lift")[0], 0.3f);
    EXPECT_FLOAT_EQ(p.at("rim-lighting-mix")[0], 0.7f);
    EXPECT_FLOAT_EQ(p.at("outline-width-mode")[0], 2.0f);
    EXPECT_FLOAT_EQ(p.at("outline-width")[0], 0.005f);
    EXPECT_EQ(p.at("outline-color"), (std::vector<float>{1, 0, 1}));
    EXPECT_FLOAT_EQ(p.at("outline-lighting-mix")[0], 1.0f);           // default
    EXPECT_EQ(m.materials[0].diffuse, glm::vec3(0.5f, 0.25f, 1.0f));  // VRM 1.0 keeps the glTF base colour
}

// VRMC_materials_mtoon's textureInfo objects become the material's MToon textures, decoded
// like the base colour texture (images shared), and matcapFactor its matcap colour.
TEST(GltfReader, VrmOneMToonTexturesAreRead) {
    TempDir dir;
    GltfBuilder g = textured_quad();
    const std::vector<uint8_t> grey = {40, 80, 120, 255};
    const int matcap = g.texture_in_buffer(png_bytes(1, 1, grey));
    g.doc["materials"][0]["extensions"]["VRMC_materials_mtoon"] = {{"specVersion", "1.0"},
                                                                   {"matcapFactor", {0.5, 0.25, 1}},
                                                                   {"matcapTexture", {{"index", matcap}}},
                                                                   {"rimMultiplyTexture", {{"index", 0}}},
                                                                   {"outlineWidthMultiplyTexture", {{"index", 0}}}};
    Mesh m = load_mesh(dir.write("avatar.vrm", g.glb()));
    const Material& mat = m.materials[0];
    EXPECT_EQ(mat.mtoon.at("matcap-color"), (std::vector<float>{0.5f, 0.25f, 1}));
    ASSERT_TRUE(mat.mtoon_textures.at("matcap-texture"));
    EXPECT_EQ(mat.mtoon_textures.at("matcap-texture")->rgba, grey);
    ASSERT_TRUE(mat.mtoon_textures.at("rim-multiply-texture"));
    EXPECT_EQ(mat.mtoon_textures.at("rim-multiply-texture"), mat.texture);  // one image, decoded once
    EXPECT_EQ(mat.mtoon_textures.at("outline-width-multiply-texture"), mat.texture);

    // Without them: no MToon textures, the specification's matcap factor 1.
    g.doc["materials"][0]["extensions"]["VRMC_materials_mtoon"] = {{"specVersion", "1.0"}};
    Mesh plain = load_mesh(dir.write("plain.vrm", g.glb()));
    EXPECT_TRUE(plain.materials[0].mtoon_textures.empty());
    EXPECT_EQ(plain.materials[0].mtoon.at("matcap-color"), (std::vector<float>{1, 1, 1}));
}

// VRM 0.x: _SphereAdd, _RimTexture and _OutlineWidthTexture, as three-vrm's
// VRMMaterialsV0CompatPlugin ports them.
TEST(GltfReader, VrmZeroMToonTexturesAreRead) {
    TempDir dir;
    GltfBuilder g = textured_quad();
    nlohmann::json props = vrm0_material_properties();
    props[0]["textureProperties"] = {{"_SphereAdd", 0}, {"_RimTexture", 0}, {"_OutlineWidthTexture", 0}};
    g.doc["extensions"]["VRM"] = {{"materialProperties", props}};
    Mesh m = load_mesh(dir.write("avatar.vrm", g.glb()));
    const Material& mat = m.materials[0];
    for (const char* key : {"matcap-texture", "rim-multiply-texture", "outline-width-multiply-texture"}) {
        ASSERT_TRUE(mat.mtoon_textures.count(key)) << key;
        EXPECT_EQ(mat.mtoon_textures.at(key)->rgba, kTexturePixels) << key;
    }
}

// VRM 0.x's shade, emission, bump and UV animation properties as VRMMaterialsV0CompatPlugin
// ports them: _EmissionColor gamma-decoded into emissiveFactor, _BumpScale the normal map's
// scale, _UvAnimScrollY negated (0.x scrolled v up the image), the textures by their 0.x names.
TEST(GltfReader, VrmZeroMapsEmissionAndUvAnimationAreConverted) {
    TempDir dir;
    GltfBuilder g = textured_quad();
    nlohmann::json props = vrm0_material_properties();
    props[0]["floatProperties"]["_BumpScale"] = 0.7;
    props[0]["floatProperties"]["_UvAnimScrollX"] = 0.2;
    props[0]["floatProperties"]["_UvAnimScrollY"] = 0.3;
    props[0]["floatProperties"]["_UvAnimRotation"] = 0.1;
    props[0]["vectorProperties"]["_EmissionColor"] = {0.5, 0.25, 0, 1};
    props[0]["textureProperties"] = {
        {"_ShadeTexture", 0}, {"_EmissionMap", 0}, {"_BumpMap", 0}, {"_UvAnimMaskTexture", 0}};
    g.doc["extensions"]["VRM"] = {{"materialProperties", props}};
    const Mesh m = load_mesh(dir.write("avatar.vrm", g.glb()));
    const Material& mat = m.materials[0];
    const auto& p = mat.mtoon;
    EXPECT_NEAR(p.at("emissive")[0], std::pow(0.5f, 2.2f), 1e-6f);
    EXPECT_NEAR(p.at("emissive")[1], std::pow(0.25f, 2.2f), 1e-6f);
    EXPECT_EQ(p.at("emissive")[2], 0.0f);
    EXPECT_FLOAT_EQ(p.at("emissive-intensity")[0], 1.0f);
    EXPECT_FLOAT_EQ(p.at("normal-scale")[0], 0.7f);
    EXPECT_FLOAT_EQ(p.at("uv-animation-scroll-x-speed")[0], 0.2f);
    EXPECT_FLOAT_EQ(p.at("uv-animation-scroll-y-speed")[0], -0.3f);
    EXPECT_FLOAT_EQ(p.at("uv-animation-rotation-speed")[0], 0.1f);
    EXPECT_FLOAT_EQ(p.at("shading-shift-texture-scale")[0], 1.0f);
    for (const char* key :
         {"shade-multiply-texture", "emissive-texture", "normal-texture", "uv-animation-mask-texture"}) {
        ASSERT_TRUE(mat.mtoon_textures.count(key)) << key;
        EXPECT_EQ(mat.mtoon_textures.at(key)->rgba, kTexturePixels) << key;
    }
    EXPECT_EQ(mat.mtoon_textures.count("shading-shift-texture"), 0u);  // MToon 0.x has none

    // Without them: no emission, scale 1, no animation.
    const Mesh plain = load_mesh(dir.write("plain.vrm", [&] {
        GltfBuilder q = textured_quad();
        q.doc["extensions"]["VRM"] = {{"materialProperties", vrm0_material_properties()}};
        return q.glb();
    }()));
    EXPECT_EQ(plain.materials[0].mtoon.at("emissive"), (std::vector<float>{0, 0, 0}));
    EXPECT_FLOAT_EQ(plain.materials[0].mtoon.at("normal-scale")[0], 1.0f);
    EXPECT_FLOAT_EQ(plain.materials[0].mtoon.at("uv-animation-scroll-y-speed")[0], 0.0f);
}

// VRM 0.x's VRM/Unlit* shaders become an MToon material whose shade colour and shade multiply
// texture are the lit colour and main texture, so light changes nothing.
TEST(GltfReader, VrmZeroUnlitShadesWithItsMainTexture) {
    TempDir dir;
    GltfBuilder g = textured_quad();
    g.doc["extensions"]["VRM"] = {
        {"materialProperties", nlohmann::json::array({{{"name", "unlit"},
                                                       {"shader", "VRM/UnlitTexture"},
                                                       {"vectorProperties", {{"_Color", {0.5, 1, 1, 1}}}},
                                                       {"textureProperties", {{"_MainTex", 0}}}}})}};
    const Mesh m = load_mesh(dir.write("avatar.vrm", g.glb()));
    const Material& mat = m.materials[0];
    EXPECT_NEAR(mat.mtoon.at("shade-color")[0], std::pow(0.5f, 2.2f), 1e-6f);
    ASSERT_TRUE(mat.mtoon_textures.count("shade-multiply-texture"));
    EXPECT_EQ(mat.mtoon_textures.at("shade-multiply-texture"), mat.texture);
}

// VRM 1.0: the glTF material's emissiveFactor, KHR_materials_emissive_strength, emissiveTexture
// and normalTexture (with its scale), and VRMC_materials_mtoon's shade multiply, shading shift
// (with its scale) and UV animation, as three-vrm's loader plugins give them to MToonMaterial;
// KHR_materials_unlit beside MToon is dropped, as three-vrm drops it.
TEST(GltfReader, VrmOneMapsEmissionAndUvAnimationAreRead) {
    TempDir dir;
    GltfBuilder g = textured_quad();
    nlohmann::json& mat = g.doc["materials"][0];
    mat["emissiveFactor"] = {0.5, 0.25, 0.125};
    mat["emissiveTexture"] = {{"index", 0}};
    mat["normalTexture"] = {{"index", 0}, {"scale", 0.6}};
    mat["extensions"]["KHR_materials_emissive_strength"] = {{"emissiveStrength", 4}};
    mat["extensions"]["KHR_materials_unlit"] = nlohmann::json::object();
    mat["extensions"]["VRMC_materials_mtoon"] = {{"specVersion", "1.0"},
                                                 {"shadeMultiplyTexture", {{"index", 0}}},
                                                 {"shadingShiftTexture", {{"index", 0}, {"scale", 0.3}}},
                                                 {"uvAnimationMaskTexture", {{"index", 0}}},
                                                 {"uvAnimationScrollXSpeedFactor", 0.5},
                                                 {"uvAnimationScrollYSpeedFactor", -0.25},
                                                 {"uvAnimationRotationSpeedFactor", 2}};
    const Mesh m = load_mesh(dir.write("avatar.vrm", g.glb()));
    const Material& out = m.materials[0];
    const auto& p = out.mtoon;
    EXPECT_EQ(p.at("emissive"), (std::vector<float>{0.5f, 0.25f, 0.125f}));  // linear, as written
    EXPECT_FLOAT_EQ(p.at("emissive-intensity")[0], 4.0f);
    EXPECT_FLOAT_EQ(p.at("normal-scale")[0], 0.6f);
    EXPECT_FLOAT_EQ(p.at("shading-shift-texture-scale")[0], 0.3f);
    EXPECT_FLOAT_EQ(p.at("uv-animation-scroll-x-speed")[0], 0.5f);
    EXPECT_FLOAT_EQ(p.at("uv-animation-scroll-y-speed")[0], -0.25f);
    EXPECT_FLOAT_EQ(p.at("uv-animation-rotation-speed")[0], 2.0f);
    for (const char* key : {"shade-multiply-texture", "shading-shift-texture", "emissive-texture", "normal-texture",
                            "uv-animation-mask-texture"}) {
        ASSERT_TRUE(out.mtoon_textures.count(key)) << key;
        EXPECT_EQ(out.mtoon_textures.at(key), out.texture) << key;  // one image, decoded once
    }
    EXPECT_FALSE(out.unlit);

    // The specification's defaults: no emission (intensity 1), scales 1, no animation.
    mat = {{"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, 1}}}},
           {"extensions", {{"VRMC_materials_mtoon", {{"specVersion", "1.0"}}}}}};
    const Mesh defaults = load_mesh(dir.write("plain.vrm", g.glb()));
    const auto& d = defaults.materials[0].mtoon;
    EXPECT_EQ(d.at("emissive"), (std::vector<float>{0, 0, 0}));
    EXPECT_FLOAT_EQ(d.at("emissive-intensity")[0], 1.0f);
    EXPECT_FLOAT_EQ(d.at("normal-scale")[0], 1.0f);
    EXPECT_FLOAT_EQ(d.at("shading-shift-texture-scale")[0], 1.0f);
    EXPECT_FLOAT_EQ(d.at("uv-animation-rotation-speed")[0], 0.0f);
}

// KHR_texture_transform as three.js r187's GLTFLoader.extendTexture sets the texture's matrix
// when there is a rotation (the extension's T R S: scale, rotate, then offset; setUvTransform,
// which rotates first, gives the same matrix without one):
// s' = cos r sx s + sin r sy t + ox, t' = -sin r sx s + cos r sy t + oy.
glm::vec2 three_uv(glm::vec2 st, float ox, float oy, float r, float sx, float sy) {
    return {std::cos(r) * sx * st.x + std::sin(r) * sy * st.y + ox,
            -std::sin(r) * sx * st.x + std::cos(r) * sy * st.y + oy};
}
glm::vec2 apply(const glm::mat3& m, glm::vec2 st) { return glm::vec2(m * glm::vec3(st, 1.0f)); }
void expect_near2(glm::vec2 a, glm::vec2 b, float eps) { expect_near(glm::vec3(a, 0.0f), glm::vec3(b, 0.0f), eps); }

TEST(GltfReader, TextureTransformsAreReadAsThreeJsAppliesThem) {
    TempDir dir;
    GltfBuilder g = textured_quad();
    nlohmann::json& mat = g.doc["materials"][0];
    mat["pbrMetallicRoughness"]["baseColorTexture"]["extensions"]["KHR_texture_transform"] = {
        {"offset", {0.1, 0.2}}, {"rotation", 0.5}, {"scale", {2, 3}}};
    mat["emissiveTexture"] = {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"scale", {4, 4}}}}}}};
    mat["extensions"]["VRMC_materials_mtoon"] = {
        {"specVersion", "1.0"},
        {"shadeMultiplyTexture", {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"offset", {0.5, 0}}}}}}}},
        {"rimMultiplyTexture", {{"index", 0}}}};
    const Mesh m = load_mesh(dir.write("avatar.vrm", g.glb()));
    const Material& out = m.materials[0];
    const glm::vec2 st(0.3f, 0.7f);
    ASSERT_TRUE(out.uv_transforms.count("base-color-texture"));
    expect_near2(apply(out.uv_transforms.at("base-color-texture"), st), three_uv(st, 0.1f, 0.2f, 0.5f, 2, 3), 1e-6f);
    ASSERT_TRUE(out.uv_transforms.count("shade-multiply-texture"));
    expect_near2(apply(out.uv_transforms.at("shade-multiply-texture"), st), st + glm::vec2(0.5f, 0.0f), 1e-6f);
    ASSERT_TRUE(out.uv_transforms.count("emissive-texture"));
    expect_near2(apply(out.uv_transforms.at("emissive-texture"), st), 4.0f * st, 1e-6f);
    EXPECT_EQ(out.uv_transforms.count("rim-multiply-texture"), 0u);  // none given: identity
    for (const std::string& w : m.warnings) EXPECT_EQ(w.find("KHR_texture_transform"), std::string::npos) << w;

    // VRM 0.x: _MainTex [offset s, offset t, scale s, scale t] ported as three-vrm ports it
    // (three-vrm 3.5.5 _portTextureTransform: offset t' = 1 - scale t - offset t), for every
    // texture but the matcap.
    GltfBuilder v0 = textured_quad();
    nlohmann::json props = vrm0_material_properties();
    props[0]["vectorProperties"]["_MainTex"] = {0.25, 0.1, 2, 3};
    props[0]["textureProperties"] = {{"_MainTex", 0}, {"_ShadeTexture", 0}, {"_SphereAdd", 0}, {"_EmissionMap", 0}};
    v0.doc["extensions"]["VRM"] = {{"materialProperties", props}};
    const Mesh old = load_mesh(dir.write("old.vrm", v0.glb()));
    const Material& o = old.materials[0];
    const glm::vec2 want = three_uv(st, 0.25f, 1.0f - 3.0f - 0.1f, 0.0f, 2, 3);
    for (const char* key : {"base-color-texture", "shade-multiply-texture", "emissive-texture"}) {
        ASSERT_TRUE(o.uv_transforms.count(key)) << key;
        expect_near2(apply(o.uv_transforms.at(key), st), want, 1e-5f);
    }
    EXPECT_TRUE(o.mtoon_textures.count("matcap-texture"));
    EXPECT_EQ(o.uv_transforms.count("matcap-texture"), 0u);
}

TEST(GltfReader, PlainGltfMaterialHasNoMToonParameters) {
    TempDir dir;
    Mesh m = load_mesh(dir.write("quad.glb", textured_quad().glb()));
    EXPECT_TRUE(m.materials[0].mtoon.empty());
}

// glTF alphaMode, alphaCutoff, doubleSided and baseColorFactor's alpha (sections 3.9.4-3.9.5),
// with the specification's defaults (OPAQUE, 0.5, single-sided) where absent.
TEST(GltfReader, AlphaModesCutoffAndDoubleSidedAreRead) {
    TempDir dir;
    GltfBuilder g = textured_quad();
    Mesh plain = load_mesh(dir.write("plain.glb", g.glb()));
    EXPECT_EQ(plain.materials[0].alpha_mode, AlphaMode::Opaque);
    EXPECT_EQ(plain.materials[0].sides, FaceSides::Front);
    EXPECT_FLOAT_EQ(plain.materials[0].alpha, 1.0f);
    EXPECT_FLOAT_EQ(plain.materials[0].alpha_cutoff, 0.5f);

    g.doc["materials"][0]["alphaMode"] = "MASK";
    g.doc["materials"][0]["alphaCutoff"] = 0.3;
    g.doc["materials"][0]["doubleSided"] = true;
    g.doc["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = {0.5, 0.25, 1.0, 0.75};
    Mesh mask = load_mesh(dir.write("mask.glb", g.glb()));
    EXPECT_EQ(mask.materials[0].alpha_mode, AlphaMode::Mask);
    EXPECT_FLOAT_EQ(mask.materials[0].alpha_cutoff, 0.3f);
    EXPECT_EQ(mask.materials[0].sides, FaceSides::Double);
    EXPECT_FLOAT_EQ(mask.materials[0].alpha, 0.75f);

    g.doc["materials"][0]["alphaMode"] = "BLEND";
    Mesh blend = load_mesh(dir.write("blend.glb", g.glb()));
    EXPECT_EQ(blend.materials[0].alpha_mode, AlphaMode::Blend);
    EXPECT_FALSE(blend.materials[0].blend_depth_write);  // GLTFLoader: depthWrite false
    EXPECT_EQ(blend.materials[0].render_order, 0);
}

// three-vrm's MToonMaterialLoaderPlugin: renderOrder = renderQueueOffsetNumber + (19 without
// transparentWithZWrite, 0 with it); the z-write flag writes depth.
TEST(GltfReader, VrmOneTransparentWithZWriteAndRenderQueueAreRead) {
    TempDir dir;
    GltfBuilder g = textured_quad();
    g.doc["materials"][0]["alphaMode"] = "BLEND";
    g.doc["materials"][0]["extensions"]["VRMC_materials_mtoon"] = {
        {"specVersion", "1.0"}, {"transparentWithZWrite", true}, {"renderQueueOffsetNumber", 3}};
    Mesh z = load_mesh(dir.write("z.vrm", g.glb()));
    EXPECT_TRUE(z.materials[0].blend_depth_write);
    EXPECT_EQ(z.materials[0].render_order, 3);
    g.doc["materials"][0]["extensions"]["VRMC_materials_mtoon"] = {{"specVersion", "1.0"},
                                                                   {"renderQueueOffsetNumber", -2}};
    Mesh plain = load_mesh(dir.write("plain.vrm", g.glb()));
    EXPECT_FALSE(plain.materials[0].blend_depth_write);
    EXPECT_EQ(plain.materials[0].render_order, 17);
}

// VRM 0.x, as three-vrm's VRMMaterialsV0CompatPlugin ports it: _ALPHABLEND_ON / _ALPHATEST_ON
// and _Cutoff, _ZWrite, _CullMode 0 = double-sided, _Color's alpha as written, and the
// transparent materials' render queues mapped in order to offsets ending at 0 (z-write:
// starting at 0).
TEST(GltfReader, VrmZeroBlendModesCullModeAndRenderQueuesAreConverted) {
    TempDir dir;
    GltfBuilder g = textured_quad();
    for (int i = 0; i < 3; ++i) g.doc["materials"].push_back(g.doc["materials"][0]);
    json props = json::array();
    for (int i = 0; i < 4; ++i) props.push_back(vrm0_material_properties()[0]);
    props[0]["keywordMap"] = {{"_ALPHATEST_ON", true}};
    props[0]["floatProperties"]["_Cutoff"] = 0.25;
    props[0]["floatProperties"]["_CullMode"] = 0;
    props[0]["vectorProperties"]["_Color"] = {1, 1, 1, 0.5};
    props[1]["keywordMap"] = {{"_ALPHABLEND_ON", true}};
    props[1]["renderQueue"] = 3005;
    props[2]["keywordMap"] = {{"_ALPHABLEND_ON", true}};
    props[2]["renderQueue"] = 3001;
    props[3]["keywordMap"] = {{"_ALPHABLEND_ON", true}};
    props[3]["floatProperties"]["_ZWrite"] = 1;
    props[3]["renderQueue"] = 2501;
    g.doc["extensions"]["VRM"] = {{"materialProperties", props}};
    // One primitive per material.
    json prim = g.doc["meshes"][0]["primitives"][0];
    for (int i = 1; i < 4; ++i) {
        prim["material"] = i;
        g.doc["meshes"][0]["primitives"].push_back(prim);
    }
    Mesh m = load_mesh(dir.write("avatar.vrm", g.glb()));
    ASSERT_EQ(m.materials.size(), 4u);
    EXPECT_EQ(m.materials[0].alpha_mode, AlphaMode::Mask);
    EXPECT_FLOAT_EQ(m.materials[0].alpha_cutoff, 0.25f);
    EXPECT_EQ(m.materials[0].sides, FaceSides::Double);
    EXPECT_FLOAT_EQ(m.materials[0].alpha, 0.5f);  // alpha is stored linear
    EXPECT_EQ(m.materials[1].alpha_mode, AlphaMode::Blend);
    EXPECT_EQ(m.materials[1].sides, FaceSides::Front);  // _CullMode 2 (back) by default
    EXPECT_EQ(m.materials[1].render_order, 19 + 0);     // queues 3001, 3005 -> offsets -1, 0
    EXPECT_EQ(m.materials[2].render_order, 19 - 1);
    EXPECT_TRUE(m.materials[3].blend_depth_write);
    EXPECT_EQ(m.materials[3].render_order, 0);
}

TEST(GltfReader, LinesAreKeptAndPointsSkippedWithAWarning) {
    TempDir dir;
    GltfBuilder g;
    int tri = triangle_mesh(g);
    int pos = g.floats({0, 0, 0, 1, 0, 0, 1, 1, 0}, "VEC3", 3);
    int lines = g.mesh({{"POSITION", pos}}, -1, -1, kLines);  // 3 vertices: one segment, one left over
    int loop = g.mesh({{"POSITION", pos}}, -1, -1, 2);        // LINE_LOOP: three segments
    int points = g.mesh({{"POSITION", pos}}, -1, -1, kPoints);
    g.scene({g.node({{"mesh", tri}}), g.node({{"mesh", lines}, {"translation", {0, 0, 5}}}),
             g.node({{"mesh", loop}}), g.node({{"mesh", points}})});
    Mesh m = load_mesh(dir.write("mixed.glb", g.glb()));
    EXPECT_EQ(m.triangle_count(), 1u);
    ASSERT_EQ(m.line_segments.size(), 4u);
    // Placed by their node's transform.
    EXPECT_EQ(m.positions[m.line_segments[0].x], glm::vec3(0, 0, 5));
    EXPECT_EQ(m.positions[m.line_segments[0].y], glm::vec3(1, 0, 5));
    EXPECT_EQ(m.positions[m.line_segments[3].y], glm::vec3(0, 0, 0));  // the loop closes
    EXPECT_TRUE(has_warning(m, "1 point primitive skipped"));
}

// --- bad input: one line naming the file and the problem, never a crash ---------------------

TEST(GltfReader, OnlyPointsOrLinesIsAnError) {
    TempDir dir;
    GltfBuilder g;
    int pos = g.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
    g.scene({g.node({{"mesh", g.mesh({{"POSITION", pos}}, -1, -1, kPoints)}})});
    EXPECT_TRUE(
        LoadFailsWith(dir.write("points.glb", g.glb()), "no triangles (only point or line primitives: 1 skipped)"));
}

TEST(GltfReader, TruncatedGlbIsAnError) {
    TempDir dir;
    std::string glb = textured_quad().glb();
    EXPECT_TRUE(LoadFailsWith(dir.write("a.glb", glb.substr(0, 7)), "truncated GLB (7 bytes; the header alone is 12)"));
    EXPECT_TRUE(LoadFailsWith(dir.write("b.glb", glb.substr(0, glb.size() - 10)),
                              "truncated GLB: the header says " + std::to_string(glb.size()) +
                                  " bytes but the file has " + std::to_string(glb.size() - 10)));
    // Header patched to match a cut file: the chunks themselves run past the end.
    std::string cut = glb.substr(0, 40);
    uint32_t len = 40;
    std::memcpy(&cut[8], &len, 4);
    EXPECT_TRUE(LoadFailsWith(dir.write("c.glb", cut), "truncated GLB: the JSON chunk"));
    for (size_t n = 1; n < glb.size(); n += 7) {  // every cut: a one-line error
        std::string p = dir.write("cut.glb", glb.substr(0, n));
        EXPECT_THROW(load_mesh(p), InputError) << n;
    }
}

TEST(GltfReader, WrongMagicOrVersionIsAnError) {
    TempDir dir;
    std::string glb = textured_quad().glb();
    std::string wrong = glb;
    wrong.replace(0, 4, "GLTF");
    EXPECT_TRUE(LoadFailsWith(dir.write("magic.glb", wrong), "not a GLB file (magic is 'GLTF', expected 'glTF')"));
    EXPECT_TRUE(LoadFailsWith(dir.write("obj.vrm", cube_obj()), "not a GLB file (magic is '# un', expected 'glTF')"));
    std::string v1 = glb;
    v1[4] = 1;
    EXPECT_TRUE(LoadFailsWith(dir.write("v1.glb", v1), "GLB version 1 is not supported (glTF 2.0 only)"));
}

TEST(GltfReader, BadJsonIsAnError) {
    TempDir dir;
    EXPECT_TRUE(LoadFailsWith(dir.write("bad.gltf", "{\"asset\": {\"version\": \"2.0\"},\n \"meshes\": [ }"),
                              "bad JSON: parse error at line 2"));
    EXPECT_TRUE(LoadFailsWith(dir.write("noasset.gltf", "{\"meshes\": []}"), "\"asset\" object not found"));
    EXPECT_TRUE(LoadFailsWith(dir.write("v1.gltf", "{\"asset\": {\"version\": \"1.0\"}}"),
                              "glTF version 1.0 is not supported"));
    EXPECT_TRUE(LoadFailsWith(dir.write("empty.gltf", "{\"asset\": {\"version\": \"2.0\"}}"),
                              "no triangles (the scene has no mesh)"));
}

TEST(GltfReader, OutOfRangeAccessorIsAnErrorNamingTheAccessor) {
    TempDir dir;
    GltfBuilder g = textured_quad();
    g.doc["accessors"][0]["count"] = 5;  // 5 positions of 12 bytes in a 48-byte bufferView
    EXPECT_TRUE(LoadFailsWith(dir.write("count.glb", g.glb()),
                              "accessor 0 (POSITION of mesh 0 primitive 0): 5 elements of 12 bytes from offset 0 do "
                              "not fit in bufferView 0 (48 bytes)"));
    g = textured_quad();
    g.doc["accessors"][0]["count"] = 800000000;  // checked against the bufferView before allocating 9.6 GB
    EXPECT_TRUE(
        LoadFailsWith(dir.write("big.glb", g.glb()), "800000000 elements of 12 bytes from offset 0 do not fit"));
    g = textured_quad();
    g.doc["accessors"][0]["byteOffset"] = 4;
    EXPECT_TRUE(LoadFailsWith(dir.write("offset.glb", g.glb()),
                              "accessor 0 (POSITION of mesh 0 primitive 0): 4 elements of 12 bytes from offset 4"));
    g = textured_quad();
    g.doc["accessors"][1]["bufferView"] = 99;
    EXPECT_TRUE(LoadFailsWith(dir.write("view.glb", g.glb()),
                              "accessor 1 (TEXCOORD_0 of mesh 0 primitive 0) refers to bufferView 99"));
    g = textured_quad();
    g.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 42;
    EXPECT_TRUE(LoadFailsWith(dir.write("missing.glb", g.glb()),
                              "POSITION of mesh 0 primitive 0 refers to accessor 42 but the file has 3"));
    g = textured_quad();
    g.doc["accessors"][0]["count"] = 1000000000000LL;
    g.doc["accessors"][0].erase("bufferView");  // zeros of a huge count: refused before allocating
    EXPECT_TRUE(LoadFailsWith(dir.write("huge.glb", g.glb()),
                              "accessor 0 (POSITION of mesh 0 primitive 0) claims 1000000000000 elements"));
    g.doc["accessors"][0]["count"] = 100000000;
    EXPECT_TRUE(LoadFailsWith(dir.write("zeros.glb", g.glb()),
                              "claims 100000000 elements without a bufferView (limit 4194304)"));
    g = textured_quad();
    g.doc["bufferViews"][0]["byteStride"] = 8;  // smaller than a VEC3 of floats
    EXPECT_TRUE(
        LoadFailsWith(dir.write("stride.glb", g.glb()), "bufferView 0 has byteStride 8 (elements are 12 bytes)"));
}

TEST(GltfReader, BufferViewPastTheBufferIsAnError) {
    TempDir dir;
    GltfBuilder g = textured_quad();
    g.doc["bufferViews"][1]["byteOffset"] = 4000;
    EXPECT_TRUE(LoadFailsWith(
        dir.write("view.glb", g.glb()),
        "accessor 1 (TEXCOORD_0 of mesh 0 primitive 0): bufferView 1 (bytes 4000..4032) is past the end of buffer 0"));
}

TEST(GltfReader, IndexOutOfRangeIsAnError) {
    TempDir dir;
    GltfBuilder g;
    int pos = g.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
    int idx = g.data(std::vector<uint16_t>{0, 1, 3}, kUShort, 1, "SCALAR");
    g.scene({g.node({{"mesh", g.mesh({{"POSITION", pos}}, idx)}})});
    EXPECT_TRUE(
        LoadFailsWith(dir.write("idx.glb", g.glb()),
                      "accessor 1 (indices of mesh 0 primitive 0): index 2 is 3 but the primitive has 3 vertices"));
}

TEST(GltfReader, MissingBinFileIsAnError) {
    TempDir dir;
    EXPECT_TRUE(LoadFailsWith(dir.write("quad.gltf", textured_quad().json_with_buffer("quad.bin")),
                              "buffer file 'quad.bin' not found"));
    dir.write("short.bin", "0123");
    EXPECT_TRUE(LoadFailsWith(dir.write("short.gltf", textured_quad().json_with_buffer("short.bin")),
                              "buffer file size does not match"));
}

TEST(GltfReader, NodeCycleIsAnErrorNotAHang) {
    TempDir dir;
    GltfBuilder g;
    int mesh = triangle_mesh(g);
    g.node({{"mesh", mesh}, {"children", {1}}});
    g.node({{"children", {0}}});
    g.scene({0});
    EXPECT_TRUE(
        LoadFailsWith(dir.write("cycle.glb", g.glb()), "node 0 is reached twice (the node hierarchy must be a tree)"));
    g.doc["nodes"][1]["children"] = {7};
    EXPECT_TRUE(LoadFailsWith(dir.write("dangling.glb", g.glb()), "scene refers to node 7 but the file has 2"));
}

TEST(GltfReader, CompressedGeometryIsRefusedClearly) {
    TempDir dir;
    GltfBuilder g = textured_quad();
    g.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    g.doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    EXPECT_TRUE(LoadFailsWith(dir.write("draco.glb", g.glb()), "requires extension KHR_draco_mesh_compression"));
}

TEST(GltfReader, NonFiniteValuesAreErrors) {
    TempDir dir;
    GltfBuilder g;
    int pos = g.floats({0, 0, 0, NAN, 0, 0, 0, 1, 0}, "VEC3", 3);
    g.scene({g.node({{"mesh", g.mesh({{"POSITION", pos}})}})});
    EXPECT_TRUE(LoadFailsWith(dir.write("nan.glb", g.glb()),
                              "accessor 0 (POSITION of mesh 0 primitive 0): element 1 is not a finite number"));
}

}  // namespace
}  // namespace inkshade::test
