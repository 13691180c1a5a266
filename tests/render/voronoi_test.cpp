// voronoi (Worley 1996): F1 and cell colours against a CPU twin of the shader's hash
// and cell search at sampled sphere pixels, edges and isolines where F2 - F1 and F1 say, and
// the pattern on meshes loaded from OBJ and binary STL files, far from the origin and at very
// different sizes: the same cells as the CPU reference, several distinct colours, no black holes.
#include <algorithm>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include "geometry/builtin_models.hpp"
#include "inkshade/io.hpp"
#include "render/cell_hash.hpp"
#include "render/render_fixture.hpp"
#include "support/temp_dir.hpp"

namespace inkshade::test {
namespace {

struct Scene : PixelScene {
    Camera camera = ortho_camera();
};

// Defaults of the test: cells mode, pure cell colours, no edges, unlit.
Scene voronoi_scene(int mode = 0) {
    Scene s;
    s.light = directional_light(glm::vec3(1.0f, 1.0f, 2.0f), glm::vec3(0.9f), glm::vec3(0.1f));
    s.shading.model = "voronoi";
    s.shading.base_color = glm::vec3(0.9f, 0.8f, 0.6f);
    s.shading.params["mode"] = {float(mode)};
    s.shading.params["scale"] = {8.0f};
    s.shading.params["color-mix"] = {1.0f};
    s.shading.params["edge-width"] = {0.0f};
    s.shading.params["lit"] = {0.0f};
    s.options.width = s.options.height = kSize;
    s.options.background = glm::vec4(0, 0, 0, 1);
    return s;
}

// The mesh is the unit sphere scaled by `size` about the origin and moved to `centre`; the
// camera is ortho_camera() scaled and moved with it, so pixels see the same unit-sphere points.
struct Placement {
    glm::vec3 centre{0.0f};
    float size = 1.0f;
    Camera camera() const {
        Camera c = ortho_camera();
        c.eye = centre + size * c.eye;
        c.target = centre;
        c.ortho_height *= size;
        c.near_plane *= size;
        c.far_plane *= size;
        return c;
    }
};

Image render(const Mesh& mesh, const Scene& s, const Placement& where = {}) {
    Renderer& r = shared_renderer();
    r.set_mesh(mesh);
    return r.render(where.camera(), s.light, s.shading, s.options);
}

// Worley features at the surface point under pixel (x, y), as the shader computes them from
// the model-space position normalised by the mesh's bounding box.
struct PixelFeatures {
    glm::vec3 n;  // unit-sphere normal (= point)
    Worley w;
};
std::optional<PixelFeatures> features_at(const Mesh& mesh, const Placement& where, float scale, float x, float y,
                                         float radius = 1.0f) {
    auto n = sphere_normal(ray_origin(ortho_camera(), x, y), radius);
    if (!n) return std::nullopt;
    if (radius != 1.0f) n = sphere_normal(ray_origin(ortho_camera(), x, y));
    const BoundingBox b = mesh.bounds();
    glm::vec3 extent = b.max - b.min;
    glm::vec3 p = where.centre + where.size * *n;
    glm::vec3 q = (p - b.min) / std::max({extent.x, extent.y, extent.z});
    return PixelFeatures{*n, worley(q * scale)};
}

// Calls check(x, y, features) at a 24x24 grid of pixels with n.v > 0.2; returns the count.
int for_sampled_pixels(const Mesh& mesh, const Placement& where, float scale,
                       const std::function<bool(int, int, const PixelFeatures&)>& check) {
    int compared = 0;
    for (int gy = 0; gy < 24; ++gy)
        for (int gx = 0; gx < 24; ++gx) {
            int px = 8 + gx * 10, py = 8 + gy * 10;
            auto f = features_at(mesh, where, scale, px + 0.5f, py + 0.5f);
            if (!f || f->n.z < 0.2f) continue;
            if (check(px, py, *f)) ++compared;
        }
    return compared;
}

bool expect_pixel(const Image& img, int x, int y, const glm::vec3& want, int tolerance = 2) {
    const uint8_t* got = img.pixel(x, y);
    bool ok = true;
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(int(got[c]), to_byte(want[c]), tolerance) << "pixel (" << x << "," << y << ") channel " << c;
        ok = ok && std::abs(int(got[c]) - to_byte(want[c])) <= tolerance;
    }
    return ok;
}

glm::vec3 lighting(const Scene& s, const glm::vec3& n) {
    glm::vec3 l = glm::normalize(s.light.position - s.light.target);
    return s.light.color * std::max(glm::dot(n, l), 0.0f) + s.light.ambient;
}

// Cell colours of pixels away from cell borders (F2 - F1 > 0.1) match the hashed colour of
// the CPU's F1 cell; returns how many matched.
int expect_cells_match_reference(const Image& img, const Mesh& mesh, const Placement& where, const Scene& s, bool lit) {
    return for_sampled_pixels(mesh, where, 8.0f, [&](int x, int y, const PixelFeatures& f) {
        if (f.w.f2 - f.w.f1 < 0.1f) return false;
        glm::vec3 want = voronoi_cell_color(f.w.id);
        if (lit) want *= lighting(s, f.n);
        return expect_pixel(img, x, y, want);
    });
}

// Colours covering at least `min_pixels` pixels of the disc of radius 0.97.
int distinct_colours(const Image& img, int min_pixels) {
    std::map<uint32_t, int> counts;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            if (!sphere_normal(ray_origin(ortho_camera(), x + 0.5f, y + 0.5f), 0.97f)) continue;
            const uint8_t* p = img.pixel(x, y);
            ++counts[uint32_t(p[0]) << 16 | uint32_t(p[1]) << 8 | p[2]];
        }
    int n = 0;
    for (auto& [colour, count] : counts) n += count >= min_pixels;
    return n;
}

