// glTF cameras (section 3.10), KHR_lights_punctual lights and KHR_materials_unlit as read_gltf
// returns them: placed by their nodes' global transforms, in scene order, a bad one a warning.
#include <gtest/gtest.h>

#include <cmath>

#include "io/gltf_files.hpp"
#include "io/readers.hpp"
#include "support/temp_dir.hpp"
#include "support/expect_near.hpp"

namespace inkshade::test {
namespace {

using nlohmann::json;

bool has_warning(const Mesh& m, const std::string& phrase) {
    for (const std::string& w : m.warnings)
        if (w.find(phrase) != std::string::npos) return true;
    return false;
}

// A builder with one triangle at the origin (node 0, the scene's first root).
GltfBuilder with_triangle() {
    GltfBuilder g;
    int pos = g.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
    g.node({{"mesh", g.mesh({{"POSITION", pos}})}});
    return g;
}

// Quaternion (x, y, z, w) of a rotation by `degrees` about a unit axis.
json quaternion(glm::vec3 axis, float degrees) {
    const float h = 0.5f * glm::radians(degrees);
    return {axis.x * std::sin(h), axis.y * std::sin(h), axis.z * std::sin(h), std::cos(h)};
}

TEST(GltfCameras, PerspectiveAndOrthographicCamerasArePlacedByTheirNodes) {
    TempDir dir;
    GltfBuilder g = with_triangle();
    g.doc["cameras"] = {
        {{"type", "perspective"},
         {"name", "Main"},
         {"perspective", {{"yfov", 0.6}, {"aspectRatio", 1.5}, {"znear", 0.1}, {"zfar", 50}}}},
        {{"type", "orthographic"}, {"orthographic", {{"xmag", 2}, {"ymag", -1}, {"znear", 0.01}, {"zfar", 20}}}},
        {{"type", "perspective"}, {"perspective", {{"yfov", 1.0}, {"znear", 0.5}}}}};
    // The parent turns 90 degrees about +y and moves to (1, 2, 3); the child sits 5 along the
    // parent's +z and tilts 30 degrees down (about +x by -30).
    int child = g.node({{"camera", 0}, {"translation", {0, 0, 5}}, {"rotation", quaternion({1, 0, 0}, -30)}});
    int parent = g.node({{"translation", {1, 2, 3}}, {"rotation", quaternion({0, 1, 0}, 90)}, {"children", {child}}});
    int top = g.node({{"name", "TopNode"}, {"camera", 1}, {"translation", {0, 0, 10}}, {"scale", {3, 3, 3}}});
    int plain = g.node({{"camera", 2}});
    g.scene({0, parent, top, plain});
    const Mesh m = io::read_gltf(dir.write("cameras.glb", g.glb()));
    EXPECT_TRUE(m.warnings.empty()) << m.warnings.front();
    ASSERT_EQ(m.cameras.size(), 3u);

    const FileCamera& main = m.cameras[0];
    EXPECT_EQ(main.name, "Main");
    EXPECT_FALSE(main.orthographic);
    EXPECT_NEAR(main.yfov_degrees, 0.6 * 180.0 / M_PI, 1e-4);
    ASSERT_TRUE(main.aspect_ratio);
    EXPECT_FLOAT_EQ(*main.aspect_ratio, 1.5f);
    EXPECT_FLOAT_EQ(main.znear, 0.1f);
    ASSERT_TRUE(main.zfar);
    EXPECT_FLOAT_EQ(*main.zfar, 50.0f);
    // (0, 0, 5) turned about +y by 90 degrees is (5, 0, 0); -z tilted down is (0, -sin 30, -cos 30),
    // then turned: (-cos 30, -sin 30, 0); +y tilted: (0, cos 30, -sin 30), turned: (-sin 30, cos 30, 0).
    const float c30 = std::cos(glm::radians(30.0f)), s30 = 0.5f;
    expect_near(main.placement.position, {6, 2, 3});
    expect_near(main.placement.forward, {-c30, -s30, 0});
    expect_near(main.placement.up, {-s30, c30, 0});

    const FileCamera& ortho = m.cameras[1];
    EXPECT_EQ(ortho.name, "TopNode");  // the camera has no name: its node's
    EXPECT_TRUE(ortho.orthographic);
    EXPECT_FLOAT_EQ(ortho.xmag, 2.0f);
    EXPECT_FLOAT_EQ(ortho.ymag, 1.0f);  // a negative magnification reads as its size
    EXPECT_FLOAT_EQ(ortho.znear, 0.01f);
    EXPECT_FLOAT_EQ(*ortho.zfar, 20.0f);
    expect_near(ortho.placement.position, {0, 0, 10});
    expect_near(ortho.placement.forward, {0, 0, -1});  // the node's scale is ignored
    expect_near(ortho.placement.up, {0, 1, 0});

    const FileCamera& plain_camera = m.cameras[2];
    EXPECT_EQ(plain_camera.name, "camera 2");  // neither named: the glTF index
    EXPECT_FALSE(plain_camera.aspect_ratio);
    EXPECT_FALSE(plain_camera.zfar);  // infinite
}

TEST(GltfCameras, BadCameraIsAWarningAndLeftOut) {
    TempDir dir;
    GltfBuilder g = with_triangle();
    g.doc["cameras"] = {
        {{"type", "perspective"}, {"name", "Bad"}, {"perspective", {{"yfov", 0.5}, {"znear", 2}, {"zfar", 1}}}}};
    g.node({{"camera", 0}});
    g.node({{"camera", 4}});
    g.doc["cameras"].push_back({{"type", "orthographic"},
                                {"name", "Far"},
                                {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0}, {"zfar", 1}}}});
    g.node({{"camera", 1}, {"translation", {1e30, 0, 0}}});
    g.scene({0, 1, 2, 3});
    const Mesh m = io::read_gltf(dir.write("bad.glb", g.glb()));
    EXPECT_TRUE(m.cameras.empty());
    EXPECT_EQ(m.triangle_count(), 1u);
    EXPECT_TRUE(has_warning(m, "camera 'Bad' has zfar 1 (must be greater than znear); ignored"));
    EXPECT_TRUE(has_warning(m, "node 2 refers to camera 4 but the file has 2; ignored"));
    EXPECT_TRUE(has_warning(m, "camera 'Far' is placed out of range (beyond 1e15); ignored"));
}

