// stipple (object-space dots): dots stay on the surface when the camera orbits, their
// number grows as light falls, and their size in pixels does not change with zoom.
// Dots are found as connected components of ink pixels on a sphere whose surface point
// under each pixel is known analytically.
#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry/builtin_models.hpp"
#include "render/render_fixture.hpp"

namespace inkshade::test {
namespace {

using Scene = PixelScene;

Scene stipple_scene(int size) {
    Scene s;
    s.light = directional_light(glm::vec3(1.0f, 1.0f, 2.0f), glm::vec3(0.9f), glm::vec3(0.1f));
    s.shading.model = "stipple";
    s.options.width = s.options.height = size;
    s.options.background = glm::vec4(1, 1, 1, 1);
    return s;
}

glm::vec3 light_dir(const Scene& s) { return glm::normalize(s.light.position - s.light.target); }

// Orthographic camera frame: pixel <-> unit-sphere point for any eye direction.
struct OrthoView {
    Camera camera;
    int size;
    glm::vec3 right, up, back;  // back = towards the viewer
    OrthoView(const Camera& c, int image_size) : camera(c), size(image_size) {
        back = glm::normalize(c.eye - c.target);
        right = glm::normalize(glm::cross(c.up, back));
        up = glm::cross(back, right);
    }
    float pixels_per_unit() const { return float(size) / camera.ortho_height; }
    // Visible point of the unit sphere at the centre of pixel coordinates (x, y), or nullopt.
    std::optional<glm::vec3> sphere_point(glm::vec2 pixel, float radius = 1.0f) const {
        float a = (pixel.x - 0.5f * size) / pixels_per_unit(), b = (0.5f * size - pixel.y) / pixels_per_unit();
        float d2 = a * a + b * b;
        if (d2 >= radius * radius) return std::nullopt;
        return a * right + b * up + std::sqrt(1.0f - d2) * back;
    }
    glm::vec2 project(const glm::vec3& p) const {
        return {0.5f * size + glm::dot(p, right) * pixels_per_unit(),
                0.5f * size - glm::dot(p, up) * pixels_per_unit()};
    }
};

Camera orbit(float degrees, float ortho_height = 2.5f) {
    Camera c = ortho_camera();
    float a = glm::radians(degrees);
    c.eye = 5.0f * glm::vec3(std::sin(a), 0.0f, std::cos(a));
    c.ortho_height = ortho_height;
    return c;
}

Image render(const Mesh& mesh, const Scene& s, const Camera& camera) {
    Renderer& r = shared_renderer();
    r.set_mesh(mesh);
    return r.render(camera, s.light, s.shading, s.options);
}

bool is_ink(const Image& img, int x, int y) { return img.pixel(x, y)[1] < 128; }

struct Dot {
    glm::vec2 centre;  // pixel coordinates (pixel centres at +0.5)
    int area = 0;
    bool touches_border = false;
};

// 8-connected components of ink pixels.
std::vector<Dot> find_dots(const Image& img) {
    const int w = img.width, h = img.height;
    std::vector<int> label(size_t(w) * h, -1);
    std::vector<Dot> dots;
    std::vector<glm::ivec2> stack;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (!is_ink(img, x, y) || label[size_t(y) * w + x] >= 0) continue;
            Dot d;
            glm::vec2 sum(0);
            stack.push_back({x, y});
            label[size_t(y) * w + x] = int(dots.size());
            while (!stack.empty()) {
                glm::ivec2 p = stack.back();
                stack.pop_back();
                sum += glm::vec2(p) + 0.5f;
                ++d.area;
                if (p.x == 0 || p.y == 0 || p.x == w - 1 || p.y == h - 1) d.touches_border = true;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        int qx = p.x + dx, qy = p.y + dy;
                        if (qx < 0 || qy < 0 || qx >= w || qy >= h) continue;
                        size_t i = size_t(qy) * w + qx;
                        if (label[i] >= 0 || !is_ink(img, qx, qy)) continue;
                        label[i] = int(dots.size());
                        stack.push_back({qx, qy});
                    }
            }
            d.centre = sum / float(d.area);
            dots.push_back(d);
        }
    return dots;
}

// Isolated dots (not merged clusters) on the part of the sphere facing the viewer
// (n.v > min_ndotv) whose analytic n.l lies in [lo, hi].
std::vector<Dot> dots_in_tone_band(const std::vector<Dot>& dots, const OrthoView& view, const Scene& s, float min_ndotv,
                                   float lo, float hi, int max_area) {
    std::vector<Dot> out;
    for (const Dot& d : dots) {
        if (d.touches_border || d.area > max_area) continue;
        auto p = view.sphere_point(d.centre);
        if (!p || glm::dot(*p, view.back) < min_ndotv) continue;
        float ndotl = glm::dot(*p, light_dir(s));
        if (ndotl < lo || ndotl > hi) continue;
        out.push_back(d);
    }
    return out;
}

double median_area(std::vector<Dot> dots) {
    if (dots.empty()) return 0.0;
    std::vector<int> a;
    for (const Dot& d : dots) a.push_back(d.area);
    std::nth_element(a.begin(), a.begin() + a.size() / 2, a.end());
    return a[a.size() / 2];
}

