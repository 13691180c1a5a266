// The AOVs against analytic answers: depth reprojected onto the unit sphere, normals against the
// sphere's in camera space, ids and materials of two objects, the mask against the disc's area,
// and each line mask against the line the image draws.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>

#include "inkshade/aov.hpp"
#include "inkshade/error.hpp"
#include "inkshade/scene.hpp"
#include "inkshade/style.hpp"
#include "render/render_fixture.hpp"

namespace inkshade {
namespace {

using test::fine_sphere;
using test::shared_renderer;

Camera perspective_camera() {
    Camera c;
    c.eye = {2.0f, 1.5f, 3.5f};
    c.target = {0.1f, -0.05f, 0.0f};  // off centre: the sphere is not on the optical axis
    c.fov_degrees = 40.0f;
    c.near_plane = 1.0f;
    c.far_plane = 10.0f;
    return c;
}

AovImages render_aovs(const Camera& camera, AovSet set, int width, int height, int samples = 4) {
    RenderOptions options;
    options.width = width;
    options.height = height;
    options.samples = samples;
    options.aovs = set;
    AovImages aovs;
    shared_renderer().render(camera, test::ambient_only(), ShadingSelection{}, {}, options, aovs);
    return aovs;
}

AovSet set_of(std::initializer_list<Aov> list) {
    AovSet s;
    for (Aov a : list) s.add(a);
    return s;
}

// Pixel centre (u, v) and depth d to the world, with K as the camera file writes it (pinhole,
// OpenCV axes) and the inverse of the OpenGL view matrix.
glm::vec3 reproject(const Camera& c, int width, int height, float u, float v, float d) {
    const float f = 0.5f * float(height) / std::tan(0.5f * glm::radians(c.fov_degrees));
    const glm::vec3 cv((u - 0.5f * float(width)) * d / f, (v - 0.5f * float(height)) * d / f, d);
    return glm::vec3(glm::inverse(c.view()) * glm::vec4(cv.x, -cv.y, -cv.z, 1.0f));
}

TEST(Aov, DepthReprojectsOntoTheSphere) {
    shared_renderer().set_mesh(fine_sphere());
    const Camera c = perspective_camera();
    const int w = 320, h = 240;
    const AovImages a = render_aovs(c, set_of({Aov::Depth}), w, h);
    ASSERT_EQ(a.depth.size(), size_t(w * h));
    double sum = 0.0, worst = 0.0;
    int n = 0, background = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float d = a.depth[size_t(y * w + x)];
            if (d == 0.0f) {
                ++background;
                continue;
            }
            const double r = glm::length(reproject(c, w, h, float(x) + 0.5f, float(y) + 0.5f, d));
            sum += r;
            worst = std::max(worst, std::abs(r - 1.0));
            ++n;
        }
    ASSERT_GT(n, 5000);
    ASSERT_GT(background, 5000);
    EXPECT_NEAR(sum / n, 1.0, 0.005);  // the acceptance bound; measured: 0.99991
    EXPECT_LT(worst, 0.001);           // measured: 0.00015 (the 128 x 256 polygon inside the sphere)
}

TEST(Aov, NormalsAreTheSpheresInCameraSpace) {
    shared_renderer().set_mesh(fine_sphere());
    const Camera c = perspective_camera();
    const int w = 320, h = 240;
    const AovImages a = render_aovs(c, set_of({Aov::Normal, Aov::Depth}), w, h);
    const glm::mat3 to_camera(c.view());
    const glm::mat4 inverse_view = glm::inverse(c.view());
    const float f = 0.5f * float(h) / std::tan(0.5f * glm::radians(c.fov_degrees));
    double worst = 0.0, sum = 0.0;
    int n = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y * w + x);
            const glm::vec3 got(a.normal[3 * i], a.normal[3 * i + 1], a.normal[3 * i + 2]);
            if (a.depth[i] == 0.0f) {
                EXPECT_EQ(got, glm::vec3(0.0f));
                continue;
            }
            // The pixel's ray against the true sphere (|p| = 1): the analytic normal is p.
            const glm::vec3 dir_camera((float(x) + 0.5f - 0.5f * float(w)) / f, -(float(y) + 0.5f - 0.5f * float(h)) / f,
                                       -1.0f);
            const glm::dvec3 o(c.eye), dir(glm::normalize(glm::vec3(inverse_view * glm::vec4(dir_camera, 0.0f))));
            const double b = glm::dot(o, dir), disc = b * b - (glm::dot(o, o) - 1.0);
            if (disc < 0.02) continue;  // grazing rays: the polygon and the sphere part there
            const glm::dvec3 p = o + (-b - std::sqrt(disc)) * dir;
            const glm::vec3 want = glm::normalize(to_camera * glm::vec3(p));
            const double angle = glm::degrees(std::acos(std::min(1.0f, glm::dot(glm::normalize(got), want))));
            EXPECT_NEAR(glm::length(got), 1.0f, 1e-4f);
            worst = std::max(worst, angle);
            sum += angle;
            ++n;
        }
    ASSERT_GT(n, 5000);
    EXPECT_LT(worst, 0.2);  // degrees; measured: 0.06
    EXPECT_LT(sum / n, 0.01);  // measured: 0.002
}

