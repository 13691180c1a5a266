// `--camera` and `--lights file` on the command line: a glTF camera renders exactly the bytes
// of the same camera given by flags (perspective and orthographic, under a node hierarchy),
// the image takes its aspect without --size, --up-axis leaves it alone, `info` lists cameras
// and lights, and a missing camera or light is exit 2 with one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cli/run_cli.hpp"
#include "inkshade/image.hpp"
#include "inkshade/io.hpp"
#include "io/gltf_files.hpp"

namespace inkshade::test {
namespace {

using nlohmann::json;

json quaternion(glm::vec3 axis, float degrees) {
    const float h = 0.5f * glm::radians(degrees);
    return {axis.x * std::sin(h), axis.y * std::sin(h), axis.z * std::sin(h), std::cos(h)};
}

// Two boxes (one moved and turned by its node) seen by a perspective camera "Persp", which a
// turned, moved parent carries, and an orthographic camera "Side"; with two lights.
std::string scene_glb(bool with_cameras = true, bool with_lights = true) {
    GltfBuilder g;
    std::vector<float> p;
    for (int i = 0; i < 8; ++i) p.insert(p.end(), {i & 1 ? 1.0f : -1.0f, i & 2 ? 1.0f : -1.0f, i & 4 ? 1.0f : -1.0f});
    const std::vector<uint16_t> faces = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                                         2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
    const int box = g.mesh({{"POSITION", g.floats(p, "VEC3", 3)}}, g.data(faces, kUShort, 1, "SCALAR"));
    std::vector<int> roots = {g.node({{"mesh", box}}),
                              g.node({{"mesh", box},
                                      {"translation", {0.5, 1.6, 0.2}},
                                      {"rotation", quaternion(glm::normalize(glm::vec3(1, 1, 0)), 35)},
                                      {"scale", {0.5, 0.5, 0.5}}})};
    if (with_cameras) {
        g.doc["cameras"] = {{{"type", "perspective"},
                             {"name", "Persp"},
                             {"perspective", {{"yfov", 0.7}, {"aspectRatio", 1.5}, {"znear", 0.1}, {"zfar", 50}}}},
                            {{"type", "orthographic"},
                             {"name", "Side"},
                             {"orthographic", {{"xmag", 2.5}, {"ymag", 2}, {"znear", 0.5}, {"zfar", 30}}}}};
        // The parent turns 90 degrees about +y: the child's (0, 3, 6) lands at (6.5, 3, 0),
        // looking along (-cos 30, -sin 30, 0) once it tilts 30 degrees down.
        const int child = g.node({{"camera", 0}, {"translation", {0, 3, 6}}, {"rotation", quaternion({1, 0, 0}, -30)}});
        roots.push_back(
            g.node({{"translation", {0.5, 0, 0}}, {"rotation", quaternion({0, 1, 0}, 90)}, {"children", {child}}}));
        roots.push_back(g.node({{"camera", 1}, {"translation", {0.3, 0.2, 10}}}));
    }
    if (with_lights) {
        g.doc["extensions"]["KHR_lights_punctual"]["lights"] = {
            {{"type", "spot"}, {"name", "Key"}, {"intensity", 40}, {"spot", {{"outerConeAngle", 0.6}}}},
            {{"type", "directional"}, {"name", "Fill"}}};
        roots.push_back(g.node({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}},
                                {"translation", {0, 6, 0}},
                                {"rotation", quaternion({1, 0, 0}, -90)}}));
        roots.push_back(g.node({{"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}}));
    }
    g.scene(roots);
    return g.glb();
}

std::string exact(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", v);  // reads back as the same float
    return buf;
}

std::string exact(glm::vec3 v) { return exact(v.x) + "," + exact(v.y) + "," + exact(v.z); }

// The flags that place the view as the file's camera does: eye, the target on the view axis
// nearest the model's centre (at least a model radius ahead; docs/inputs.md), and up.
std::string placement_flags(const Mesh& mesh, const FileCamera& c) {
    const BoundingBox box = mesh.bounds();
    const NodePlacement& p = c.placement;
    const float radius = std::max(0.5f * box.diagonal(), 1e-6f);
    const float ahead = std::max(glm::dot(box.center() - p.position, p.forward), radius);
    return " --eye " + exact(p.position) + " --target " + exact(p.position + ahead * p.forward) + " --up " +
           exact(p.up);
}

void expect_same_png(const std::string& a, const std::string& b) {
    const std::string x = slurp(a), y = slurp(b);
    ASSERT_FALSE(x.empty());
    EXPECT_TRUE(x == y) << a << " and " << b << " differ";
}

void expect_near(glm::vec3 a, glm::vec3 b) {
    EXPECT_NEAR(a.x, b.x, 1e-5f);
    EXPECT_NEAR(a.y, b.y, 1e-5f);
    EXPECT_NEAR(a.z, b.z, 1e-5f);
}

TEST(GltfSceneCli, PerspectiveCameraRendersTheBytesOfTheSameFlags) {
    TempDir dir;
    const std::string model = dir.write("scene.glb", scene_glb());
    const Mesh mesh = load_mesh(model);
    ASSERT_EQ(mesh.cameras.size(), 2u);
    const FileCamera& c = mesh.cameras[0];
    const float c30 = std::cos(glm::radians(30.0f));
    expect_near(c.placement.position, {6.5f, 3.0f, 0.0f});
    expect_near(c.placement.forward, {-c30, -0.5f, 0.0f});
    expect_near(c.placement.up, {-0.5f, c30, 0.0f});

    const std::string common = " --size 96x64 -o '";
    auto file = run_cli("render '" + model + "' --camera Persp" + common + dir.file("file.png") + "'");
    ASSERT_EQ(file.status, 0) << file.err;
    EXPECT_EQ(file.err, "");
    const std::string flags = placement_flags(mesh, c) + " --fov " + exact(float(0.7 * 180.0 / M_PI)) + " --near " +
                              exact(0.1f) + " --far 50";
    auto given = run_cli("render '" + model + "'" + flags + common + dir.file("flags.png") + "'");
    ASSERT_EQ(given.status, 0) << given.err;
    expect_same_png(dir.file("file.png"), dir.file("flags.png"));

    // By index; and --up-axis turns orbits, not a camera that is in the model's frame already.
    ASSERT_EQ(run_cli("render '" + model + "' --camera 0" + common + dir.file("index.png") + "'").status, 0);
    expect_same_png(dir.file("file.png"), dir.file("index.png"));
    ASSERT_EQ(run_cli("render '" + model + "' --camera Persp --up-axis z" + common + dir.file("z.png") + "'").status,
              0);
    expect_same_png(dir.file("file.png"), dir.file("z.png"));

    // Not a blank picture: the boxes are in view.
    const Image img = read_png(dir.file("file.png"));
    int shaded = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) shaded += img.pixel(x, y)[0] < 250;
    EXPECT_GT(shaded, 300);
}

TEST(GltfSceneCli, OrthographicCameraRendersTheBytesOfTheSameFlags) {
    TempDir dir;
    const std::string model = dir.write("scene.glb", scene_glb());
    const Mesh mesh = load_mesh(model);
    const std::string common = " --size 80x64 -o '";
    auto file = run_cli("render '" + model + "' --camera side" + common + dir.file("file.png") + "'");
    ASSERT_EQ(file.status, 0) << file.err;
    auto given = run_cli("render '" + model + "'" + placement_flags(mesh, mesh.cameras[1]) +
                         " --ortho --ortho-height 4 --near 0.5 --far 30" + common + dir.file("flags.png") + "'");
    ASSERT_EQ(given.status, 0) << given.err;
    expect_same_png(dir.file("file.png"), dir.file("flags.png"));
    ASSERT_EQ(run_cli("render '" + model + "' --camera 1 --up-axis -x" + common + dir.file("x.png") + "'").status, 0);
    expect_same_png(dir.file("file.png"), dir.file("x.png"));
}

TEST(GltfSceneCli, WithoutSizeTheImageTakesTheCamerasAspect) {
    TempDir dir;
    const std::string model = dir.write("scene.glb", scene_glb());
    ASSERT_EQ(run_cli("render '" + model + "' --camera Persp --samples 1 -o '" + dir.file("p.png") + "'").status, 0);
    const Image p = read_png(dir.file("p.png"));
    EXPECT_EQ(p.width, 1024);
    EXPECT_EQ(p.height, 683);  // aspectRatio 1.5
    ASSERT_EQ(run_cli("lines '" + model + "' --camera Side -o '" + dir.file("s.svg") + "'").status, 0);
    EXPECT_NE(slurp(dir.file("s.svg")).find("width=\"1024\" height=\"819\""), std::string::npos);  // 2.5 / 2
}

TEST(GltfSceneCli, MissingCameraOrLightIsExit2WithOneLine) {
    TempDir dir;
    const std::string model = dir.write("scene.glb", scene_glb());
    auto r = run_cli("render '" + model + "' --camera Pers -o '" + dir.file("a.png") + "'");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "inkshade: --camera: " + model +
                         " has no camera 'Pers' (did you mean 'Persp'?); its cameras: 0 'Persp', 1 'Side'\n");
    EXPECT_FALSE(std::ifstream(dir.file("a.png")).good());

    r = run_cli("render '" + model + "' --camera nosuch -o '" + dir.file("a.png") + "'");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "inkshade: --camera: " + model + " has no camera 'nosuch'; its cameras: 0 'Persp', 1 'Side'\n");

