// Normals of a file without normals in the three.js convention (a scene file, a threejs-*
// model, mtoon's threejs convention): weighted by area as three.js's computeVertexNormals
// weights them, seen through threejs-normal (MeshNormalMaterial: 0.5 n + 0.5, unencoded) at the
// pixel over a vertex whose area- and angle-weighted normals differ; Inkshade's angle weighting
// elsewhere.
#include <gtest/gtest.h>

#include <cmath>

#include "inkshade/io.hpp"
#include "inkshade/scene.hpp"
#include "support/temp_dir.hpp"

namespace inkshade {
namespace {

// A fan of five unequal triangles around a raised centre at the origin of x, y (a ring that
// is not planar, else every weighting by area gives the ring's plane), as OBJ text without
// normals.
std::string fan_obj() {
    const float degrees[] = {0, 30, 60, 90, 250}, radii[] = {0.3f, 2.0f, 0.3f, 2.0f, 0.5f};
    const float heights[] = {0.0f, 0.5f, -0.1f, -0.4f, 0.2f};
    std::string obj = "v 0 0 0.4\n";
    for (int i = 0; i < 5; ++i) {
        const float a = glm::radians(degrees[i]);
        obj += "v " + std::to_string(radii[i] * std::cos(a)) + " " + std::to_string(radii[i] * std::sin(a)) + " " +
               std::to_string(heights[i]) + "\n";
    }
    for (int i = 0; i < 5; ++i) obj += "f 1 " + std::to_string(2 + i) + " " + std::to_string(2 + (i + 1) % 5) + "\n";
    return obj;
}

// three.js r187 computeVertexNormals at the centre: the sum of the faces' cross products.
glm::vec3 threejs_centre_normal(const Mesh& m) {
    glm::vec3 sum(0.0f);
    for (const glm::uvec3& t : m.triangles) {
        const glm::vec3 a = m.positions[t.x], b = m.positions[t.y], c = m.positions[t.z];
        sum += glm::cross(c - b, a - b);
    }
    return glm::normalize(sum);
}

int byte(float v) { return int(std::lround(255.0f * std::clamp(v, 0.0f, 1.0f))); }

// The centre pixel of an odd-sized orthographic view straight down on the centre vertex.
glm::ivec3 centre_pixel(const std::string& obj, const std::function<void(SceneRequest&)>& edit) {
    SceneRequest r;
    r.model = obj;
    r.shading = "threejs-normal";
    r.size = {65, 65};
    r.samples = 1;
    r.smooth_angle = 180.0f;  // one normal at the centre, as three.js computes it
    r.camera.orthographic = true;
    r.camera.ortho_height = 3.0f;
    r.camera.eye = glm::vec3(0, 0, 5);
    r.camera.target = glm::vec3(0, 0, 0);
    r.camera.up = glm::vec3(0, 1, 0);
    edit(r);
    const Scene scene = make_scene(r);
    const Mesh mesh = load_mesh(scene.model, scene.load_options());
    Renderer renderer;
    renderer.set_mesh(mesh);
    const Camera camera = scene.frame(mesh);
    const Image img = render_scene(renderer, scene, camera, scene.light(mesh.bounds(), camera));
    const uint8_t* p = img.pixel(32, 32);
    return {p[0], p[1], p[2]};
}

TEST(ThreejsNormals, SceneModeWeightsFilesNormalsByAreaAsThreejs) {
    test::TempDir dir;
    const std::string obj = dir.write("fan.obj", fan_obj());
    Mesh plain = load_mesh(obj, LoadOptions{.compute_normals = false});
    const glm::vec3 area = threejs_centre_normal(plain);
    ASSERT_EQ(plain.positions.at(0), glm::vec3(0.0f, 0.0f, 0.4f));
    const glm::vec3 angle = load_mesh(obj).normals.at(0);  // Inkshade's default weighting
    const glm::ivec3 want(byte(0.5f * area.x + 0.5f), byte(0.5f * area.y + 0.5f), byte(0.5f * area.z + 0.5f));
    const glm::ivec3 angle_px(byte(0.5f * angle.x + 0.5f), byte(0.5f * angle.y + 0.5f), byte(0.5f * angle.z + 0.5f));
    ASSERT_GT(std::abs(want.x - angle_px.x) + std::abs(want.y - angle_px.y), 20)
        << "the fan does not tell them apart";

    // A threejs-* model (the view's normal is the world normal: the camera looks down -z).
    const glm::ivec3 threejs = centre_pixel(obj, [](SceneRequest&) {});
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(threejs[c], want[c], 1) << c << " angle-weighted: " << angle_px[c];
    // A scene file's style (style_data) with another model: still the three.js convention.
    SceneRequest probe;
    probe.style_data = load_style("lambert");
    EXPECT_EQ(make_scene(probe).load_options().normal_weighting, NormalWeighting::Area);
    SceneRequest lambert;
    lambert.shading = "lambert";
    EXPECT_EQ(make_scene(lambert).load_options().normal_weighting, NormalWeighting::Angle);
    SceneRequest mtoon_seeds;
    mtoon_seeds.style = "mtoon";  // the preset's seeds convention
    EXPECT_EQ(make_scene(mtoon_seeds).load_options().normal_weighting, NormalWeighting::Angle);
}

}  // namespace
}  // namespace inkshade
