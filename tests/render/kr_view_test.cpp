// Debug view `kr`: the per-view radial curvature on a diverging colour scale. On the unit
// sphere kr = 1 in every direction, so every pixel shows the colour for kr * feature / range
// (feature = 1% of the bounding-box diagonal), except where w vanishes (view along the normal,
// kr reported 0), which the comparison avoids.
#include "inkshade/io.hpp"
#include "render/render_fixture.hpp"

namespace inkshade::test {
namespace {

glm::vec3 kr_color(float kr, float feature, float range) {
    const float t = std::clamp(kr * feature / range, -1.0f, 1.0f);
    return t >= 0.0f ? glm::mix(glm::vec3(1.0f), glm::vec3(0.85f, 0.1f, 0.05f), t)
                     : glm::mix(glm::vec3(1.0f), glm::vec3(0.05f, 0.25f, 0.85f), -t);
}

TEST(KrView, UnitSphereShowsRadialCurvatureOne) {
    const Mesh& sphere = fine_sphere();
    const float feature = 0.01f * sphere.bounds().diagonal();
    for (float range : {0.15f, 0.05f}) {
        ShadingSelection s;
        s.model = "kr";
        s.params["range"] = {range};
        RenderOptions o;
        o.width = o.height = kSize;
        const Image img = render_ortho(sphere, directional_light({0, 0, 1}, glm::vec3(1), glm::vec3(0)), s, o);
        int compared = 0;
        const Camera cam = ortho_camera();
        for (int gy = 0; gy < 24; ++gy)
            for (int gx = 0; gx < 24; ++gx) {
                const int px = 8 + gx * 10, py = 8 + gy * 10;
                auto n = sphere_normal(ray_origin(cam, px + 0.5f, py + 0.5f));
                if (!n || n->z < 0.2f || n->z > 0.97f) continue;
                const glm::vec3 want = kr_color(1.0f, feature, range);
                // Curvature estimates on the 128 x 256 sphere are within 1% of 1/r.
                const glm::vec3 lo = kr_color(0.99f, feature, range), hi = kr_color(1.01f, feature, range);
                for (int c = 0; c < 3; ++c) {
                    const int tol = 2 + std::abs(to_byte(hi[c]) - to_byte(lo[c]));
                    EXPECT_NEAR(int(img.pixel(px, py)[c]), to_byte(want[c]), tol)
                        << "range " << range << " pixel (" << px << "," << py << ") channel " << c;
                }
                ++compared;
            }
        EXPECT_GE(compared, 50);
    }
}

// A saddle has negative radial curvature in some directions: the inner side of a torus seen
// obliquely shows blue, the outer side red.
TEST(KrView, TorusInnerSaddleIsNegativeOuterIsPositive) {
    Renderer& r = shared_renderer();
    const Mesh torus = load_mesh("builtin:torus");
    r.set_mesh(torus);
    const Camera cam = frame_camera(torus.bounds(), {.azimuth_degrees = 20.0f, .elevation_degrees = 40.0f}, 1.0f);
    ShadingSelection s;
    s.model = "kr";
    s.params["range"] = {0.05f};
    RenderOptions o;
    o.width = o.height = 200;
    const Image img = r.render(cam, default_light(torus.bounds(), cam), s, o);
    int blue = 0, red = 0;
    for (size_t i = 0; i < img.rgba.size(); i += 4) {
        blue += img.rgba[i + 2] > img.rgba[i] + 30;
        red += img.rgba[i] > img.rgba[i + 2] + 30;
    }
    EXPECT_GT(blue, 200);
    EXPECT_GT(red, 4 * blue);
}

}  // namespace
}  // namespace inkshade::test
