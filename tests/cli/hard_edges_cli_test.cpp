// Auto-smooth on files without normals: a cube written as OFF, STL and OBJ renders with flat,
// uniform faces (hard edges), `anime` draws nothing inside a face, and --smooth-angle 180 brings
// back the averaged normals that shade a cube like a sphere.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>

#include <glm/glm.hpp>

#include "cli/run_cli.hpp"
#include "inkshade/image.hpp"

namespace inkshade::test {
namespace {

constexpr int kSize = 128;
constexpr float kOrthoHeight = 4.0f;
const glm::vec3 kEye(3.0f, 2.5f, 4.0f);  // three faces seen, target the origin, up +y
const char* kCamera = " --ortho --ortho-height 4 --eye 3,2.5,4 --target 0,0,0 --up 0,1,0 --size 128x128 ";

// The cube [-1, 1]³ as the three formats write it without normals.
std::array<glm::vec3, 8> corners() {
    std::array<glm::vec3, 8> p;
    for (int i = 0; i < 8; ++i) p[i] = glm::vec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
    return p;
}
const int kTriangles[12][3] = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                               {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};

std::string cube_off() {
    std::string s = "OFF\n8 12 0\n";
    for (const glm::vec3& p : corners())
        s += std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
    for (const auto& t : kTriangles)
        s += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + "\n";
    return s;
}

std::string cube_obj() {
    std::string s;
    for (const glm::vec3& p : corners())
        s += "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
    for (const auto& t : kTriangles)
        s += "f " + std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " + std::to_string(t[2] + 1) + "\n";
    return s;
}

std::string cube_stl() {  // ASCII STL: a soup, welded on load; the facet normals are ignored
    const auto p = corners();
    std::string s = "solid cube\n";
    for (const auto& t : kTriangles) {
        s += "facet normal 0 0 0\nouter loop\n";
        for (int k : t)
            s +=
                "vertex " + std::to_string(p[k].x) + " " + std::to_string(p[k].y) + " " + std::to_string(p[k].z) + "\n";
        s += "endloop\nendfacet\n";
    }
    return s + "endsolid cube\n";
}

// The cube face (0..5: -x, +x, -y, +y, -z, +z) the orthographic ray through image point (x, y)
// enters, or nothing.
std::optional<int> face_at(float x, float y) {
    const glm::vec3 forward = glm::normalize(-kEye), right = glm::normalize(glm::cross(forward, {0, 1, 0}));
    const glm::vec3 up = glm::cross(right, forward);
    const float half = 0.5f * kOrthoHeight;
    const glm::vec3 o = kEye + right * ((x / kSize * 2.0f - 1.0f) * half) + up * ((1.0f - y / kSize * 2.0f) * half);
    float enter = -1e30f, leave = 1e30f;
    int axis = -1;
    for (int a = 0; a < 3; ++a) {
        const float t0 = (-1.0f - o[a]) / forward[a], t1 = (1.0f - o[a]) / forward[a];
        if (std::min(t0, t1) > enter) enter = std::min(t0, t1), axis = a;
        leave = std::min(leave, std::max(t0, t1));
    }
    if (enter > leave) return std::nullopt;
    return 2 * axis + (forward[axis] < 0.0f ? 1 : 0);
}

// Per face, the largest spread (max − min over one channel) of the pixels at least `margin`
// pixels inside it.
std::map<int, int> spread_per_face(const Image& img, int margin) {
    std::map<int, std::array<int, 6>> range;  // min r, g, b, max r, g, b
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const auto f = face_at(x + 0.5f, y + 0.5f);
            if (!f) continue;
            bool inside = true;
            for (int dy : {-margin, margin})
                for (int dx : {-margin, margin}) inside &= face_at(x + 0.5f + dx, y + 0.5f + dy) == f;
            if (!inside) continue;
            auto [it, fresh] = range.try_emplace(*f, std::array<int, 6>{255, 255, 255, 0, 0, 0});
            for (int c = 0; c < 3; ++c) {
                it->second[c] = std::min(it->second[c], int(img.pixel(x, y)[c]));
                it->second[3 + c] = std::max(it->second[3 + c], int(img.pixel(x, y)[c]));
            }
        }
    std::map<int, int> out;
    for (const auto& [f, r] : range) out[f] = std::max({r[3] - r[0], r[4] - r[1], r[5] - r[2]});
    return out;
}

Image render(const std::string& model, const std::string& options) {
    TempDir dir;
    const auto r = run_cli("render " + model + kCamera + options + " -o " + dir.file("o.png"));
    EXPECT_EQ(r.status, 0) << r.err;
    return r.status == 0 ? read_png(dir.file("o.png")) : Image(kSize, kSize);
}

TEST(HardEdges, CubeWithoutNormalsHasUniformFacesInEveryFormat) {
    TempDir dir;
    const std::string files[] = {dir.write("cube.off", cube_off()), dir.write("cube.obj", cube_obj()),
                                 dir.write("cube.stl", cube_stl())};
    for (const std::string& file : files) {
        for (const char* style : {"lambert", "cel-000"}) {
            const std::map<int, int> spread = spread_per_face(render(file, std::string("--style ") + style), 1);
            ASSERT_EQ(spread.size(), 3u) << file;  // the three faces turned to the eye
            for (const auto& [face, s] : spread) EXPECT_LE(s, 1) << file << " " << style << " face " << face;
        }
        // `anime` (cel shading, rim, outline): nothing drawn inside a face.
        for (const auto& [face, s] : spread_per_face(render(file, "--style anime"), 5))
            EXPECT_LE(s, 1) << file << " anime face " << face;
    }
}

TEST(HardEdges, SmoothAngleOf180AveragesNormalsAcrossTheEdges) {
    TempDir dir;
    const std::string file = dir.write("cube.off", cube_off());
    int largest = 0;
    for (const auto& [face, s] : spread_per_face(render(file, "--style lambert --smooth-angle 180"), 1))
        largest = std::max(largest, s);
    EXPECT_GT(largest, 20);  // today's sphere-like shading: a gradient across every face
    // A style file can ask for it too; the option wins over the style.
    const std::string style = dir.write("smooth.toml", "smooth-angle = 180\n[shading]\nmodel = \"lambert\"\n");
    largest = 0;
    for (const auto& [face, s] : spread_per_face(render(file, "--style " + style), 1)) largest = std::max(largest, s);
    EXPECT_GT(largest, 20);
    for (const auto& [face, s] : spread_per_face(render(file, "--style " + style + " --smooth-angle 30"), 1))
        EXPECT_LE(s, 1) << face;
}

TEST(HardEdges, SmoothAngleOutOfRangeIsAnError) {
    const auto r = run_cli("render builtin:sphere --smooth-angle 200 -o /tmp/never.png");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "inkshade: --smooth-angle: expected degrees in [0, 180], got '200'\n");
}

}  // namespace
}  // namespace inkshade::test