TEST(GltfLights, PunctualLightsAreReadWithTheirNodes) {
    TempDir dir;
    GltfBuilder g = with_triangle();
    g.doc["extensionsUsed"] = {"KHR_lights_punctual"};
    g.doc["extensions"]["KHR_lights_punctual"]["lights"] = {
        {{"type", "directional"}, {"name", "Sun"}, {"color", {1.0, 0.5, 0.25}}, {"intensity", 3}},
        {{"type", "point"}, {"intensity", 100}, {"range", 10}},
        {{"type", "spot"}, {"name", "Spot"}, {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.5}}}}};
    auto light = [](int i) { return json{{"KHR_lights_punctual", {{"light", i}}}}; };
    // The sun points straight down: -z turned about +x by -90 degrees is -y.
    int sun = g.node({{"extensions", light(0)}, {"rotation", quaternion({1, 0, 0}, -90)}});
    int lamp = g.node({{"name", "Lamp"}, {"extensions", light(1)}, {"translation", {0, 4, 0}}});
    int spot = g.node({{"extensions", light(2)}, {"translation", {1, 1, 1}}, {"rotation", quaternion({0, 1, 0}, 90)}});
    g.scene({0, sun, lamp, spot});
    const Mesh m = io::read_gltf(dir.write("lights.gltf", g.gltf_embedded()));
    EXPECT_TRUE(m.warnings.empty()) << m.warnings.front();
    ASSERT_EQ(m.lights.size(), 3u);

    const FileLight& s = m.lights[0];
    EXPECT_EQ(s.name, "Sun");
    EXPECT_EQ(s.type, FileLightType::Directional);
    EXPECT_EQ(s.color, glm::vec3(1.0f, 0.5f, 0.25f));
    EXPECT_FLOAT_EQ(s.intensity, 3.0f);
    EXPECT_FALSE(s.range);
    expect_near(s.placement.forward, {0, -1, 0});

    const FileLight& p = m.lights[1];
    EXPECT_EQ(p.name, "Lamp");  // its node's name
    EXPECT_EQ(p.type, FileLightType::Point);
    EXPECT_EQ(p.color, glm::vec3(1.0f));  // the extension's default
    EXPECT_FLOAT_EQ(p.intensity, 100.0f);
    ASSERT_TRUE(p.range);
    EXPECT_FLOAT_EQ(*p.range, 10.0f);
    expect_near(p.placement.position, {0, 4, 0});

    const FileLight& c = m.lights[2];
    EXPECT_EQ(c.type, FileLightType::Spot);
    EXPECT_FLOAT_EQ(c.intensity, 1.0f);
    EXPECT_FLOAT_EQ(c.inner_cone_angle, 0.2f);
    EXPECT_FLOAT_EQ(c.outer_cone_angle, 0.5f);
    expect_near(c.placement.position, {1, 1, 1});
    expect_near(c.placement.forward, {-1, 0, 0});  // -z turned 90 degrees about +y
}