// Files: OBJ with positions and faces only (normals computed by the loader), binary STL soup
// (welded by the loader).
std::string obj_text(const Mesh& m) {
    std::ostringstream s;
    s.precision(9);
    s << "# voronoi test sphere\no sphere\n";
    for (const glm::vec3& p : m.positions) s << "v " << p.x << " " << p.y << " " << p.z << "\n";
    for (const glm::uvec3& t : m.triangles) s << "f " << t.x + 1 << " " << t.y + 1 << " " << t.z + 1 << "\n";
    return s.str();
}

std::string binary_stl_bytes(const Mesh& m) {
    std::string s(80, ' ');
    auto put = [&](auto v) {
        char b[sizeof(v)];
        std::memcpy(b, &v, sizeof(v));
        s.append(b, sizeof(v));
    };
    put(uint32_t(m.triangles.size()));
    for (const glm::uvec3& t : m.triangles) {
        glm::vec3 a = m.positions[t.x], b = m.positions[t.y], c = m.positions[t.z];
        glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
        for (glm::vec3 v : {n, a, b, c}) put(v.x), put(v.y), put(v.z);
        put(uint16_t(0));
    }
    return s;
}

Mesh placed_sphere(const Placement& where, int rings = 64, int segments = 128) {
    Mesh m = builtin::sphere(rings, segments);
    for (glm::vec3& p : m.positions) p = where.centre + where.size * p;
    m.normals.clear();
    return m;
}

class Voronoi : public ::testing::Test {};

TEST_F(Voronoi, DistanceModeIsWorleyF1AtSampledPixels) {
    Scene s = voronoi_scene(1);
    Image img = render(fine_sphere(), s);
    int compared = for_sampled_pixels(fine_sphere(), {}, 8.0f, [&](int x, int y, const PixelFeatures& f) {
        return expect_pixel(img, x, y, glm::vec3(f.w.f1));
    });
    EXPECT_GE(compared, 50);
}

TEST_F(Voronoi, CellsModeShowsHashedCellColours) {
    Scene s = voronoi_scene(0);
    EXPECT_GE(expect_cells_match_reference(render(fine_sphere(), s), fine_sphere(), {}, s, false), 50);
    s.shading.params["lit"] = {1.0f};
    EXPECT_GE(expect_cells_match_reference(render(fine_sphere(), s), fine_sphere(), {}, s, true), 50);
    // color-mix 0 is the base colour C everywhere.
    s.shading.params["lit"] = {0.0f};
    s.shading.params["color-mix"] = {0.0f};
    Image plain = render(fine_sphere(), s);
    EXPECT_GE(for_sampled_pixels(
                  fine_sphere(), {}, 8.0f,
                  [&](int x, int y, const PixelFeatures&) { return expect_pixel(plain, x, y, s.shading.base_color); }),
              50);
}

TEST_F(Voronoi, EdgesWhereF2MinusF1IsBelowTheWidth) {
    Scene s = voronoi_scene(0);
    s.shading.params["edge-width"] = {0.12f};
    s.shading.params["edge-color"] = {1.0f, 0.0f, 1.0f};
    Image img = render(fine_sphere(), s);
    int on_edge = 0, inside = 0;
    for_sampled_pixels(fine_sphere(), {}, 8.0f, [&](int x, int y, const PixelFeatures& f) {
        float e = f.w.f2 - f.w.f1;
        // Edges are anti-aliased over fwidth(F2 - F1), which grows towards the limb (a pixel
        // at n.v = 0.25 spans ~0.3 cell units there): check pure colours away from it.
        if (f.n.z < 0.5f) return false;
        if (e < 0.06f) on_edge += expect_pixel(img, x, y, glm::vec3(1, 0, 1));
        if (e > 0.2f) inside += expect_pixel(img, x, y, voronoi_cell_color(f.w.id));
        return true;
    });
    EXPECT_GE(on_edge, 10);
    EXPECT_GE(inside, 50);
}