class Stipple : public ::testing::Test {};

// Orbit the camera by 1 degree about +y: each dot seen in the first view, lifted to the
// sphere and projected with the second camera, must have a dot within 1 px in the second
// image (screen-space noise would leave the dots where they were: ~3.5 px off at the centre).
TEST_F(Stipple, DotsStayOnTheSurfaceWhenTheCameraOrbits) {
    const int size = 512;
    Scene s = stipple_scene(size);
    const OrthoView first(orbit(0.0f), size), second(orbit(1.0f), size);
    const std::vector<Dot> before = find_dots(render(fine_sphere(), s, first.camera));
    const std::vector<Dot> after = find_dots(render(fine_sphere(), s, second.camera));
    const std::vector<Dot> tracked = dots_in_tone_band(before, first, s, 0.5f, 0.2f, 0.8f, 40);
    ASSERT_GE(tracked.size(), 100u);
    int followed = 0;
    double moved = 0;
    for (const Dot& d : tracked) {
        glm::vec3 p = *first.sphere_point(d.centre);
        glm::vec2 want = second.project(p);
        moved += glm::length(want - d.centre);
        float best = INFINITY;
        for (const Dot& e : after) best = std::min(best, glm::length(e.centre - want));
        followed += best <= 1.0f;
    }
    double fraction = double(followed) / double(tracked.size());
    EXPECT_GE(fraction, 0.8) << followed << " of " << tracked.size() << " dots followed the surface";
    EXPECT_GT(moved / double(tracked.size()), 2.0) << "the orbit should move the surface by > 2 px";
    RecordProperty("followed_fraction", std::to_string(fraction));
}

// More ink where the surface is darker: ink fraction in bands of analytic n.l decreases.
TEST_F(Stipple, InkFractionFallsAsLightRises) {
    const int size = 256;
    Scene s = stipple_scene(size);
    const OrthoView view(orbit(0.0f), size);
    Image img = render(fine_sphere(), s, view.camera);
    constexpr int kBands = 5;
    int ink[kBands + 1] = {}, total[kBands + 1] = {};  // last band: n.l < 0 (ambient only)
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            auto p = view.sphere_point({x + 0.5f, y + 0.5f});
            if (!p || p->z < 0.3f) continue;
            float ndotl = glm::dot(*p, light_dir(s));
            int band = ndotl < 0.0f ? kBands : std::min(kBands - 1, int(ndotl * kBands));
            ++total[band];
            ink[band] += is_ink(img, x, y);
        }
    double previous = double(ink[kBands]) / std::max(total[kBands], 1);
    EXPECT_GT(previous, 0.15) << "unlit side";
    for (int b = 0; b < kBands; ++b) {
        ASSERT_GT(total[b], 500) << "band " << b;
        double fraction = double(ink[b]) / total[b];
        EXPECT_LT(fraction, previous - 0.01) << "band n.l in [" << b * 0.2 << "," << (b + 1) * 0.2 << ")";
        previous = fraction;
    }
    EXPECT_LT(previous, 0.05) << "brightest band";
}

// Zooming in 2x (ortho height halved) keeps the dots' size in pixels: median area of the
// isolated mid-tone dots changes by less than 30%, and so does their number per pixel.
TEST_F(Stipple, DotSizeInPixelsIsStableAcrossZoom) {
    const int size = 256;
    Scene s = stipple_scene(size);
    const OrthoView wide(orbit(0.0f, 2.5f), size), close(orbit(0.0f, 1.25f), size);
    const auto dots_wide =
        dots_in_tone_band(find_dots(render(fine_sphere(), s, wide.camera)), wide, s, 0.6f, 0.3f, 0.7f, 60);
    const auto dots_close =
        dots_in_tone_band(find_dots(render(fine_sphere(), s, close.camera)), close, s, 0.6f, 0.3f, 0.7f, 60);
    ASSERT_GE(dots_wide.size(), 50u);
    ASSERT_GE(dots_close.size(), 50u);
    double a = median_area(dots_wide), b = median_area(dots_close);
    EXPECT_GT(a, 2.0);
    EXPECT_LT(std::abs(b - a) / a, 0.3) << "median dot area " << a << " px -> " << b << " px";
    RecordProperty("median_area_wide", std::to_string(a));
    RecordProperty("median_area_close", std::to_string(b));
}

// dot-size scales the dots (and only them): doubling it about quadruples the dot area.
TEST_F(Stipple, DotSizeParameterSetsDotArea) {
    const int size = 256;
    Scene s = stipple_scene(size);
    const OrthoView view(orbit(0.0f), size);
    s.shading.params["dot-size"] = {3.0f};
    double small = median_area(
        dots_in_tone_band(find_dots(render(fine_sphere(), s, view.camera)), view, s, 0.6f, 0.3f, 0.7f, 200));
    s.shading.params["dot-size"] = {6.0f};
    double large = median_area(
        dots_in_tone_band(find_dots(render(fine_sphere(), s, view.camera)), view, s, 0.6f, 0.3f, 0.7f, 200));
    EXPECT_GT(large, 2.5 * small) << small << " px -> " << large << " px";
}

}  // namespace
}  // namespace inkshade::test