// Two spheres apart: the left of one material, the right of two (upper and lower half).
Mesh two_spheres() {
    Mesh a = builtin::sphere(32, 64), b = a;
    Mesh m;
    for (glm::vec3 p : a.positions) m.positions.push_back(p + glm::vec3(-1.3f, 0, 0));
    for (glm::vec3 p : b.positions) m.positions.push_back(p + glm::vec3(1.3f, 0, 0));
    const uint32_t offset = uint32_t(a.positions.size());
    m.normals = a.normals;
    m.normals.insert(m.normals.end(), b.normals.begin(), b.normals.end());
    m.materials = {Material{.name = "left"}, Material{.name = "top"}, Material{.name = "bottom"}};
    for (const glm::uvec3& t : a.triangles) {
        m.triangles.push_back(t);
        m.face_materials.push_back(0);
    }
    for (const glm::uvec3& t : b.triangles) {
        m.triangles.push_back(t + offset);
        const float y = (b.positions[t.x].y + b.positions[t.y].y + b.positions[t.z].y) / 3.0f;
        m.face_materials.push_back(y > 0.0f ? 1 : 2);
    }
    return m;
}

TEST(Aov, IdsNumberObjectsAndMaterials) {
    shared_renderer().set_mesh(two_spheres());
    Camera c = test::ortho_camera();
    c.ortho_height = 3.0f;
    const int w = 300, h = 150;  // 50 pixels a world unit
    const AovImages a = render_aovs(c, set_of({Aov::Id, Aov::Material}), w, h);
    auto at = [&](const std::vector<uint32_t>& v, float wx, float wy) {
        const int x = int(std::floor(150.0f + wx * 50.0f)), y = int(std::floor(75.0f - wy * 50.0f));
        return v[size_t(y * w + x)];
    };
    EXPECT_EQ(at(a.id, -1.3f, 0.5f), 1u);  // the left sphere comes first in the faces
    EXPECT_EQ(at(a.id, 1.3f, 0.5f), 2u);
    EXPECT_EQ(at(a.id, 1.3f, -0.5f), 2u);  // one object whatever its materials
    EXPECT_EQ(at(a.id, 0.0f, 0.0f), 0u);   // background between them
    EXPECT_EQ(at(a.material, -1.3f, 0.5f), 1u);
    EXPECT_EQ(at(a.material, 1.3f, 0.5f), 2u);
    EXPECT_EQ(at(a.material, 1.3f, -0.5f), 3u);
    EXPECT_EQ(at(a.material, 0.0f, 0.0f), 0u);
    EXPECT_EQ(at(a.material, 0.0f, 1.4f), 0u);
}

TEST(Aov, MaskIsTheCoverageOfTheDisc) {
    shared_renderer().set_mesh(fine_sphere());
    const Camera c = test::ortho_camera();  // 2.5 units high
    const int size = 256;
    const AovImages a = render_aovs(c, set_of({Aov::Mask}), size, size, 4);
    const double r = double(size) / 2.5;  // the unit sphere's radius in pixels
    double covered = 0.0;
    int partial = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const uint8_t m = a.mask[size_t(y * size + x)];
            covered += m / 255.0;
            const double d = std::hypot(x + 0.5 - size / 2.0, y + 0.5 - size / 2.0);
            if (d < r - 1.0) {
                EXPECT_EQ(m, 255) << x << "," << y;
            }
            if (d > r + 1.0) {
                EXPECT_EQ(m, 0) << x << "," << y;
            }
            partial += m > 0 && m < 255;
        }
    // Antialiased: the edge pixels hold fractions, and they add up to the disc's area.
    EXPECT_GT(partial, 200);
    EXPECT_NEAR(covered / (std::numbers::pi * r * r), 1.0, 0.001);  // measured: 1.00007
}

// Each line mask is the coverage of its line: over a white surface and background (ambient 1,
// no key light) a black line gives exactly 255 - mask wherever it is drawn.
TEST(Aov, LineMasksAreTheDrawnLines) {
    Mesh mesh = builtin::sphere(64, 128);
    shared_renderer().set_mesh(mesh);
    for (const std::string type : {"hull", "contour", "rim-contour"}) {
        SCOPED_TRACE(type);
        SceneRequest r;
        r.model = "builtin:sphere";
        r.shading = "lambert";
        r.size = {200, 160};
        r.light_color = glm::vec3(0.0f);
        r.ambient = glm::vec3(1.0f);
        r.base_color = glm::vec3(1.0f);
        r.background = glm::vec4(1.0f);
        r.added_lines = {type};
        r.sets = {type + ".color=0,0,0"};
        r.aovs = {"lines", "mask"};
        const Scene scene = make_scene(r);
        const Camera camera = scene.frame(mesh);
        AovImages aovs;
        const Image image = render_scene(shared_renderer(), scene, camera, scene.light(mesh.bounds(), camera), aovs);
        ASSERT_EQ(aovs.lines.size(), 1u);
        EXPECT_EQ(aovs.lines[0].type, type);
        const std::vector<uint8_t>& mask = aovs.lines[0].pixels;
        int drawn = 0, worst = 0;
        for (size_t i = 0; i < mask.size(); ++i) {
            worst = std::max(worst, std::abs(int(image.rgba[4 * i]) - (255 - int(mask[i]))));
            drawn += mask[i] > 128;
        }
        EXPECT_GT(drawn, 100);
        EXPECT_LE(worst, 2);
    }
}

