// A VRM material's MToon textures against three-vrm 3.x's mtoon.frag and mtoon.vert, evaluated
// on the CPU: the matcap (read where the view-space normal puts it in the frame x =
// normalize(v.z, 0, -v.x), y = v x x) scaled by matcapFactor and added to the parametric rim,
// both times rimMultiplyTexture at the uvs, on a sphere with known uvs (a planar projection:
// u = (x + 1)/2, v = (y + 1)/2); and outlineWidthMultiplyTexture's green channel scaling the
// outline. Colour textures are decoded from sRGB (three-vrm's colour spaces), data ones not.
#include <cmath>
#include <memory>

#include "render/render_fixture.hpp"
#include "render/sphere_ring.hpp"

namespace inkshade::test {
namespace {

constexpr int kTexels = 32;

float srgb_encode(float c) {
    c = std::clamp(c, 0.0f, 1.0f);
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}
float srgb_decode(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

// A kTexels^2 texture of two ramps (red across, green down the rows) and a constant blue.
std::shared_ptr<Texture> ramps(uint8_t blue) {
    auto t = std::make_shared<Texture>();
    t->source = "ramps";
    t->width = t->height = kTexels;
    for (int y = 0; y < kTexels; ++y)
        for (int x = 0; x < kTexels; ++x)
            for (uint8_t c : {uint8_t(std::lround(255.0f * float(x) / (kTexels - 1))),
                              uint8_t(std::lround(255.0f * float(y) / (kTexels - 1))), blue, uint8_t(255)})
                t->rgba.push_back(c);
    return t;
}

// GL's bilinear read of `t` at texture coordinates (s, t) (row 0 at t = 0), each texel decoded
// from sRGB first as an sRGB texture is.
glm::vec3 sample(const Texture& tex, glm::vec2 st) {
    const float x = st.x * float(tex.width) - 0.5f, y = st.y * float(tex.height) - 0.5f;
    const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    const float fx = x - float(x0), fy = y - float(y0);
    auto texel = [&](int i, int j) {
        i = std::clamp(i, 0, tex.width - 1);
        j = std::clamp(j, 0, tex.height - 1);
        const uint8_t* p = &tex.rgba[size_t(4 * (j * tex.width + i))];
        return glm::vec3(srgb_decode(p[0] / 255.0f), srgb_decode(p[1] / 255.0f), srgb_decode(p[2] / 255.0f));
    };
    return glm::mix(glm::mix(texel(x0, y0), texel(x0 + 1, y0), fx),
                    glm::mix(texel(x0, y0 + 1), texel(x0 + 1, y0 + 1), fx), fy);
}

struct Look {
    glm::vec3 C{0.35f, 0.3f, 0.25f}, shade{0.1f, 0.05f, 0.15f}, rim{0.3f, 0.2f, 0.1f}, matcap{0.6f, 0.5f, 0.4f};
    float toony = 0.7f, shift = 0.0f, power = 2.0f, lift = 0.1f, rim_mix = 0.5f;
};

// The unit sphere with uvs u = (x + 1)/2, v = (y + 1)/2 and one VRM MToon material.
Mesh sphere_with(const Material& m) {
    Mesh s = fine_sphere();
    for (const glm::vec3& p : s.positions) s.uvs.push_back(0.5f * (glm::vec2(p) + 1.0f));
    s.materials = {m};
    s.face_materials.assign(s.triangles.size(), 0);
    return s;
}

ShadingSelection selection(const Look& k) {
    ShadingSelection s;
    s.model = "mtoon";
    s.base_color = k.C;
    s.params = {{"shade-color", {k.shade.r, k.shade.g, k.shade.b}},
                {"shading-toony", {k.toony}},
                {"shading-shift", {k.shift}},
                {"rim-color", {k.rim.r, k.rim.g, k.rim.b}},
                {"rim-fresnel-power", {k.power}},
                {"rim-lift", {k.lift}},
                {"rim-lighting-mix", {k.rim_mix}},
                {"shadows", {0}}};
    return s;
}

// three-vrm's mtoon.frag at the unit sphere's point n under an orthographic camera at `eye`
// (view space = world space moved), then three.js's sRGB encode.
glm::vec3 three_vrm(const Look& k, const Light& light, const glm::vec3& n, const glm::vec3& eye, const Texture* matcap,
                    const Texture* rim_multiply) {
    const glm::vec3 l = glm::normalize(light.position - light.target);
    const glm::vec3 E = light.color * light.intensity, A = light.ambient;
    const float a = -1.0f + k.toony, b = 1.0f - k.toony;
    const float t = std::clamp((std::clamp(glm::dot(n, l), -1.0f, 1.0f) + k.shift - a) / (b - a), 0.0f, 1.0f);
    const glm::vec3 direct = E / kPi * glm::mix(k.shade, k.C, t), gi = A / kPi * k.C;
    const glm::vec3 v = glm::normalize(eye - n);
    glm::vec3 rim = k.rim * std::pow(std::clamp(1.0f - glm::dot(v, n) + k.lift, 0.0f, 1.0f), k.power);
    if (matcap) {
        const glm::vec3 x = glm::normalize(glm::vec3(v.z, 0.0f, -v.x)), y = glm::cross(v, x);
        rim += k.matcap * sample(*matcap, 0.5f + 0.5f * glm::vec2(glm::dot(x, n), -glm::dot(y, n)));
    }
    if (rim_multiply) rim *= sample(*rim_multiply, {0.5f * n.x + 0.5f, 1.0f - (0.5f * n.y + 0.5f)});
    rim *= glm::mix(glm::vec3(1.0f), (E + A) / kPi, k.rim_mix);
    const glm::vec3 c = direct + gi + rim;
    return {srgb_encode(c.r), srgb_encode(c.g), srgb_encode(c.b)};
}

Light key_light() {
    Light l = directional_light({-1.0f, 1.5f, 2.0f}, glm::vec3(1.0f, 0.95f, 0.9f), glm::vec3(0.3f, 0.3f, 0.35f));
    l.intensity = 2.0f;
    return l;
}

TEST(MtoonTextures, MatcapAndRimMultiplyFollowThreeVrm) {
    const Look k;
    const auto matcap = ramps(80), rim_multiply = ramps(230);
    Material m;
    m.name = "vrm";
    m.diffuse = glm::vec3(1.0f);
    m.mtoon = {{"matcap-color", {k.matcap.r, k.matcap.g, k.matcap.b}}};
    m.mtoon_textures = {{"matcap-texture", matcap}, {"rim-multiply-texture", rim_multiply}};
    RenderOptions o;
    o.width = o.height = kSize;
    o.samples = 1;
    const Light light = key_light();
    const glm::vec3 eye = ortho_camera().eye;

    const Image img = render_ortho(sphere_with(m), light, selection(k), o);
    int differs = 0;
    const int compared = compare_on_sphere(
        img,
        [&](const glm::vec3& n) {
        const glm::vec3 want = three_vrm(k, light, n, eye, matcap.get(), rim_multiply.get());
        const glm::vec3 plain = three_vrm(k, light, n, eye, nullptr, nullptr);
        differs += std::abs(to_byte(want.g) - to_byte(plain.g)) > 8;
        return want;
        },
        0.45f, "matcap and rim multiply");
    EXPECT_GE(compared, 150);
    EXPECT_GE(differs, compared / 2) << "the textures hardly change the picture: the test proves little";

    // Only a rim multiply texture: no matcap term (the absent matcap reads black).
    m.mtoon_textures = {{"rim-multiply-texture", rim_multiply}};
    const Image rim_only = render_ortho(sphere_with(m), light, selection(k), o);
    compare_on_sphere(
        rim_only, [&](const glm::vec3& n) { return three_vrm(k, light, n, eye, nullptr, rim_multiply.get()); }, 0.45f,
        "rim multiply alone");

    // use-material-params off restyles the material: its textures go with its values.
    ShadingSelection off = selection(k);
    off.params["use-material-params"] = {0};
    m.mtoon_textures = {{"matcap-texture", matcap}, {"rim-multiply-texture", rim_multiply}};
    const Image restyled = render_ortho(sphere_with(m), light, off, o);
    compare_on_sphere(
        restyled, [&](const glm::vec3& n) { return three_vrm(k, light, n, eye, nullptr, nullptr); }, 0.45f,
        "use-material-params off");
}

// A mesh without uvs still gets its matcap (three-vrm reads it at the view-space normal, not
// at the uvs); the rim multiply texture is then read at uv (0, 0), WebGL's value of an absent
// attribute: here its texel there, the same on every pixel.
TEST(MtoonTextures, MatcapNeedsNoUvs) {
    const Look k;
    const auto matcap = ramps(80);
    Material m;
    m.name = "vrm";
    m.diffuse = glm::vec3(1.0f);
    m.mtoon = {{"matcap-color", {k.matcap.r, k.matcap.g, k.matcap.b}}};
    m.mtoon_textures = {{"matcap-texture", matcap}};
    Mesh mesh = sphere_with(m);
    mesh.uvs.clear();
    RenderOptions o;
    o.width = o.height = kSize;
    o.samples = 1;
    const Light light = key_light();
    const glm::vec3 eye = ortho_camera().eye;
    const Image img = render_ortho(mesh, light, selection(k), o);
    int differs = 0;
    const int compared = compare_on_sphere(
        img,
        [&](const glm::vec3& n) {
        const glm::vec3 want = three_vrm(k, light, n, eye, matcap.get(), nullptr);
        differs += std::abs(to_byte(want.g) - to_byte(three_vrm(k, light, n, eye, nullptr, nullptr).g)) > 8;
        return want;
        },
        0.45f, "matcap without uvs");
    EXPECT_GE(compared, 150);
    EXPECT_GE(differs, compared / 2) << "the matcap hardly changes the picture: the test proves little";
}

// outlineWidthMultiplyTexture's green channel (data: as stored) scales the outline width: full
// on the left half of the uvs, 128/255 on the right.
TEST(MtoonTextures, OutlineWidthMultiplyScalesTheRing) {
    auto halves = std::make_shared<Texture>();
    halves->width = halves->height = kTexels;
    for (int y = 0; y < kTexels; ++y)
        for (int x = 0; x < kTexels; ++x)
            for (uint8_t c : {uint8_t(0), uint8_t(x < kTexels / 2 ? 255 : 128), uint8_t(0), uint8_t(255)})
                halves->rgba.push_back(c);
    const float width = 0.1f;
    Material m;
    m.name = "vrm";
    m.diffuse = glm::vec3(1.0f);
    m.mtoon = {{"shade-color", {0, 1, 0}},
               {"outline-width-mode", {1}},
               {"outline-width", {width}},
               {"outline-color", {0, 0, 1}},
               {"outline-lighting-mix", {0}}};
    m.mtoon_textures = {{"outline-width-multiply-texture", halves}};
    ShadingSelection s;
    s.model = "mtoon";
    s.base_color = {0, 1, 0};
    s.params = {{"shadows", {0}}};
    Light light = directional_light({0, 0, 1}, glm::vec3(1), glm::vec3(0));
    light.intensity = kPi;
    RenderOptions o;
    o.width = o.height = kSize;
    const Image img = render_ortho(sphere_with(m), light, s, o);
    const float px_per_unit = float(kSize) / ortho_camera().ortho_height;
    const glm::vec2 centre(0.5f * kSize, 0.5f * kSize);
    for (float degrees : {-30.0f, 30.0f}) {
        const float right = glm::radians(degrees), left = kPi + glm::radians(degrees);
        const Ring r = ring_along(img, centre, right), l = ring_along(img, centre, left);
        EXPECT_NEAR(r.inner, px_per_unit, 1.0f) << degrees;
        EXPECT_NEAR(l.inner, px_per_unit, 1.0f) << degrees;
        EXPECT_NEAR(r.outer, (1.0f + width * 128.0f / 255.0f) * px_per_unit, 1.0f) << degrees;
        EXPECT_NEAR(l.outer, (1.0f + width) * px_per_unit, 1.0f) << degrees;
    }
}

}  // namespace
}  // namespace inkshade::test