TEST_F(Voronoi, IsolinesAtMultiplesOfTheSpacing) {
    Scene s = voronoi_scene(2);
    s.shading.params["isoline-spacing"] = {0.25f};
    Image img = render(fine_sphere(), s);
    int on_line = 0, between = 0;
    for_sampled_pixels(fine_sphere(), {}, 8.0f, [&](int x, int y, const PixelFeatures& f) {
        float t = f.w.f1 / 0.25f, d = std::abs(t - std::round(t));
        if (d < 0.02f) {
            EXPECT_LT(img.pixel(x, y)[1], 100) << "isoline pixel (" << x << "," << y << ")";
            ++on_line;
        }
        // Lines are about a pixel wide: away from the limb (little foreshortening) a pixel
        // 0.4 spacings from the nearest line is clear of it.
        if (d > 0.4f && f.n.z > 0.7f) between += expect_pixel(img, x, y, s.shading.base_color);
        return true;
    });
    EXPECT_GE(on_line, 3);
    EXPECT_GE(between, 30);
}

// The mesh is written to disk, moved far from the origin and scaled, and loaded back: the
// pattern must be the one of the bounding-box-normalised position, whatever the size.
void expect_pattern_on_loaded_mesh(const Mesh& loaded, const Placement& where, const char* what) {
    SCOPED_TRACE(what);
    Scene s = voronoi_scene(0);
    Image flat = render(loaded, s, where);
    EXPECT_GE(expect_cells_match_reference(flat, loaded, where, s, false), 50);
    EXPECT_GE(distinct_colours(flat, 20), 5);

    s.shading.params["lit"] = {1.0f};
    Image lit = render(loaded, s, where);
    // No holes or NaN pixels: nothing pure black on the lit side, and the image varies.
    int lit_side = 0, black = 0;
    double sum = 0, sum2 = 0;
    glm::vec3 l = glm::normalize(s.light.position - s.light.target);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            auto n = sphere_normal(ray_origin(ortho_camera(), x + 0.5f, y + 0.5f), 0.97f);
            if (!n || glm::dot(*n, l) < 0.1f) continue;
            const uint8_t* p = lit.pixel(x, y);
            ++lit_side;
            black += p[0] == 0 && p[1] == 0 && p[2] == 0;
            double g = p[1];
            sum += g, sum2 += g * g;
        }
    ASSERT_GT(lit_side, 1000);
    EXPECT_EQ(black, 0);
    double mean = sum / lit_side, sd = std::sqrt(std::max(0.0, sum2 / lit_side - mean * mean));
    EXPECT_GT(sd, 20.0) << "lit side nearly uniform";
    EXPECT_GE(distinct_colours(lit, 1), 200);
}

TEST_F(Voronoi, WorksOnObjLoadedFromDisk) {
    TempDir dir;
    const Placement where{{120.0f, -35.0f, 8.0f}, 40.0f};
    std::string path = dir.write("sphere.obj", obj_text(placed_sphere(where)));
    Mesh loaded = load_mesh(path);
    ASSERT_GT(loaded.triangle_count(), 1000u);
    expect_pattern_on_loaded_mesh(loaded, where, "OBJ, size 40 at (120,-35,8)");
}

TEST_F(Voronoi, WorksOnBinaryStlLoadedFromDisk) {
    TempDir dir;
    const Placement where{{-0.3f, 0.02f, 0.5f}, 0.01f};
    std::string path = dir.write("sphere.stl", binary_stl_bytes(placed_sphere(where)));
    Mesh loaded = load_mesh(path);
    ASSERT_GT(loaded.triangle_count(), 1000u);
    expect_pattern_on_loaded_mesh(loaded, where, "binary STL, size 0.01 at (-0.3,0.02,0.5)");
}

// `scale` cells per longest side: more cells, more distinct colours on the visible half.
TEST_F(Voronoi, ScaleSetsCellsPerLongestSide) {
    Scene s = voronoi_scene(0);
    s.shading.params["scale"] = {3.0f};
    int few = distinct_colours(render(fine_sphere(), s), 20);
    s.shading.params["scale"] = {16.0f};
    int many = distinct_colours(render(fine_sphere(), s), 20);
    EXPECT_GE(few, 3);
    EXPECT_GT(many, 3 * few);
}

}  // namespace
}  // namespace inkshade::test
