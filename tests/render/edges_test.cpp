// edges (G-buffer + Sobel/Canny): a unit cube seen from a corner shows 9 edges (3 creases
// meeting at the near corner, 6 on the silhouette); each is found at its projected position
// (within 1 px) and no line lies inside the flat faces. Two boxes touching in one plane have
// no depth or normal discontinuity between them: only object ids (connected components, or
// materials) find that edge.
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "render/lines/image_lines_pass.hpp"
#include "render/render_fixture.hpp"

namespace inkshade::test {
namespace {

ShadingSelection flat_green() {
    ShadingSelection s;
    s.model = "lambert";
    s.base_color = glm::vec3(0, 1, 0);
    return s;
}

// Axis-aligned box [lo, hi], 8 shared vertices, outward counter-clockwise faces.
void add_box(Mesh& m, glm::vec3 lo, glm::vec3 hi, uint32_t material = 0) {
    const uint32_t b = uint32_t(m.positions.size());
    for (int i = 0; i < 8; ++i)
        m.positions.push_back({(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z});
    const uint32_t q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& f : q) {
        m.triangles.push_back({b + f[0], b + f[1], b + f[2]});
        m.triangles.push_back({b + f[0], b + f[2], b + f[3]});
        m.face_materials.push_back(material);
        m.face_materials.push_back(material);
    }
}

LineSettings edges(const char* detector = "sobel", bool ids = true) {
    LineSettings l{"edges", {}};
    l.params["color"] = {0, 0, 1};
    l.params["width"] = {2};
    l.params["detector"] = {std::string(detector) == "canny" ? 1.0f : 0.0f};
    l.params["ids"] = {ids ? 1.0f : 0.0f};
    return l;
}

bool is_line(const Image& img, int x, int y) {
    if (x < 0 || y < 0 || x >= img.width || y >= img.height) return false;
    const uint8_t* p = img.pixel(x, y);
    return p[2] > 100 && p[1] < 160;  // blue over green or white
}

// Image position (pixels, y down) of a world point under any camera.
glm::vec2 to_image(const Camera& c, glm::vec3 p, int w, int h) {
    glm::vec4 clip = c.projection(float(w) / float(h)) * c.view() * glm::vec4(p, 1.0f);
    glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {(ndc.x + 1.0f) * 0.5f * float(w), (1.0f - ndc.y) * 0.5f * float(h)};
}

float segment_distance(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
    glm::vec2 ab = b - a;
    float t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
    return glm::length(p - (a + t * ab));
}

struct CubeView {
    Camera camera;
    std::vector<std::pair<glm::vec2, glm::vec2>> edges;  // the 9 visible edges, projected
};

// The unit cube [-0.5, 0.5]^3 from direction (1, 1.3, 1.7) (a generic corner view): visible
// edges are those with at least one adjacent face facing the viewer.
CubeView corner_view() {
    CubeView v;
    v.camera.orthographic = true;
    v.camera.ortho_height = 2.2f;
    v.camera.eye = 5.0f * glm::normalize(glm::vec3(1.0f, 1.3f, 1.7f));
    v.camera.near_plane = 1.0f;
    v.camera.far_plane = 10.0f;
    const glm::vec3 view = glm::normalize(v.camera.eye);
    for (int axis = 0; axis < 3; ++axis)
        for (int s1 = 0; s1 < 2; ++s1)
            for (int s2 = 0; s2 < 2; ++s2) {
                // Edge along `axis`, at signs s1, s2 on the two other axes.
                const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
                glm::vec3 p(0), n1(0), n2(0);
                p[a1] = s1 ? 0.5f : -0.5f;
                p[a2] = s2 ? 0.5f : -0.5f;
                n1[a1] = s1 ? 1.0f : -1.0f;
                n2[a2] = s2 ? 1.0f : -1.0f;
                if (glm::dot(n1, view) <= 0 && glm::dot(n2, view) <= 0) continue;
                glm::vec3 q = p, r = p;
                q[axis] = -0.5f;
                r[axis] = 0.5f;
                v.edges.push_back({to_image(v.camera, q, kSize, kSize), to_image(v.camera, r, kSize, kSize)});
            }
    return v;
}

Image render_mesh(const Mesh& mesh, const Camera& camera, const LineSettings& line) {
    Renderer& r = shared_renderer();
    r.set_mesh(mesh);
    RenderOptions o;
    o.width = o.height = kSize;
    return r.render(camera, ambient_only(), flat_green(), {line}, o);
}

void expect_cube_edges(const char* detector) {
    Mesh cube;
    add_box(cube, glm::vec3(-0.5f), glm::vec3(0.5f));
    const CubeView view = corner_view();
    ASSERT_EQ(view.edges.size(), 9u);
    Image img = render_mesh(cube, view.camera, edges(detector));
    // Every visible edge: a line pixel within 1 px of points along it.
    for (const auto& [a, b] : view.edges)
        for (float t = 0.1f; t <= 0.9f; t += 0.05f) {
            const glm::vec2 p = a + t * (b - a);
            bool found = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const glm::vec2 q(std::floor(p.x) + dx + 0.5f, std::floor(p.y) + dy + 0.5f);
                    if (glm::length(q - p) <= 1.0f + 0.71f && is_line(img, int(q.x), int(q.y))) found = true;
                }
            EXPECT_TRUE(found) << detector << ": no edge near " << p.x << "," << p.y;
        }
    // No line farther than 3 px from every edge (inside the faces, or on the background).
    int lines = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            if (!is_line(img, x, y)) continue;
            ++lines;
            float d = INFINITY;
            for (const auto& [a, b] : view.edges) d = std::min(d, segment_distance({x + 0.5f, y + 0.5f}, a, b));
            EXPECT_LT(d, 3.0f) << detector << ": stray line pixel " << x << "," << y;
        }
    EXPECT_GT(lines, 300) << detector;
}

