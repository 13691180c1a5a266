// A glTF assembly of parts covered by long sliver triangles, as CAD exports tessellate them: a
// round bar whose sides are needles spanning its whole length, and a flat bar of needles
// crossing in front of it, 0.2 in front — much closer than the needles are long, which hid
// nothing under the old rule that ignored occluders within the line's face's longest edge
// (the bar's outline was drawn straight across the flat bar). `inkshade lines` draws no stroke
// across the flat bar's faces, in the default (contour, suggestive, crease, border) and the
// technical line sets, and the round bar's hidden outline is there at occlusion level 2 (in
// through the flat bar's front, out through its back) when asked for.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/run_cli.hpp"
#include "geometry/analytic_meshes.hpp"
#include "geometry/visibility.hpp"
#include "io/gltf_files.hpp"

namespace inkshade::test {
namespace {

// The flat bar x ∈ [−0.4, 0.4], y ∈ [−0.8, 0.8], z ∈ [0.7, 0.8]: each face a strip of triangles
// spanning the face's whole length along y (needles 1.6 long, 4e-3 wide on the large faces);
// the two small end faces are one quad each.
void add_flat_bar(std::vector<float>& p, std::vector<uint32_t>& idx) {
    constexpr int kStrips = 200;
    const glm::vec3 lo(-0.4f, -0.8f, 0.7f), hi(0.4f, 0.8f, 0.8f);
    // Face: origin, u (along the needles), v (across them), `strips` of them; outward u × v.
    auto face = [&](glm::vec3 o, glm::vec3 u, glm::vec3 v, int strips) {
        const uint32_t base = uint32_t(p.size() / 3);
        for (int j = 0; j <= strips; ++j)
            for (int i = 0; i < 2; ++i) {
                const glm::vec3 q = o + float(i) * u + (float(j) / float(strips)) * v;
                p.insert(p.end(), {q.x, q.y, q.z});
            }
        for (uint32_t j = 0; j < uint32_t(strips); ++j) {
            const uint32_t a = base + 2 * j, b = a + 1, c = a + 3, d = a + 2;
            idx.insert(idx.end(), {a, b, c, a, c, d});
        }
    };
    const glm::vec3 dx(hi.x - lo.x, 0, 0), dy(0, hi.y - lo.y, 0), dz(0, 0, hi.z - lo.z);
    face({hi.x, lo.y, hi.z}, dy, -dx, kStrips);  // front (+z): y × −x = +z
    face({lo.x, lo.y, lo.z}, dy, dx, kStrips);   // back (−z): y × x = −z
    face({hi.x, lo.y, lo.z}, dy, dz, kStrips);   // right (+x): y × z = +x
    face({lo.x, lo.y, hi.z}, dy, -dz, kStrips);  // left (−x): y × −z = −x
    face({lo.x, hi.y, lo.z}, dz, dx, 1);         // top (+y): z × x = +y
    face({lo.x, lo.y, lo.z}, dx, dz, 1);         // bottom (−y): x × z = −y
}

// Two parts, two nodes: the flat bar in front of a round bar (radius 0.5 around the x axis,
// x ∈ [−1.5, 1.5], open ends, 256 needles around, with normals).
std::string assembly_glb() {
    GltfBuilder g;
    std::vector<float> bar_p;
    std::vector<uint32_t> bar_i;
    add_flat_bar(bar_p, bar_i);
    const Mesh round = cylinder(0.5f, 256, 2, 3.0f);  // around z, z ∈ [0, 3]
    std::vector<float> round_p, round_n;
    for (const glm::vec3& q : round.positions) round_p.insert(round_p.end(), {q.z - 1.5f, q.y, -q.x});  // z → x
    for (const glm::vec3& n : round.normals) round_n.insert(round_n.end(), {n.z, n.y, -n.x});
    std::vector<uint32_t> round_i;
    for (const glm::uvec3& t : round.triangles) round_i.insert(round_i.end(), {t.x, t.y, t.z});
    const int bar = g.mesh({{"POSITION", g.floats(bar_p, "VEC3", 3)}}, g.data(bar_i, kUInt, 1, "SCALAR"));
    const int rod = g.mesh({{"POSITION", g.floats(round_p, "VEC3", 3)}, {"NORMAL", g.floats(round_n, "VEC3", 3)}},
                           g.data(round_i, kUInt, 1, "SCALAR"));
    g.scene({g.node({{"mesh", bar}}), g.node({{"mesh", rod}})});
    return g.glb();
}

constexpr int kSize = 512;
const char* kCamera = " --eye 0.4,0.6,6 --target 0,0,0 --fov 40 --near 1 --far 20 --size 512x512";

// The flat bar's front face in the image, shrunk by `margin` pixels: [x0, x1] × [y0, y1].
struct Box {
    double x0, y0, x1, y1;
    bool inside(double x, double y) const { return x > x0 && x < x1 && y > y0 && y < y1; }
};
Box bar_front(double margin) {
    Camera c;
    c.eye = {0.4f, 0.6f, 6.0f};
    c.target = glm::vec3(0.0f);
    c.fov_degrees = 40.0f;
    c.near_plane = 1.0f;
    c.far_plane = 20.0f;
    const geometry::ImageProjection view(c, kSize, kSize);
    Box b{1e9, 1e9, -1e9, -1e9};
    for (float x : {-0.4f, 0.4f})
        for (float y : {-0.8f, 0.8f}) {
            const glm::dvec3 q = view.project({x, y, 0.8f});
            b.x0 = std::min(b.x0, q.x), b.x1 = std::max(b.x1, q.x);
            b.y0 = std::min(b.y0, q.y), b.y1 = std::max(b.y1, q.y);
        }
    return {b.x0 + margin, b.y0 + margin, b.x1 - margin, b.y1 - margin};
}

TEST(SliverAssembly, NoStrokeAcrossTheSliverFacesAndTheHiddenOutlineHasLevelTwo) {
    TempDir dir;
    const std::string model = dir.file("assembly.glb");
    {
        std::FILE* f = std::fopen(model.c_str(), "wb");
        ASSERT_NE(f, nullptr);
        const std::string bytes = assembly_glb();
        std::fwrite(bytes.data(), 1, bytes.size(), f);
        std::fclose(f);
    }
    const Box inner = bar_front(2.0);
    ASSERT_GT(inner.x1 - inner.x0, 50.0);
    ASSERT_GT(inner.y1 - inner.y0, 150.0);
    for (const std::string set : {"", " --style technical", " --lines contour,crease --hidden"}) {
        const auto r = run_cli("lines " + model + kCamera + set + " -o " + dir.file("a.svg") + " --lines-json " +
                               dir.file("a.json"));
        ASSERT_EQ(r.status, 0) << set << ": " << r.err;
        const nlohmann::json j = nlohmann::json::parse(slurp(dir.file("a.json")));
        double visible_inside = 0.0, visible = 0.0, hidden_inside = 0.0;
        int hidden_level = 0;
        for (const auto& layer : j.at("layers"))
            for (const auto& path : layer.at("paths")) {
                const auto& pts = path.at("points");
                for (size_t i = 0; i + 1 < pts.size(); ++i) {
                    const double x = 0.5 * (pts[i][0].get<double>() + pts[i + 1][0].get<double>());
                    const double y = 0.5 * (pts[i][1].get<double>() + pts[i + 1][1].get<double>());
                    const double len = std::hypot(pts[i + 1][0].get<double>() - pts[i][0].get<double>(),
                                                  pts[i + 1][1].get<double>() - pts[i][1].get<double>());
                    if (path.at("level").get<int>() == 0) {
                        visible += len;
                        if (inner.inside(x, y)) visible_inside += len;
                    } else if (inner.inside(x, y) && layer.at("type") == "contour") {
                        hidden_inside += len;
                        hidden_level = std::max(hidden_level, path.at("level").get<int>());
                    }
                }
            }
        EXPECT_GT(visible, 300.0) << set << ": the round bar's outline (and the flat bar's edges) are drawn";
        EXPECT_EQ(visible_inside, 0.0) << set << ": strokes across the flat bar's front face";
        if (set.find("--hidden") != std::string::npos) {
            EXPECT_GT(hidden_inside, 80.0) << "the round bar's outline behind the flat bar (two lines)";
            EXPECT_EQ(hidden_level, 2) << "in through the flat bar's front face and out through its back";
        }
    }
}

}  // namespace
}  // namespace inkshade::test
