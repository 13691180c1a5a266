// threejs-outline (three.js OutlineEffect): on the unit sphere the outline ring runs from the
// projected radius out by thickness * H/2 pixels (orthographic: exactly; perspective: times the
// factor the 4-vector normalisation gives, evaluated here on the CPU), within 1 px; the colour
// is the sRGB encode of the linear outline colour, blended by alpha.
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "geometry/builtin_models.hpp"
#include "inkshade/lines.hpp"
#include "render/render_fixture.hpp"
#include "render/sphere_ring.hpp"

namespace inkshade::test {
namespace {

// Unlit green surface (MeshBasicMaterial 0x00ff00), blue outline, white background.
ShadingSelection green() {
    ShadingSelection s;
    s.model = "threejs-basic";
    s.params["color"] = {0, 1, 0};
    return s;
}

LineSettings outline(float thickness, glm::vec3 color = {0, 0, 1}, float alpha = 1.0f) {
    return {"threejs-outline",
            {{"thickness", {thickness}}, {"color", {color.r, color.g, color.b}}, {"alpha", {alpha}}}};
}

Image render_sphere(const Camera& camera, const LineSettings& line, int size) {
    Renderer& r = shared_renderer();
    r.set_mesh(fine_sphere());
    RenderOptions o;
    o.width = o.height = size;
    return r.render(camera, directional_light({0, 0, 1}, glm::vec3(1), glm::vec3(0)), green(), {line}, o);
}

// The outer edge of OutlineEffect's ring in pixels: the farthest image point of a back-facing
// sphere point p (normal p) moved by clip += normalize(VP (n, 0)) * thickness * clip.w, over the
// great circle through the silhouette. Its ratio to thickness * H/2 is the perspective factor.
float outline_outer_radius(const Camera& c, float thickness, int size) {
    const glm::mat4 vp = c.projection(1.0f) * c.view();
    float best = 0.0f;
    for (int i = 0; i < 40000; ++i) {
        const float phi = 2.0f * float(M_PI) * float(i) / 40000.0f;
        const glm::vec3 p(std::cos(phi), 0.0f, std::sin(phi));
        if (glm::dot(p, p - c.eye) <= 0.0f) continue;  // front-facing: culled
        glm::vec4 clip = vp * glm::vec4(p, 1.0f);
        const glm::vec4 d = vp * glm::vec4(p, 0.0f);
        clip += d / glm::length(d) * thickness * clip.w;
        best = std::max(best, std::abs(clip.x / clip.w) * 0.5f * float(size));
    }
    return best;
}

TEST(ThreejsOutline, OrthographicRingIsThicknessTimesHalfHeight) {
    for (int size : {256, 384})
        for (float t : {0.02f, 0.04f}) {
            const float r = silhouette_radius(ortho_camera(), size);
            expect_ring(render_sphere(ortho_camera(), outline(t), size), r, r + t * 0.5f * float(size),
                        "size " + std::to_string(size) + " thickness " + std::to_string(t));
        }
}

TEST(ThreejsOutline, PerspectiveRingIsThicknessTimesHalfHeightTimesPerspectiveFactor) {
    const int size = 320;
    for (float distance : {5.0f, 8.0f}) {
        const float t = 0.03f;
        const Camera cam = perspective(distance);
        const float r = silhouette_radius(cam, size), outer = outline_outer_radius(cam, t, size);
        const float factor = (outer - r) / (t * 0.5f * float(size));
        EXPECT_GT(factor, 0.9f) << "distance " << distance;
        EXPECT_LT(factor, 1.2f) << "distance " << distance;
        expect_ring(render_sphere(cam, outline(t), size), r, outer, "distance " + std::to_string(distance));
    }
}

// The outline colour is linear (OutlineEffect's [r, g, b]) and written sRGB-encoded; alpha < 1
// blends it over what lies behind (here the white background) in the encoded values.
TEST(ThreejsOutline, ColourIsEncodedAndAlphaBlends) {
    const glm::vec3 c(0.2f, 0.05f, 0.6f);
    auto encode = [](float v) { return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f; };
    const int size = 256;
    const float t = 0.08f;  // a ring of 10 px
    const float middle = silhouette_radius(ortho_camera(), size) + 0.5f * t * 0.5f * float(size);
    for (float alpha : {1.0f, 0.5f}) {
        const Image img = render_sphere(ortho_camera(), outline(t, c, alpha), size);
        for (int i = 0; i < 8; ++i) {
            const float a = 2.0f * float(M_PI) * (float(i) + 0.5f) / 8.0f;
            const int x = int(128.0f + middle * std::cos(a)), y = int(128.0f + middle * std::sin(a));
            for (int k = 0; k < 3; ++k)
                EXPECT_NEAR(int(img.pixel(x, y)[k]), to_byte(alpha * encode(c[k]) + (1.0f - alpha)), 1)
                    << "alpha " << alpha << " channel " << k << " at " << x << "," << y;
        }
    }
}

TEST(ThreejsOutline, DefaultsAreOutlineEffects) {
    const LineType& t = line_type("threejs-outline");
    EXPECT_EQ(t.space, LineSpace::Image);
    EXPECT_EQ(t.param("thickness")->default_value, ParamValue{0.003f});
    EXPECT_EQ(t.param("color")->default_value, (ParamValue{0, 0, 0}));
    EXPECT_EQ(t.param("alpha")->default_value, ParamValue{1.0f});
}

// At the default thickness 0.003 a 1024-pixel image has an outline of about 1.5 px: present,
// black, and gone with thickness 0.
TEST(ThreejsOutline, DefaultThicknessDrawsAThinBlackOutline) {
    auto dark_ring_pixels = [](const Image& img) {
        int n = 0;
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x) n += img.pixel(x, y)[0] < 64 && img.pixel(x, y)[1] < 64;
        return n;
    };
    Renderer& r = shared_renderer();
    r.set_mesh(fine_sphere());
    RenderOptions o;
    o.width = o.height = 1024;
    const Light light = directional_light({0, 0, 1}, glm::vec3(1), glm::vec3(0));
    const Image with = r.render(ortho_camera(), light, green(), {LineSettings{"threejs-outline", {}}}, o);
    const Image without = r.render(ortho_camera(), light, green(), {outline(0.0f)}, o);
    // Circumference 2 pi R with R = 1024 / 2.5 px, about 1.5 px wide.
    const float expected = 2.0f * float(M_PI) * 1024.0f / 2.5f * 0.003f * 512.0f;
    EXPECT_GT(dark_ring_pixels(with), 0.5f * expected);
    EXPECT_LT(dark_ring_pixels(with), 1.6f * expected);
    EXPECT_EQ(dark_ring_pixels(without), 0);
}

}  // namespace
}  // namespace inkshade::test
