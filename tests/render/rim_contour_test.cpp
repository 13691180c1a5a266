// rim-contour (the |n.v| < t band around the contour): on the unit sphere seen along z, |n.v| < t is the
// annulus sqrt(1 - t^2) < r < 1; the drawn band matches it within 1 px for several t, also on
// and the compensated mode gives a band of
// `width` pixels whatever the curvature.
#include <cmath>

#include "render/render_fixture.hpp"

namespace inkshade::test {
namespace {

ShadingSelection flat_green() {
    ShadingSelection s;
    s.model = "lambert";
    s.base_color = glm::vec3(0, 1, 0);
    return s;
}
Light ambient_only() { return directional_light(glm::vec3(0, 0, 1), glm::vec3(0), glm::vec3(1)); }

LineSettings rim(float threshold, bool compensate = false, float width = 2.0f) {
    LineSettings l{"rim-contour", {}};
    l.params["color"] = {0, 0, 1};
    l.params["threshold"] = {threshold};
    l.params["compensate"] = {compensate ? 1.0f : 0.0f};
    l.params["width"] = {width};
    return l;
}

// Radii (pixels from the image centre) where the line begins and where the background begins,
// along `angle`, in quarter-pixel steps; a pixel is line when blue dominates green.
std::pair<float, float> band_along(const Image& img, float angle) {
    const glm::vec2 c(0.5f * float(img.width), 0.5f * float(img.height)), d(std::cos(angle), std::sin(angle));
    float inner = -1;
    for (float t = 0; t < 0.5f * float(img.width); t += 0.25f) {
        const glm::vec2 q = c + t * d;
        const uint8_t* p = img.pixel(int(q.x), int(q.y));
        if (inner < 0 && p[2] > p[1]) inner = t;
        if (p[0] > 128) return {inner, t};  // white background
    }
    return {inner, -1};
}

Image render_rim(const LineSettings& line) {
    Renderer& r = shared_renderer();
    r.set_mesh(fine_sphere());
    RenderOptions o;
    o.width = o.height = kSize;
    return r.render(ortho_camera(), ambient_only(), flat_green(), {line}, o);
}

TEST(RimContour, SphereBandMatchesAnalyticAnnulus) {
    const float px = float(kSize) / ortho_camera().ortho_height;
    for (float t : {0.175f, 0.3f, 0.5f}) {
        Image img = render_rim(rim(t));
        for (int i = 0; i < 24; ++i) {
            const float a = 2.0f * float(M_PI) * (float(i) + 0.4f) / 24.0f;
            auto [inner, outer] = band_along(img, a);
            EXPECT_NEAR(inner, std::sqrt(1.0f - t * t) * px, 1.0f) << "t=" << t << " angle " << a;
            EXPECT_NEAR(outer, px, 1.0f) << "t=" << t << " angle " << a;
        }
    }
}

TEST(RimContour, CompensatedBandIsWidthPixels) {
    const float px = float(kSize) / ortho_camera().ortho_height;
    for (float width : {3.0f, 6.0f}) {
        Image img = render_rim(rim(0.175f, true, width));
        for (int i = 0; i < 24; ++i) {
            const float a = 2.0f * float(M_PI) * (float(i) + 0.4f) / 24.0f;
            auto [inner, outer] = band_along(img, a);
            // The contour is the silhouette: the band covers the last `width` pixels inside it.
            EXPECT_NEAR(outer - inner, width, 1.0f) << "width " << width << " angle " << a;
            EXPECT_NEAR(outer, px, 1.0f);
        }
    }
}

}  // namespace
}  // namespace inkshade::test