TEST(Edges, CubeFromCornerSobelFindsNineEdges) { expect_cube_edges("sobel"); }
TEST(Edges, CubeFromCornerCannyFindsNineEdges) { expect_cube_edges("canny"); }

// Two boxes side by side, front faces in the plane z = 0.5, seen head-on: the seam x = 0
// has the same depth and normal on both sides.
int seam_line_pixels(const Mesh& mesh, bool ids) {
    Image img = render_mesh(mesh, ortho_camera(), edges("sobel", ids));
    const Camera cam = ortho_camera();
    int count = 0;
    for (float y = -0.3f; y <= 0.3f; y += 0.02f) {
        const glm::vec2 q = project(cam, {0.0f, y, 0.5f});
        bool found = false;
        for (int dx = -1; dx <= 1; ++dx) found = found || is_line(img, int(q.x) + dx, int(q.y));
        count += found;
    }
    return count;
}

TEST(Edges, TouchingObjectsSeparatedByObjectIds) {
    Mesh components;  // no shared positions: two connected components, one material
    add_box(components, {-0.8f, -0.5f, -0.5f}, {0.0f, 0.5f, 0.5f});
    add_box(components, {0.0f, -0.45f, -0.5f}, {0.8f, 0.55f, 0.5f});
    Mesh materials;  // one connected surface pair sharing positions, two materials
    add_box(materials, {-0.8f, -0.5f, -0.5f}, {0.0f, 0.5f, 0.5f}, 0);
    add_box(materials, {0.0f, -0.5f, -0.5f}, {0.8f, 0.5f, 0.5f}, 1);
    materials.materials = {Material{"a", glm::vec3(1)}, Material{"b", glm::vec3(1)}};
    components.face_materials.clear();
    for (const Mesh* m : {&components, &materials}) {
        EXPECT_GE(seam_line_pixels(*m, true), 30);  // all 31 samples along the seam
        EXPECT_EQ(seam_line_pixels(*m, false), 0);  // depth and normals see nothing there
    }
}

// The image-lines pass shades only the projected bounding box grown by the detectors' reach:
// the rectangle is that box in GL window pixels, the whole image when the box reaches behind
// the eye, and empty when it lies outside the view.
TEST(Edges, ImageLinesRegionIsTheProjectedBoxPlusTheMargin) {
    const Camera cam = ortho_camera();  // 2.5 units high: 102.4 px a unit at 256 px
    const BoundingBox box{{-0.5f, -0.25f, -1.0f}, {0.5f, 0.75f, 1.0f}};
    const glm::ivec4 r = render::ImageLinesPass::image_lines_region(box, cam, kSize, kSize, 3);
    // x in [128 - 51.2, 128 + 51.2] = [76.8, 179.2] px, y (GL, up) in [128 - 25.6, 128 + 76.8];
    // floor/ceil, then 3 px margin and 1 px for rounding on each side.
    const int x0 = 76 - 4, x1 = 180 + 4, y0 = 102 - 4, y1 = 205 + 4;
    EXPECT_EQ(r, glm::ivec4(x0, y0, x1 - x0, y1 - y0));
    Camera inside = cam;
    inside.orthographic = false;
    inside.eye = {0.0f, 0.0f, 0.5f};  // within the box's z range: a corner behind the eye
    EXPECT_EQ(render::ImageLinesPass::image_lines_region(box, inside, kSize, kSize, 3), glm::ivec4(0, 0, kSize, kSize));
    const BoundingBox away{{10.0f, 10.0f, -1.0f}, {11.0f, 11.0f, 1.0f}};
    const glm::ivec4 none = render::ImageLinesPass::image_lines_region(away, cam, kSize, kSize, 3);
    EXPECT_TRUE(none.z == 0 || none.w == 0);
}

}  // namespace
}  // namespace inkshade::test
