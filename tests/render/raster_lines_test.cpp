// The raster line passes together: lines of an object behind another are hidden by it;
// rendering twice gives the same bytes; object-space contours become strokes on the outline;
// the old render() is the new one with no lines.
#include <cstring>

#include "geometry/builtin_models.hpp"
#include "render/render_fixture.hpp"

namespace inkshade::test {
namespace {

Mesh translated_sphere(glm::vec3 centre, float radius) {
    Mesh m = builtin::sphere(64, 128);
    for (glm::vec3& p : m.positions) p = centre + radius * p;
    return m;
}

Mesh two_spheres() {
    Mesh m = translated_sphere({0.5f, 0.2f, -2.0f}, 0.8f);       // behind
    Mesh front = translated_sphere({-0.3f, -0.1f, 0.0f}, 0.6f);  // in front, overlapping it
    const uint32_t base = uint32_t(m.positions.size());
    m.positions.insert(m.positions.end(), front.positions.begin(), front.positions.end());
    m.normals.insert(m.normals.end(), front.normals.begin(), front.normals.end());
    for (glm::uvec3 t : front.triangles) m.triangles.push_back(t + glm::uvec3(base));
    return m;
}

std::vector<LineSettings> all_raster_lines() {
    std::vector<LineSettings> lines;
    for (const char* type : {"hull", "rim-contour", "edges", "suggestive-image"}) {
        LineSettings l{type, {}};
        l.params["color"] = {0, 0, 1};
        lines.push_back(l);
    }
    return lines;
}

Image render_lines(const Mesh& mesh, const std::vector<LineSettings>& lines) {
    Renderer& r = shared_renderer();
    r.set_mesh(mesh);
    RenderOptions o;
    o.width = o.height = kSize;
    ShadingSelection s;
    s.model = "lambert";
    s.base_color = glm::vec3(0, 1, 0);
    return r.render(ortho_camera(), directional_light(glm::vec3(0, 0, 1), glm::vec3(0), glm::vec3(1)), s, lines, o);
}

bool blue(const uint8_t* p) { return p[2] > 100 && p[1] < 160; }

TEST(RasterLines, BackObjectLinesHiddenBehindFrontObject) {
    Image img = render_lines(two_spheres(), all_raster_lines());
    const Camera cam = ortho_camera();
    const glm::vec2 front = project(cam, {-0.3f, -0.1f, 0.0f}), back = project(cam, {0.5f, 0.2f, -2.0f});
    const float px = float(kSize) / cam.ortho_height, front_r = 0.6f * px, back_r = 0.8f * px;
    int inside = 0, back_outline = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const glm::vec2 q(x + 0.5f, y + 0.5f);
            const float df = glm::length(q - front), db = glm::length(q - back);
            // Inside the front disc away from its own rim (n.v > 0.6): no line, although the
            // back sphere's outline passes behind.
            if (df < 0.8f * front_r) {
                EXPECT_FALSE(blue(img.pixel(x, y))) << "line inside the front object at " << x << "," << y;
                ++inside;
            }
            // The back sphere's outline where the front one does not cover it: drawn.
            if (std::abs(db - back_r) < 1.0f && df > front_r + 6.0f) back_outline += blue(img.pixel(x, y));
        }
    EXPECT_GT(inside, 1000);
    EXPECT_GT(back_outline, 100);
}

TEST(RasterLines, RenderingTwiceGivesIdenticalBytes) {
    const Mesh mesh = builtin::teapot(8);
    Image a = render_lines(mesh, all_raster_lines());
    Image b = render_lines(mesh, all_raster_lines());
    ASSERT_EQ(a.rgba.size(), b.rgba.size());
    EXPECT_EQ(std::memcmp(a.rgba.data(), b.rgba.data(), a.rgba.size()), 0);
}

TEST(RasterLines, NoLinesEqualsThePlainRender) {
    Renderer& r = shared_renderer();
    r.set_mesh(fine_sphere());
    RenderOptions o;
    o.width = o.height = 64;
    ShadingSelection s;
    Light light;
    Image a = r.render(ortho_camera(), light, s, o);
    Image b = r.render(ortho_camera(), light, s, std::vector<LineSettings>{}, o);
    EXPECT_EQ(a.rgba, b.rgba);
}

// Object-space contours are drawn as strokes: on the unit sphere seen orthographically the
// stroke (width 2 px) is centred on the analytic outline circle, and nothing else is drawn.
TEST(RasterLines, ObjectSpaceContourStrokeLiesOnTheOutline) {
    LineSettings contour{"contour", {}};
    contour.params["color"] = {0, 0, 1};
    contour.params["width"] = {2};
    Image img = render_lines(fine_sphere(), {contour});
    const Camera cam = ortho_camera();
    const glm::vec2 centre = project(cam, glm::vec3(0.0f));
    const float radius = float(kSize) / cam.ortho_height;  // the unit sphere's outline in pixels
    int stroke = 0, off = 0, ring_samples = 0, ring_hits = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const float d = glm::length(glm::vec2(x + 0.5f, y + 0.5f) - centre) - radius;
            const bool is_blue = blue(img.pixel(x, y));
            stroke += is_blue;
            if (is_blue && std::abs(d) > 1.0f + 1.0f) ++off;  // half width + 1 px
            if (std::abs(d) < 0.5f) ++ring_samples, ring_hits += is_blue;
        }
    EXPECT_GT(stroke, int(2.0f * 3.14159f * radius));  // about 2 px wide all round
    EXPECT_EQ(off, 0);
    EXPECT_GE(ring_hits, int(0.98f * ring_samples));
}