// An unusable light is listed (for --lights file and info), not warned about: a render that
// does not use the file's lights has no concern with it.
TEST(GltfLights, BadLightIsListedAsUnusableAndLeftOut) {
    TempDir dir;
    GltfBuilder g = with_triangle();
    g.doc["extensions"]["KHR_lights_punctual"]["lights"] = {
        {{"type", "spot"}, {"name", "Wide"}, {"spot", {{"innerConeAngle", 0.6}, {"outerConeAngle", 0.5}}}},
        {{"type", "area"}, {"name", "Panel"}}};
    g.node({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    g.node({{"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
    g.node({{"extensions", {{"KHR_lights_punctual", {{"light", 9}}}}}});
    g.scene({0, 1, 2, 3});
    const Mesh m = io::read_gltf(dir.write("bad.glb", g.glb()));
    EXPECT_TRUE(m.lights.empty());
    EXPECT_EQ(m.unusable_lights,
              (std::vector<std::string>{"light 'Wide' has cone angles 0.6, 0.5 (need 0 <= inner < outer <= pi/2)",
                                        "light 'Panel' has type 'area' (directional, point or spot)"}));
    EXPECT_FALSE(has_warning(m, "light 'Wide'"));
    EXPECT_TRUE(has_warning(m, "node 3 refers to light 9 but the file has 2; ignored"));
}

TEST(GltfMaterials, UnlitExtensionMarksTheMaterial) {
    TempDir dir;
    GltfBuilder g;
    int pos = g.floats({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}, "VEC3", 3);
    int lit = g.material({1, 0, 0, 1});
    int unlit = g.material({0, 1, 0, 1});
    g.doc["materials"][unlit]["extensions"]["KHR_materials_unlit"] = json::object();
    int a = g.mesh({{"POSITION", pos}}, g.data(std::vector<uint16_t>{0, 1, 2}, kUShort, 1, "SCALAR"), lit);
    int b = g.mesh({{"POSITION", pos}}, g.data(std::vector<uint16_t>{1, 3, 2}, kUShort, 1, "SCALAR"), unlit);
    g.scene({g.node({{"mesh", a}}), g.node({{"mesh", b}})});
    const Mesh m = io::read_gltf(dir.write("unlit.glb", g.glb()));
    ASSERT_EQ(m.materials.size(), 2u);
    EXPECT_FALSE(m.materials[0].unlit);
    EXPECT_TRUE(m.materials[1].unlit);
    EXPECT_EQ(m.materials[1].diffuse, glm::vec3(0, 1, 0));
}

}  // namespace
}  // namespace inkshade::test
