// mtoon (MToon 1.0) against a CPU evaluation of its formula (docs/shading.md, measured from
// three-vrm 3.5.5 on three.js r187), both conventions, and its shadow map: a sphere above a
// plane casts its shadow where the analytic shadow is.
#include <algorithm>
#include <cmath>

#include "geometry/builtin_models.hpp"
#include "render/render_fixture.hpp"

namespace inkshade::test {
namespace {

struct MtoonParams {
    glm::vec3 shade{0.3f, 0.2f, 0.45f};
    float shift = -0.1f, toony = 0.7f;
    glm::vec3 rim{0.2f, 0.4f, 0.6f};
    float power = 3.0f, lift = 0.1f, rim_mix = 0.5f;
    bool threejs = false;
};

ShadingSelection selection(const MtoonParams& p, bool shadows) {
    ShadingSelection s;
    s.model = "mtoon";
    s.base_color = glm::vec3(0.9f, 0.7f, 0.6f);
    s.params = {{"shade-color", {p.shade.r, p.shade.g, p.shade.b}},
                {"shading-shift", {p.shift}},
                {"shading-toony", {p.toony}},
                {"rim-color", {p.rim.r, p.rim.g, p.rim.b}},
                {"rim-fresnel-power", {p.power}},
                {"rim-lift", {p.lift}},
                {"rim-lighting-mix", {p.rim_mix}},
                {"convention", {p.threejs ? 1.0f : 0.0f}},
                {"shadows", {shadows ? 1.0f : 0.0f}}};
    return s;
}

float linearstep(float a, float b, float x) { return std::clamp((x - a) / std::max(b - a, 1e-6f), 0.0f, 1.0f); }
float srgb(float c) { return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f; }

// The formula of docs/shading.md, per channel.
glm::vec3 mtoon(const MtoonParams& p, const glm::vec3& C, const Light& light, const glm::vec3& n, const glm::vec3& v,
                float shadow = 1.0f) {
    const float k = p.threejs ? float(1.0 / M_PI) : 1.0f;
    glm::vec3 l = glm::normalize(light.position - light.target);
    float t = linearstep(-1 + p.toony, 1 - p.toony, std::clamp(glm::dot(n, l), -1.0f, 1.0f) + p.shift) * shadow;
    glm::vec3 E = light.color * k, A = light.ambient * k;
    glm::vec3 direct = E * glm::mix(p.shade, C, t), gi = A * C;
    float f = std::pow(std::clamp(1 - glm::dot(n, v) + p.lift, 0.0f, 1.0f), p.power);
    glm::vec3 rim = p.rim * f * glm::mix(glm::vec3(1), E + A, p.rim_mix);
    glm::vec3 c = glm::clamp(direct + gi + rim, 0.0f, 1.0f);
    return p.threejs ? glm::vec3(srgb(c.r), srgb(c.g), srgb(c.b)) : c;
}

Light test_light() {
    Light l;
    l.position = glm::vec3(1.0f, 1.5f, 2.0f);
    l.target = glm::vec3(0);
    l.color = glm::vec3(0.95f, 0.9f, 0.85f);
    l.ambient = glm::vec3(0.15f, 0.15f, 0.2f);
    return l;
}

int compare_sphere(const MtoonParams& p, bool shadows, float min_ndotl = -2.0f) {
    static const Mesh sphere = builtin::sphere(128, 256);
    Renderer& r = shared_renderer();
    r.set_mesh(sphere);
    RenderOptions o;
    o.width = o.height = kSize;
    const Light light = test_light();
    const ShadingSelection sel = selection(p, shadows);
    Image img = r.render(ortho_camera(), light, sel, o);
    const glm::vec3 l = glm::normalize(light.position);
    int compared = 0;
    for (int py = 6; py < kSize; py += 10)
        for (int px = 6; px < kSize; px += 10) {
            auto n = sphere_normal(ray_origin(ortho_camera(), px + 0.5f, py + 0.5f));
            if (!n || n->z < 0.2f || glm::dot(*n, l) < min_ndotl) continue;
            // The rim's v: three-vrm's, from the camera position, in the threejs convention
            // (mtoon_parity_test.cpp); the view axis in the seeds convention.
            const glm::vec3 v = p.threejs ? glm::normalize(ortho_camera().eye - *n) : glm::vec3(0, 0, 1);
            glm::vec3 want = mtoon(p, sel.base_color, light, *n, v);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(int(img.pixel(px, py)[c]), to_byte(want[c]), 2) << px << "," << py << " channel " << c;
            ++compared;
        }
    return compared;
}

TEST(Mtoon, SeedsConventionMatchesFormula) { EXPECT_GE(compare_sphere(MtoonParams{}, false), 50); }

TEST(Mtoon, ThreejsConventionMatchesFormulaWithOneOverPiAndSrgb) {
    MtoonParams p;
    p.threejs = true;
    EXPECT_GE(compare_sphere(p, false), 50);
}

// three-vrm 3.5.5's MToonMaterial uniforms' initial values (its constructor's `uniforms`:
// shadeColorFactor Color(0, 0, 0), parametricRimFresnelPowerFactor 5, rimLightingMixFactor 1),
// in its threejs convention; a scene file's MToonMaterial takes them for omitted fields.
TEST(Mtoon, DefaultsAreMToonMaterials) {
    const ShadingModel& m = shading_model("mtoon");
    EXPECT_EQ(m.param("shading-toony")->default_value, ParamValue{0.9f});
    EXPECT_EQ(m.param("shading-shift")->default_value, ParamValue{0.0f});
    EXPECT_EQ(m.param("rim-fresnel-power")->default_value, ParamValue{5.0f});
    EXPECT_EQ(m.param("shade-color")->default_value, (ParamValue{0, 0, 0}));
    EXPECT_EQ(m.param("rim-color")->default_value, (ParamValue{0, 0, 0}));
    EXPECT_EQ(m.param("rim-lighting-mix")->default_value, ParamValue{1.0f});
    EXPECT_EQ(m.param("rim-lift")->default_value, ParamValue{0.0f});
    EXPECT_EQ(m.param("convention")->choices.at(size_t(m.param("convention")->default_value.at(0))), "threejs");
}

// A convex sphere does not shadow its own lit side: with the shadow map on, lit pixels equal
// the unshadowed formula (no acne from the depth bias / normal offset).
TEST(Mtoon, ShadowMapCausesNoAcneOnConvexLitSide) { EXPECT_GE(compare_sphere(MtoonParams{}, true, 0.15f), 50); }

// Sphere of radius 0.5 centred 1 above the plane y = 0, light straight down: the shadow on the
// plane is the disc x^2 + z^2 < 0.25. Pixels of the plane inside it show the shade colour,
// outside it the lit colour.
Mesh sphere_over_plane() {
    Mesh scene = builtin::sphere(48, 96, 0.5f);
    for (auto& p : scene.positions) p.y += 1.0f;
    const uint32_t base = uint32_t(scene.positions.size());
    for (glm::vec3 p : {glm::vec3(-2, 0, -2), glm::vec3(2, 0, -2), glm::vec3(2, 0, 2), glm::vec3(-2, 0, 2)}) {
        scene.positions.push_back(p);
        scene.normals.push_back(glm::vec3(0, 1, 0));
    }
    scene.triangles.push_back({base + 0, base + 2, base + 1});  // counter-clockwise seen from +y
    scene.triangles.push_back({base + 0, base + 3, base + 2});
    return scene;
}

TEST(Mtoon, SphereCastsShadowOnPlaneWhereAnalyticShadowIs) {
    const Mesh scene = sphere_over_plane();
    Camera cam;
    cam.eye = glm::vec3(0, 3, 3);
    cam.target = glm::vec3(0, 0, 0);
    cam.orthographic = true;
    cam.ortho_height = 3.0f;
    cam.near_plane = 0.1f;
    cam.far_plane = 10.0f;
    Light light;
    light.position = glm::vec3(0, 10, 0);
    light.target = glm::vec3(0);
    light.color = glm::vec3(0.8f);
    light.ambient = glm::vec3(0.1f);
    ShadingSelection sel;
    sel.model = "mtoon";
    sel.params = {{"shade-color", {0.0f, 0.0f, 1.0f}}, {"shading-toony", {0.9f}}, {"convention", {0.0f}}};
    RenderOptions o;
    o.width = o.height = kSize;
    o.background = glm::vec4(1, 0, 0, 1);
    Renderer& r = shared_renderer();
    r.set_mesh(scene);
    Image img = r.render(cam, light, sel, o);

    const glm::mat4 inv = glm::inverse(cam.projection(1.0f) * cam.view());
    const glm::vec3 lit(0.9f), shaded(0.1f, 0.1f, 0.9f);  // E*C + A*C and E*S + A*C with C = 1
    int inside = 0, outside = 0;
    for (int py = 0; py < kSize; py += 3)
        for (int px = 0; px < kSize; px += 3) {
            glm::vec2 ndc((px + 0.5f) / kSize * 2 - 1, 1 - (py + 0.5f) / kSize * 2);
            glm::vec4 a = inv * glm::vec4(ndc, -1, 1), b = inv * glm::vec4(ndc, 1, 1);
            glm::vec3 o3 = glm::vec3(a) / a.w, d = glm::normalize(glm::vec3(b) / b.w - o3);
            // Skip rays that meet the sphere (it hides the plane there).
            glm::vec3 oc = o3 - glm::vec3(0, 1, 0);
            float bq = glm::dot(oc, d), cq = glm::dot(oc, oc) - 0.25f;
            if (bq * bq - cq > -0.01f) continue;
            float t = -o3.y / d.y;
            glm::vec3 q = o3 + t * d;
            if (std::abs(q.x) > 1.9f || std::abs(q.z) > 1.9f) continue;
            float rho = std::sqrt(q.x * q.x + q.z * q.z);
            if (std::abs(rho - 0.5f) < 0.05f) continue;  // penumbra of the PCF filter
            glm::vec3 want = rho < 0.5f ? shaded : lit;
            (rho < 0.5f ? inside : outside)++;
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(int(img.pixel(px, py)[c]), to_byte(want[c]), 2)
                    << "plane point " << q.x << "," << q.z << (rho < 0.5f ? " (shadow)" : " (lit)");
        }
    EXPECT_GE(inside, 50);
    EXPECT_GE(outside, 50);
}

// The shadow map is reused while mesh and light stay the same, and rebuilt when either
// changes: the plane point below the sphere is shadowed under a vertical light, lit under a
// light from the side, and the first picture comes back byte for byte.
TEST(Mtoon, ShadowMapFollowsLightAndMeshChanges) {
    const Mesh scene = sphere_over_plane();
    Renderer& r = shared_renderer();
    r.set_mesh(scene);
    Camera cam = ortho_camera();  // looking down -z: the plane is seen edge-on, so look from above
    cam.eye = glm::vec3(0, 5, 0.01f);
    cam.target = glm::vec3(0);
    cam.up = glm::vec3(0, 0, -1);
    ShadingSelection sel;
    sel.model = "mtoon";
    sel.params = {{"shade-color", {0.0f, 0.0f, 1.0f}}, {"convention", {0.0f}}};
    RenderOptions o;
    o.width = o.height = 64;
    auto render_with = [&](glm::vec3 dir) {
        return r.render(cam, directional_light(dir, glm::vec3(0.8f), glm::vec3(0.1f)), sel, o);
    };
    // Reference pictures, each from a freshly set mesh (no map to reuse).
    Image vertical = render_with({0, 1, 0});
    r.set_mesh(scene);
    Image side = render_with({-1, 1, 0});  // shadow of the sphere falls towards +x
    // Alternating lights on the same mesh must give the same pictures as fresh renders.
    EXPECT_EQ(render_with({0, 1, 0}).rgba, vertical.rgba) << "stale shadow map after a light change";
    EXPECT_EQ(render_with({-1, 1, 0}).rgba, side.rgba) << "stale shadow map after a light change";
    EXPECT_EQ(render_with({-1, 1, 0}).rgba, side.rgba) << "reused shadow map differs";
    // Pixel over the plane point (1, 0, 0): 2.5 units span 64 px around the origin.
    const int x = 32 + int(std::lround(1.0f / 2.5f * 64.0f)), y = 32;
    EXPECT_LT(int(vertical.pixel(x, y)[2]), int(vertical.pixel(x, y)[0]) + 5) << "lit (grey) under vertical light";
    EXPECT_GT(int(side.pixel(x, y)[2]), int(side.pixel(x, y)[0]) + 100) << "shaded (blue) under side light";
    r.set_mesh(builtin::sphere(16, 32, 0.5f));  // a new mesh invalidates the map: no stale shadow
    Image alone = render_with({-1, 1, 0});
    EXPECT_EQ(int(alone.pixel(x, y)[0]), 255);  // background: nothing there, and no crash
}

}  // namespace
}  // namespace inkshade::test