// MeshUse::OneFrame extracts object-space lines before the GL upload and frees their data:
// the same image as ManyFrames, per-vertex colours still shown, and later frames still drawn
// (with lines and with the kr view, which reads the freed curvature).
TEST(RasterLines, OneFrameUseGivesTheSameImagesAsManyFrames) {
    Mesh mesh = two_spheres();
    mesh.colors.assign(mesh.positions.size(), glm::vec3(1.0f, 0.5f, 0.25f));
    std::vector<LineSettings> lines = all_raster_lines();
    for (const char* type : {"contour", "suggestive", "crease"}) lines.push_back({type, {}});
    RenderOptions o;
    o.width = o.height = kSize;
    const Light light = directional_light(glm::vec3(0, 0, 1), glm::vec3(0), glm::vec3(1));
    const ShadingSelection lambert{}, kr{"kr", {}};
    Renderer& r = shared_renderer();
    auto frames = [&](MeshUse use) {
        r.set_mesh(mesh, use);
        std::vector<Image> images;
        images.push_back(r.render(ortho_camera(), light, lambert, lines, o));
        images.push_back(r.render(ortho_camera(), light, lambert, lines, o));
        images.push_back(r.render(ortho_camera(), light, kr, o));
        r.set_mesh(mesh, use);  // kr first: curvature computed before the upload
        images.push_back(r.render(ortho_camera(), light, kr, o));
        return images;
    };
    const std::vector<Image> many = frames(MeshUse::ManyFrames), one = frames(MeshUse::OneFrame);
    for (size_t i = 0; i < many.size(); ++i) EXPECT_EQ(one[i].rgba, many[i].rgba) << "frame " << i;
    EXPECT_EQ(many[0].rgba, many[1].rgba);
    EXPECT_EQ(many[2].rgba, many[3].rgba);
    // The colours reached the image: orange-ish lambert at the front sphere's centre.
    const glm::vec2 c = project(ortho_camera(), {-0.3f, -0.1f, 0.6f});
    const uint8_t* p = one[0].pixel(int(c.x), int(c.y));
    EXPECT_GT(p[0], 200);
    EXPECT_NEAR(p[1], p[0] / 2, 8);
}

}  // namespace
}  // namespace inkshade::test