    const std::string bare = dir.write("bare.glb", scene_glb(false, false));
    r = run_cli("render '" + bare + "' --camera 0 -o '" + dir.file("a.png") + "'");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "inkshade: --camera: " + bare + " has no cameras\n");
    r = run_cli("lines builtin:sphere --camera 0 -o '" + dir.file("a.svg") + "'");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "inkshade: --camera: builtin:sphere has no cameras\n");
    r = run_cli("render '" + bare + "' --lights file -o '" + dir.file("a.png") + "'");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "inkshade: --lights file: " + bare + " has no lights (glTF KHR_lights_punctual)\n");
    {
        // A spot light whose inner cone exceeds its outer one, the file's only light: one line
        // naming the cone, not a warning and then "has no lights".
        GltfBuilder g;
        const int mesh = g.mesh({{"POSITION", g.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3)}});
        g.doc["extensions"]["KHR_lights_punctual"]["lights"] = {
            {{"type", "spot"}, {"name", "Wide"}, {"spot", {{"innerConeAngle", 0.7}, {"outerConeAngle", 0.5}}}}};
        g.scene({g.node({{"mesh", mesh}}), g.node({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}})});
        const std::string cone = dir.write("cone.glb", g.glb());
        r = run_cli("render '" + cone + "' --lights file -o '" + dir.file("a.png") + "'");
        EXPECT_EQ(r.status, 2);
        EXPECT_EQ(r.err, "inkshade: --lights file: " + cone +
                             ": light 'Wide' has cone angles 0.7, 0.5 (need 0 <= inner < outer <= pi/2)\n");
        r = run_cli("render '" + cone + "' -o '" + dir.file("a.png") + "'");  // its lights unused: no concern
        EXPECT_EQ(r.status, 0) << r.err;
        EXPECT_EQ(r.err, "");
    }
    r = run_cli("render '" + model + "' --camera Persp --fov 20 -o '" + dir.file("a.png") + "'");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "inkshade: --camera and --fov are alternatives: the file's camera places and projects the view\n");
    r = run_cli("render '" + model + "' --lights files -o '" + dir.file("a.png") + "'");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "inkshade: --lights: expected style or file, got 'files'\n");
}

