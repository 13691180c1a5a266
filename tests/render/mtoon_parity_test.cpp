// mtoon in its threejs convention against three-vrm 3.5's MToonMaterial on three.js r187,
// evaluated on the CPU from their formulas: the rim's view direction from the camera position
// under an orthographic camera (three-vrm's mtoon.frag: viewDir = normalize(vViewPosition)),
// point and spot lights with three.js's intensity, decay, distance window and cone
// (getDistanceAttenuation, getSpotAttenuation), and the light intensity of the request path
// (SceneRequest::light_intensity) in mtoon, lambert and threejs-lambert.
#include <algorithm>
#include <cmath>

#include "inkshade/scene.hpp"
#include "render/render_fixture.hpp"

namespace inkshade::test {
namespace {

float smoothstep(float a, float b, float x) {
    const float t = std::clamp((x - a) / (b - a), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

struct Mtoon {
    glm::vec3 shade{0.3f, 0.2f, 0.45f};
    float shift = -0.1f, toony = 0.6f;
    glm::vec3 rim{0.5f, 0.4f, 0.3f};
    float power = 2.0f, lift = 0.05f, rim_mix = 0.5f;
    ShadingSelection selection(const glm::vec3& base) const {
        ShadingSelection s;
        s.model = "mtoon";
        s.base_color = base;
        s.params = {{"shade-color", {shade.r, shade.g, shade.b}},
                    {"shading-shift", {shift}},
                    {"shading-toony", {toony}},
                    {"rim-color", {rim.r, rim.g, rim.b}},
                    {"rim-fresnel-power", {power}},
                    {"rim-lift", {lift}},
                    {"rim-lighting-mix", {rim_mix}},
                    {"convention", {1.0f}},
                    {"shadows", {0.0f}}};
        return s;
    }
};

// three.js r187's directLight.color at p: colour x intensity, for a point or spot light times
// getDistanceAttenuation (and getSpotAttenuation).
glm::vec3 direct_light(const Light& light, const glm::vec3& p) {
    glm::vec3 e = light.color * light.intensity;
    if (light.type == LightType::Directional) return e;
    const float d = glm::length(light.position - p);
    float falloff = 1.0f / std::max(std::pow(d, light.decay), 0.01f);
    if (light.range > 0.0f) {
        const float w = std::clamp(1.0f - std::pow(d / light.range, 4.0f), 0.0f, 1.0f);
        falloff *= w * w;
    }
    if (light.type == LightType::Spot) {
        const float c = glm::dot(glm::normalize(p - light.position), glm::normalize(light.target - light.position));
        falloff *= smoothstep(light.cos_outer, light.cos_inner, c);
    }
    return e * falloff;
}

// three-vrm's MToonMaterial (mtoon.frag, RE_Direct_MToon and the rim) at surface point p with
// normal n, seen from `eye`, in linear light, then three.js's sRGB encode. `view_axis`: the
// view direction three.js's own materials take under an orthographic camera, for contrast.
glm::vec3 three_vrm(const Mtoon& m, const glm::vec3& C, const Light& light, const glm::vec3& p, const glm::vec3& n,
                    const glm::vec3& eye, const glm::vec3* view_axis = nullptr) {
    const glm::vec3 l = light.type == LightType::Directional ? glm::normalize(light.position - light.target)
                                                             : glm::normalize(light.position - p);
    const glm::vec3 E = direct_light(light, p), A = light.ambient;
    const float a = -1.0f + m.toony, b = 1.0f - m.toony;
    const float shading = std::clamp((std::clamp(glm::dot(n, l), -1.0f, 1.0f) + m.shift - a) / (b - a), 0.0f, 1.0f);
    const glm::vec3 direct = E / kPi * glm::mix(m.shade, C, shading);
    const glm::vec3 gi = A / kPi * C;
    const glm::vec3 v = view_axis ? *view_axis : glm::normalize(eye - p);
    const float f = std::pow(std::clamp(1.0f - glm::dot(v, n) + m.lift, 0.0f, 1.0f), m.power);
    const glm::vec3 rim = m.rim * f * glm::mix(glm::vec3(1.0f), (E + A) / kPi, m.rim_mix);
    return reference_srgb(direct + gi + rim);
}

Light light_of(LightType type, const glm::vec3& position, float intensity) {
    Light l;
    l.type = type;
    l.position = position;
    l.target = glm::vec3(0.0f);
    l.color = glm::vec3(1.0f, 0.9f, 0.8f);
    l.ambient = glm::vec3(0.2f, 0.25f, 0.3f);
    l.intensity = intensity;
    l.physical_falloff = type != LightType::Directional;
    return l;
}

Image render_sphere(const Light& light, const ShadingSelection& s) {
    RenderOptions o;
    o.width = o.height = kSize;
    return render_ortho(fine_sphere(), light, s, o);
}

const glm::vec3 kBase(0.9f, 0.75f, 0.6f);
// Mtoon{} as --set overrides (its threejs convention is the model's default).
const std::vector<std::string> kMtoonSets = {"shade-color=0.3,0.2,0.45", "shading-shift=-0.1", "shading-toony=0.6",
                                             "rim-color=0.5,0.4,0.3",    "rim-fresnel-power=2", "rim-lift=0.05",
                                             "rim-lighting-mix=0.5",     "shadows=false"};

// Under an orthographic camera three-vrm's rim looks from the camera position (0, 0, 5), not
// along the view axis; the two differ by more than 2 levels on most of the sphere, so the
// formula is what the pixels follow.
TEST(MtoonParity, OrthographicRimLooksFromTheCameraPosition) {
    const Mtoon m;
    const Light light = light_of(LightType::Directional, {1.0f, 1.5f, 2.0f}, 2.0f);
    const Image img = render_sphere(light, m.selection(kBase));
    const glm::vec3 eye = ortho_camera().eye, axis(0, 0, 1);
    int apart = 0;
    const int compared = compare_on_sphere(img, [&](const glm::vec3& n) {
        const glm::vec3 want = three_vrm(m, kBase, light, n, n, eye);
        const glm::vec3 along_axis = three_vrm(m, kBase, light, n, n, eye, &axis);
        for (int c = 0; c < 3; ++c)
            if (std::abs(to_byte(want[c]) - to_byte(along_axis[c])) > 2) {
                ++apart;
                break;
            }
        return want;
    });
    EXPECT_GE(compared, 150);
    EXPECT_GE(apart, compared / 2) << "the test does not tell the two view directions apart";
}

// A point light with intensity 3, decay 1.5 and distance 3.5 given through the request path
// (make_scene, Scene::light): three.js's falloff, window and intensity on every pixel.
TEST(MtoonParity, PointLightHasIntensityDecayAndDistanceAsThreejs) {
    const Mtoon m;
    SceneRequest r;
    r.shading = "mtoon";
    r.light_type = LightType::Point;
    r.light_position = glm::vec3(0.6f, 0.9f, 1.5f);
    r.light_color = glm::vec3(1.0f, 0.9f, 0.8f);
    r.ambient = glm::vec3(0.2f, 0.25f, 0.3f);
    r.light_intensity = 3.0f;
    r.light_decay = 1.5f;
    r.light_distance = 3.5f;
    r.base_color = kBase;
    r.sets = kMtoonSets;
    const Scene scene = make_scene(r);
    const Camera cam = ortho_camera();
    const Light light = scene.light(fine_sphere().bounds(), cam);
    ASSERT_TRUE(light.physical_falloff);
    EXPECT_FLOAT_EQ(light.intensity, 3.0f);
    EXPECT_FLOAT_EQ(light.decay, 1.5f);
    EXPECT_FLOAT_EQ(light.range, 3.5f);
    Renderer& renderer = shared_renderer();
    renderer.set_mesh(fine_sphere());
    RenderOptions o;
    o.width = o.height = kSize;
    const Image img = renderer.render(cam, light, scene.shading(), o);
    int dimmed = 0;  // pixels the window darkens by more than 2 levels
    const int compared = compare_on_sphere(img, [&](const glm::vec3& n) {
        Light unwindowed = light;
        unwindowed.range = 0.0f;
        const glm::vec3 want = three_vrm(m, kBase, light, n, n, cam.eye);
        if (to_byte(three_vrm(m, kBase, unwindowed, n, n, cam.eye).r) - to_byte(want.r) > 2) ++dimmed;
        return want;
    });
    EXPECT_GE(compared, 150);
    EXPECT_GE(dimmed, 50) << "the distance window has no visible effect in this set-up";
}

// A spot light (a glTF file's, --lights file): the cone's smoothstep on top of the falloff,
// full inside 8 degrees, none outside 16, aimed past the sphere's centre.
TEST(MtoonParity, SpotLightConeAndFalloffAsThreejs) {
    const Mtoon m;
    Light light = light_of(LightType::Spot, {0.0f, 0.0f, 3.0f}, 12.0f);
    light.target = glm::vec3(0.3f, 0.2f, 0.0f);
    light.cos_inner = std::cos(glm::radians(8.0f));
    light.cos_outer = std::cos(glm::radians(16.0f));
    light.range = 6.0f;
    const Image img = render_sphere(light, m.selection(kBase));
    int dark = 0, lit = 0;
    const int compared = compare_on_sphere(img, [&](const glm::vec3& n) {
        const float c = glm::dot(glm::normalize(n - light.position), glm::normalize(light.target - light.position));
        if (c < light.cos_outer) ++dark;
        if (c > light.cos_inner) ++lit;
        return three_vrm(m, kBase, light, n, n, ortho_camera().eye);
    });
    EXPECT_GE(compared, 150);
    EXPECT_GE(dark, 20) << "no pixel outside the cone";
    EXPECT_GE(lit, 20) << "no pixel inside the cone";
}

// --light-intensity 3 (SceneRequest::light_intensity): E = colour x 3 in a display model
// (lambert: C (3 E max(n.l, 0) + A)), in mtoon's threejs convention, and as threejs-lambert's
// light-intensity parameter.
TEST(MtoonParity, LightIntensityThreeInEveryModel) {
    const glm::vec3 to_light = glm::normalize(glm::vec3(-1.0f, 1.0f, 1.5f));
    const auto render_request = [&](const std::string& shading, const std::vector<std::string>& sets) {
        SceneRequest r;
        r.shading = shading;
        r.sets = sets;
        r.light_position = to_light * 10.0f;
        r.light_target = glm::vec3(0.0f);
        r.light_color = glm::vec3(0.3f, 0.25f, 0.2f);
        r.ambient = glm::vec3(0.05f);
        r.base_color = kBase;
        r.light_intensity = 3.0f;
        const Scene scene = make_scene(r);
        const Light light = scene.light(fine_sphere().bounds(), ortho_camera());
        Renderer& renderer = shared_renderer();
        renderer.set_mesh(fine_sphere());
        RenderOptions o;
        o.width = o.height = kSize;
        return std::pair{renderer.render(ortho_camera(), light, scene.shading(), o), scene};
    };
    const glm::vec3 E(0.3f, 0.25f, 0.2f), A(0.05f);

    const auto [lambert, lambert_scene] = render_request("lambert", {});
    int bright = 0;  // pixels above what E alone could give: the intensity is not clamped away
    EXPECT_GE(compare_on_sphere(lambert,
                                [&](const glm::vec3& n) {
                                    const glm::vec3 c = kBase * (3.0f * E * std::max(glm::dot(n, to_light), 0.0f) + A);
                                    if (c.r > kBase.r * (E.r + A.r) + 0.05f) ++bright;
                                    return c;
                                }),
              150);
    EXPECT_GE(bright, 30);

    const Mtoon m;
    const auto [mtoon, mtoon_scene] = render_request("mtoon", kMtoonSets);
    Light directional = light_of(LightType::Directional, to_light * 10.0f, 3.0f);
    directional.color = E;
    directional.ambient = A;
    EXPECT_GE(compare_on_sphere(mtoon, [&](const glm::vec3& n) {
                  return three_vrm(m, kBase, directional, n, n, ortho_camera().eye);
              }),
              150);

    const auto [three, three_scene] = render_request("threejs-lambert", {});
    EXPECT_EQ(three_scene.style.shading.params.at("light-intensity"), ParamValue{3.0f});  // the parameter, once
    EXPECT_FALSE(three_scene.style.light_intensity);
    EXPECT_GE(compare_on_sphere(three,
                                [&](const glm::vec3& n) {
                                    const glm::vec3 c =
                                        kBase / kPi * (3.0f * E * std::max(glm::dot(n, to_light), 0.0f) + A);
                                    return reference_srgb(c);
                                }),
              150);
}

}  // namespace
}  // namespace inkshade::test
