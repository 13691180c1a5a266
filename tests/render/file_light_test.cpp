// A model file's lights and unlit materials in the shaders: a spot light under threejs-lambert
// and a ranged point light under mtoon's threejs convention against three.js's physically
// correct formulas per pixel, and KHR_materials_unlit drawn in its base colour under every
// shading model (debug views excepted).
#include <cmath>

#include "render/render_fixture.hpp"

namespace inkshade::test {
namespace {

float smoothstep(float a, float b, float x) {
    const float t = std::clamp((x - a) / (b - a), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

// The square [-1, 1]^2 in z = 0 facing +z, as two quads split at x = 0 with materials 0 and 1.
Mesh two_halves(const Material& left, const Material& right) {
    Mesh m;
    m.positions = {{-1, -1, 0}, {0, -1, 0}, {0, 1, 0}, {-1, 1, 0}, {0, -1, 0}, {1, -1, 0}, {1, 1, 0}, {0, 1, 0}};
    m.normals.assign(8, glm::vec3(0, 0, 1));
    m.triangles = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}};
    m.materials = {left, right};
    m.face_materials = {0, 0, 1, 1};
    return m;
}

RenderOptions options(int size = 64) {
    RenderOptions o;
    o.width = o.height = size;
    o.samples = 1;
    return o;
}

// World point under pixel (x, y)'s centre on the z = 0 plane.
glm::vec3 plane_point(int x, int y, int size) {
    const glm::vec3 o = ray_origin(ortho_camera(), float(x) + 0.5f, float(y) + 0.5f, size, size);
    return {o.x, o.y, 0.0f};
}

// Compares every pixel of row `y` over the square with expected(p), within 1/255.
int compare_row(const Image& img, int y, const std::function<glm::vec3(const glm::vec3&)>& expected) {
    int compared = 0;
    for (int x = 0; x < img.width; ++x) {
        const glm::vec3 p = plane_point(x, y, img.width);
        if (std::abs(p.x) > 0.97f || std::abs(p.y) > 0.97f) continue;
        const glm::vec3 e = expected(p);
        const uint8_t* px = img.pixel(x, y);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(int(px[c]), to_byte(e[c]), 1) << "pixel " << x << "," << y << " c" << c;
        ++compared;
    }
    return compared;
}

TEST(FileLight, SpotLightUnderThreejsLambertIsThreejsPhysicalSpot) {
    const Mesh mesh = two_halves(Material{"a", glm::vec3(1.0f)}, Material{"b", glm::vec3(1.0f)});
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {0.0f, 0.0f, 1.2f};
    spot.target = {0.0f, 0.0f, 0.2f};  // straight down
    spot.color = {1.0f, 0.8f, 0.6f};
    spot.ambient = glm::vec3(0.0f);
    spot.cos_inner = std::cos(0.3f);
    spot.cos_outer = std::cos(0.6f);
    ShadingSelection s;
    s.model = "threejs-lambert";
    s.params["light-intensity"] = {4.0f};
    s.params["light-decay"] = {2.0f};
    const Image img = render_ortho(mesh, spot, s, options());
    // irradiance = colour x intensity / d^2 x smoothstep(cos outer, cos inner, cos theta) x n.l;
    // the Lambertian surface reflects C / pi of it.
    const auto expected = [&](const glm::vec3& p) {
        const glm::vec3 to_light = spot.position - p;
        const float d = glm::length(to_light), cos_theta = to_light.z / d;
        const float cone = smoothstep(spot.cos_outer, spot.cos_inner, cos_theta);
        const glm::vec3 c = spot.color * 4.0f / (d * d) * cone * cos_theta / kPi;
        return reference_srgb(c);
    };
    EXPECT_GT(compare_row(img, 32, expected), 45);
    EXPECT_GT(compare_row(img, 20, expected), 45);
    // Outside the cone (0.6 rad at height 1.2 reaches 0.82 from the axis), still on the square: black.
    EXPECT_EQ(int(img.pixel(8, 8)[0]), 0);
    EXPECT_GT(int(img.pixel(32, 32)[0]), 200);
}

TEST(FileLight, RangedPointLightUnderMtoonThreejsConventionFallsOffAsThreejs) {
    const Mesh mesh = two_halves(Material{"a", glm::vec3(0.8f)}, Material{"b", glm::vec3(0.8f)});
    Light point;
    point.type = LightType::Point;
    point.position = {0.3f, 0.0f, 0.8f};
    point.target = glm::vec3(0.0f);
    point.color = glm::vec3(3.0f);  // colour x intensity
    point.ambient = glm::vec3(0.0f);
    point.physical_falloff = true;
    point.range = 1.5f;
    ShadingSelection s;
    s.model = "mtoon";
    s.params["convention"] = {1.0f};  // threejs
    s.params["shadows"] = {0.0f};
    s.params["shading-toony"] = {0.0f};  // t = (n.l + 1) / 2
    s.params["shade-color"] = {0.0f, 0.0f, 0.0f};
    const Image img = render_ortho(mesh, point, s, options());
    const auto expected = [&](const glm::vec3& p) {
        const glm::vec3 to_light = point.position - p;
        const float d = glm::length(to_light), ndotl = to_light.z / d;
        const float x = d / point.range, window = std::clamp(1.0f - x * x * x * x, 0.0f, 1.0f);
        const float e = 3.0f / std::max(d * d, 0.01f) * window * window;
        const float c = e / kPi * 0.8f * 0.5f * (ndotl + 1.0f);  // E k mix(S = 0, C, t)
        return glm::vec3(reference_srgb(c));
    };
    EXPECT_GT(compare_row(img, 32, expected), 45);
    EXPECT_GT(compare_row(img, 12, expected), 45);
    EXPECT_EQ(int(img.pixel(8, 8)[0]), 0);  // 1.7 from the light: beyond its range
}

TEST(FileLight, UnlitMaterialIsItsBaseColourUnderEveryModel) {
    Material lit{"lit", glm::vec3(0.8f, 0.2f, 0.2f)};
    Material unlit{"unlit", glm::vec3(0.2f, 0.6f, 0.4f)};
    unlit.unlit = true;
    const Mesh mesh = two_halves(lit, unlit);
    const Light light = directional_light({0, 0, 1}, glm::vec3(0.5f), glm::vec3(0.1f));
    for (const char* model : {"lambert", "gouraud", "cel", "phong", "gooch", "flat", "palette", "mtoon",
                              "threejs-lambert", "threejs-toon", "stipple"}) {
        SCOPED_TRACE(model);
        ShadingSelection s;
        s.model = model;
        s.base_color = glm::vec3(1.0f, 1.0f, 0.5f);  // multiplies the unlit colour too
        const Image img = render_ortho(mesh, light, s, options());
        const glm::vec3 c = unlit.diffuse * s.base_color;
        // mtoon's default convention is three-vrm's: sRGB output, as the threejs-* models.
        const bool srgb = std::string(model).starts_with("threejs-") || std::string(model) == "mtoon";
        const glm::vec3 want = srgb ? reference_srgb(c) : c;
        const uint8_t* px = img.pixel(48, 32);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(int(px[k]), to_byte(want[k]), 1) << k;
        if (std::string(model) == "lambert") {  // the lit half is lit: C (E n.l + A)
            EXPECT_NEAR(int(img.pixel(16, 32)[0]), to_byte(0.8f * 0.6f), 1);
            EXPECT_NEAR(int(img.pixel(16, 32)[2]), to_byte(0.2f * 0.5f * 0.6f), 1);
        }
    }
    ShadingSelection normal;
    normal.model = "normal";  // a debug view shows geometry, unlit or not
    const Image img = render_ortho(mesh, light, normal, options());
    EXPECT_NEAR(int(img.pixel(48, 32)[2]), 255, 1);
    EXPECT_NEAR(int(img.pixel(48, 32)[0]), 128, 1);
}

}  // namespace
}  // namespace inkshade::test