TEST(GltfSceneCli, FileLightReplacesTheKeyLightAndOthersAreNamedOnce) {
    TempDir dir;
    const std::string model = dir.write("scene.glb", scene_glb());
    const std::string common = " --camera Side --size 64x64 --samples 1 --shading threejs-lambert";
    auto style = run_cli("render '" + model + "'" + common + " -o '" + dir.file("style.png") + "'");
    ASSERT_EQ(style.status, 0) << style.err;
    auto file = run_cli("render '" + model + "'" + common + " --lights file -o '" + dir.file("file.png") + "'");
    ASSERT_EQ(file.status, 0) << file.err;
    EXPECT_EQ(file.err,
              "inkshade: warning: " + model + ": 2 lights; Inkshade shades with one, the first: 'Key' (spot)\n");
    EXPECT_NE(slurp(dir.file("style.png")), slurp(dir.file("file.png")));
}

TEST(GltfSceneCli, ViewerStartsAtTheFileCameraWithTheFileLight) {
    TempDir dir;
    const std::string model = dir.write("scene.glb", scene_glb());
    const std::string options = " --camera Side --lights file --shading threejs-lambert --size 160x120";
    auto view =
        run_cli("view '" + model + "'" + options + " --hide-gui --frames 3 --screenshot '" + dir.file("shot.png") + "'",
                "xvfb-run -a -s '-screen 0 640x480x24'");
    ASSERT_EQ(view.status, 0) << view.err;
    EXPECT_NE(view.err.find("2 lights; Inkshade shades with one, the first: 'Key' (spot)"), std::string::npos)
        << view.err;
    ASSERT_EQ(run_cli("render '" + model + "'" + options + " -o '" + dir.file("render.png") + "'").status, 0);
    const Image shot = read_png(dir.file("shot.png")), render = read_png(dir.file("render.png"));
    ASSERT_EQ(shot.width, render.width);
    ASSERT_EQ(shot.height, render.height);
    size_t same = 0;
    for (size_t i = 0; i < shot.rgba.size(); i += 4)
        same += std::abs(int(shot.rgba[i]) - int(render.rgba[i])) <= 2 &&
                std::abs(int(shot.rgba[i + 1]) - int(render.rgba[i + 1])) <= 2 &&
                std::abs(int(shot.rgba[i + 2]) - int(render.rgba[i + 2])) <= 2;
    EXPECT_GE(double(same) / double(shot.rgba.size() / 4), 0.99);
}

TEST(GltfSceneCli, InfoListsCamerasAndLights) {
    TempDir dir;
    const std::string model = dir.write("scene.glb", scene_glb());
    auto r = run_cli("info '" + model + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("cameras:              2\n"
                         "  0 'Persp': perspective, yfov 40.107 deg, aspect 1.5, znear 0.1, zfar 50; at 6.5 3 "),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("  1 'Side': orthographic, xmag 2.5, ymag 2, znear 0.5, zfar 30; at 0.3 0.2 10 looking 0 0 "
                         "-1, up 0 1 0\n"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("lights:               2\n"
                         "  0 'Key': spot, colour 1 1 1, intensity 40 cd, range infinite, at 0 6 0, cone 0..34.3775 "
                         "deg, shining "),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("  1 'Fill': directional, colour 1 1 1, intensity 1 lux, shining 0 0 -1\n"), std::string::npos)
        << r.out;
}

}  // namespace
}  // namespace inkshade::test
