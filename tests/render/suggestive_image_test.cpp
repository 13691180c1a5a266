// suggestive-image (image-space suggestive contours on the GPU; DeCarlo et al. 2003): on the height
// field z = A sin(kx) (extruded along y) the radial curvature vanishes on the inflection
// lines x = n pi / k, so D_w(n.v) = 0 there; seen from direction (sin t, 0, cos t) with
// tan t > A k, w points along +x everywhere, D_w D_w(n.v) has the sign of cos(k x_n), and
// suggestive contours lie only on the inflections with cos(k x_n) > 0 (x = 2 m pi / k, slopes
// facing away). Lines appear there (within 2 px) and nowhere else; none on a sphere or a plane.
#include <cmath>

#include "geometry/builtin_models.hpp"
#include "render/render_fixture.hpp"

namespace inkshade::test {
namespace {

constexpr float kK = 7.5f;          // wave number: about 60 px per period in the image
constexpr float kA = 0.5f / kK;     // A k = 0.5 (slopes of 27 degrees)
constexpr float kTilt = 0.610865f;  // 35 degrees: tan = 0.7 > A k; n.v >= 0.47 on every slope

Mesh height_field() {
    Mesh m;
    const int nx = 1200, ny = 8;
    const float x0 = -3.0f, x1 = 3.0f, y0 = -1.6f, y1 = 1.6f;
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) {
            const float x = x0 + (x1 - x0) * float(i) / nx, y = y0 + (y1 - y0) * float(j) / ny;
            m.positions.push_back({x, y, kA * std::sin(kK * x)});
            m.normals.push_back(glm::normalize(glm::vec3(-kA * kK * std::cos(kK * x), 0.0f, 1.0f)));
        }
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const uint32_t a = uint32_t(j * (nx + 1) + i), b = a + 1, c = a + uint32_t(nx + 1), d = c + 1;
            m.triangles.push_back({a, b, d});
            m.triangles.push_back({a, d, c});
        }
    return m;
}

Camera tilted_camera() {
    Camera c = ortho_camera();
    c.eye = 5.0f * glm::vec3(std::sin(kTilt), 0.0f, std::cos(kTilt));
    return c;
}

LineSettings suggestive() {
    LineSettings l{"suggestive-image", {}};
    l.params["color"] = {0, 0, 0};
    l.params["width"] = {2.0f};
    return l;
}

Image render_with_lines(const Mesh& mesh, const Camera& camera) {
    Renderer& r = shared_renderer();
    r.set_mesh(mesh);
    RenderOptions o;
    o.width = o.height = kSize;
    ShadingSelection s;
    s.model = "lambert";
    s.base_color = glm::vec3(1.0f);
    Light light = directional_light(glm::vec3(0, 0, 1), glm::vec3(0), glm::vec3(1));  // white, unlit
    return r.render(camera, light, s, {suggestive()}, o);
}

bool dark(const Image& img, int x, int y) { return img.pixel(x, y)[0] < 128; }

TEST(SuggestiveImage, HeightFieldLinesOnlyOnInflectionsFacingAway) {
    Image img = render_with_lines(height_field(), tilted_camera());
    // Image x of the inflection line x_n (z = 0): its coordinate along the camera's right
    // axis (cos t, 0, -sin t).
    const float half = 0.5f * ortho_camera().ortho_height;
    auto image_x = [&](float x) { return (x * std::cos(kTilt) / half + 1.0f) * 0.5f * float(kSize); };
    std::vector<float> expected, rejected;
    for (int n = -20; n <= 20; ++n) {
        const float px = image_x(float(n) * float(M_PI) / kK);
        if (px < 8.0f || px > float(kSize) - 8.0f) continue;
        (n % 2 == 0 ? expected : rejected).push_back(px);
    }
    ASSERT_GE(expected.size(), 3u);
    ASSERT_GE(rejected.size(), 3u);
    // Each expected line: a dark pixel within 2 px on (almost) every row away from the border.
    for (float px : expected) {
        int rows = 0, found = 0;
        for (int y = 16; y < kSize - 16; ++y, ++rows) {
            bool hit = false;
            for (int x = int(std::floor(px - 2.0f)); x <= int(std::floor(px + 2.0f)); ++x) hit = hit || dark(img, x, y);
            found += hit;
        }
        EXPECT_GE(found, rows * 95 / 100) << "line at x = " << px;
    }
    // Every dark pixel is within 2 px of an expected line (none at the other inflections).
    int dark_pixels = 0;
    for (int y = 16; y < kSize - 16; ++y)
        for (int x = 8; x < kSize - 8; ++x) {
            if (!dark(img, x, y)) continue;
            ++dark_pixels;
            float d = INFINITY;
            for (float px : expected) d = std::min(d, std::abs(float(x) + 0.5f - px));
            EXPECT_LE(d, 2.5f) << "stray suggestive pixel " << x << "," << y;
            if (d > 2.5f) return;
        }
    EXPECT_GT(dark_pixels, 200);
}

TEST(SuggestiveImage, NoneOnSphereOrPlane) {
    Mesh plane;
    plane.positions = {{-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0}};
    plane.normals.assign(4, glm::vec3(0, 0, 1));
    plane.triangles = {{0, 1, 2}, {0, 2, 3}};
    for (const Mesh* m : std::vector<const Mesh*>{&fine_sphere(), &plane})
        for (const Camera& c : {ortho_camera(), tilted_camera()}) {
            Image img = render_with_lines(*m, c);
            int count = 0;
            for (int y = 0; y < kSize; ++y)
                for (int x = 0; x < kSize; ++x) count += dark(img, x, y);
            EXPECT_EQ(count, 0) << (m == &plane ? "plane" : "sphere");
        }
}

}  // namespace
}  // namespace inkshade::test