// Two spheres side by side, objects "L" (x < 0) and "R", materials "left" and "right".
Mesh two_sphere_objects() {
    Mesh m;
    m.object_names = {"L", "R"};
    m.materials = {Material{.name = "left"}, Material{.name = "right"}};
    for (uint32_t part = 0; part < 2; ++part) {
        const Mesh s = builtin::sphere(32, 64);
        const auto base = uint32_t(m.positions.size());
        for (const glm::vec3& p : s.positions) m.positions.push_back(p + glm::vec3(part == 0 ? -2.5f : 2.5f, 0, 0));
        for (const glm::vec3& n : s.normals) m.normals.push_back(n);
        for (const glm::uvec3& t : s.triangles) {
            m.triangles.push_back(t + glm::uvec3(base));
            m.face_objects.push_back(part);
            m.face_materials.push_back(part);
        }
    }
    return m;
}

// Each line set's mask holds its lines alone: the contours of the sphere it selects (by object,
// by material: the renderer keeps the material names), and nothing on the other sphere
// (Pencil+ 4's line set IDs).
TEST(Aov, LineSetMasksHoldEachSetsLinesAlone) {
    const Mesh mesh = two_sphere_objects();
    shared_renderer().set_mesh(mesh);
    SceneRequest r;
    r.model = "builtin:sphere";
    r.size = {240, 120};
    r.style_data = parse_style(
        "[shading]\nmodel = \"lambert\"\n"
        "[[lineset]]\nname = \"left\"\nobjects = \"L\"\n[[lineset.lines]]\ntype = \"contour\"\nwidth = 2.0\n"
        "[[lineset]]\nname = \"right\"\nmaterials = \"right\"\n[[lineset.lines]]\ntype = \"contour\"\nwidth = 2.0\n",
        "sets.toml");
    r.lineset_ids = true;
    const Scene scene = make_scene(r);
    ASSERT_TRUE(scene.aovs.contains(Aov::LineSets));
    const Camera camera = scene.frame(mesh);
    AovImages aovs;
    render_scene(shared_renderer(), scene, camera, scene.light(mesh.bounds(), camera), aovs);
    ASSERT_EQ(aovs.linesets.size(), 2u);
    EXPECT_EQ(aovs.linesets[0].lineset, "left");
    EXPECT_EQ(aovs.linesets[1].lineset, "right");
    for (size_t set = 0; set < 2; ++set) {
        SCOPED_TRACE(set);
        int drawn = 0, wrong_side = 0;
        const std::vector<uint8_t>& mask = aovs.linesets[set].pixels;
        ASSERT_EQ(mask.size(), size_t(240 * 120));
        for (size_t i = 0; i < mask.size(); ++i) {
            if (mask[i] < 128) continue;
            ++drawn;
            wrong_side += (int(i % 240) < 120) != (set == 0);
        }
        EXPECT_GT(drawn, 150);  // a contour circle of radius ~30 px, 2 px wide
        EXPECT_EQ(wrong_side, 0);
    }
    EXPECT_EQ(aov_file_names("out/a.png", scene.aovs, {}, {"left", "right"}),
              (std::vector<std::string>{"a.lineset-left.png", "a.lineset-right.png", "a.camera.json"}));
}

TEST(Aov, UnknownNameIsRejectedWithTheClosest) {
    SceneRequest r;
    r.aovs = {"depth", "nromal"};
    try {
        make_scene(r);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "--aov: unknown AOV 'nromal' (expected depth, normal, id, material, mask, lines, lineset-ids, "
                  "ndotv, kr, dwkr, k1, k2, pdir1, pdir2, shading-scales, camera) (did you mean 'normal'?)");
    }
    r.aovs = {"Depth", "depth"};
    EXPECT_THROW(make_scene(r), InputError);
    r.aovs = {"DEPTH", "Lines"};
    const Scene s = make_scene(r);
    EXPECT_TRUE(s.aovs.contains(Aov::Depth) && s.aovs.contains(Aov::Lines));
    EXPECT_TRUE(s.options.aovs.contains(Aov::Depth));
    EXPECT_FALSE(s.options.aovs.contains(Aov::Lines));  // the scene's, not the renderer's
}

}  // namespace
}  // namespace inkshade
