// A VRM material's shade multiply, shading shift, emissive and normal maps and its UV animation
// against three-vrm 3.x's mtoon.frag (and three.js r151+'s tangent frame for a mesh without
// tangents), evaluated on the CPU at pixel centres: on the unit sphere with planar uvs
// (u = (x + 1)/2, v = (y + 1)/2) and on the square [-1, 1]^2 in the z = 0 plane with the same
// uvs. Textures are read as GL reads them (bilinear, repeat), colour ones decoded from sRGB first
// (three-vrm marks the shading shift texture sRGB too), data ones (normal map, UV animation mask)
// as stored.
#include <cmath>
#include <functional>
#include <memory>

#include "io/texture_transform.hpp"
#include "render/render_fixture.hpp"

namespace inkshade::test {
namespace {

constexpr int kTexels = 32;

float srgb_decode(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

// A kTexels^2 texture whose texel (x, y) (row y from the top) is rgb(x, y) in 0-1, alpha 1.
std::shared_ptr<Texture> texture(const std::function<glm::vec3(int, int)>& rgb) {
    auto t = std::make_shared<Texture>();
    t->source = "test";
    t->width = t->height = kTexels;
    for (int y = 0; y < kTexels; ++y)
        for (int x = 0; x < kTexels; ++x) {
            const glm::vec3 c = rgb(x, y);
            for (float v : {c.r, c.g, c.b, 1.0f}) t->rgba.push_back(uint8_t(std::lround(255.0f * v)));
        }
    return t;
}

// Smooth and periodic across the texture's edges (repeat wrapping has no seam), different in
// each channel: a wave across, a wave down, and both.
std::shared_ptr<Texture> waves(float phase = 0.0f) {
    return texture([phase](int x, int y) {
        const float a = 2.0f * kPi * float(x) / kTexels + phase, b = 2.0f * kPi * float(y) / kTexels;
        return glm::vec3(0.5f + 0.4f * std::sin(a), 0.5f + 0.4f * std::cos(b), 0.5f + 0.3f * std::sin(a + b));
    });
}

// GL's bilinear read with repeat wrapping at texture coordinates st (row 0 at t = 0); each texel
// decoded from sRGB first when `srgb`.
glm::vec3 sample(const Texture& tex, glm::vec2 st, bool srgb) {
    const float x = st.x * float(tex.width) - 0.5f, y = st.y * float(tex.height) - 0.5f;
    const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    const float fx = x - float(x0), fy = y - float(y0);
    auto texel = [&](int i, int j) {
        i = ((i % tex.width) + tex.width) % tex.width;
        j = ((j % tex.height) + tex.height) % tex.height;
        const uint8_t* p = &tex.rgba[size_t(4 * (j * tex.width + i))];
        glm::vec3 c(p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f);
        return srgb ? glm::vec3(srgb_decode(c.r), srgb_decode(c.g), srgb_decode(c.b)) : c;
    };
    return glm::mix(glm::mix(texel(x0, y0), texel(x0 + 1, y0), fx),
                    glm::mix(texel(x0, y0 + 1), texel(x0 + 1, y0 + 1), fx), fy);
}

// The texture coordinates of a point of the sphere or the square: (u, 1 - v), three.js's uv.
glm::vec2 st_of(const glm::vec3& p) { return {0.5f * p.x + 0.5f, 1.0f - (0.5f * p.y + 0.5f)}; }

// three-vrm's UV animation (mtoon.frag's main) at `time`: scroll by speed x time x mask, then
// turn about (0.5, 0.5) by rotation speed x time x mask, mask the mask texture's blue channel.
struct UvAnimation {
    float scroll_x = 0.0f, scroll_y = 0.0f, rotation = 0.0f;
    const Texture* mask = nullptr;
};
glm::vec2 animated(glm::vec2 st, const UvAnimation& a, float time) {
    const float mask = a.mask ? sample(*a.mask, st, false).b : 1.0f;
    st += glm::vec2(a.scroll_x, a.scroll_y) * (time * mask);
    const float phase = a.rotation * time * mask, c = std::cos(phase), s = std::sin(phase);
    const glm::vec2 d = st - 0.5f;
    return glm::vec2(c * d.x + s * d.y, -s * d.x + c * d.y) + 0.5f;  // GLSL mat2(c, -s, s, c) * d
}

// What the shader reads at a point besides its normal.
struct Look {
    glm::vec3 C{0.8f, 0.7f, 0.6f}, shade{0.3f, 0.2f, 0.4f}, emissive{0.0f};
    float toony = 0.5f, shift = -0.1f;
};

// mtoon.frag without rim (parametricRimColorFactor 0, no matcap) under a directional light, in
// linear light, then the sRGB encode: n the shading normal, S and shift already with their
// textures, emit the emission with its texture.
glm::vec3 three_vrm(const Look& k, const Light& light, const glm::vec3& n, const glm::vec3& S, float shift,
                    const glm::vec3& C, const glm::vec3& emit) {
    const glm::vec3 l = glm::normalize(light.position - light.target);
    const glm::vec3 E = light.color * light.intensity, A = light.ambient;
    const float a = -1.0f + k.toony, b = 1.0f - k.toony;
    const float t = std::clamp((std::clamp(glm::dot(n, l), -1.0f, 1.0f) + shift - a) / (b - a), 0.0f, 1.0f);
    return reference_srgb(E / kPi * glm::mix(S, C, t) + A / kPi * C + emit);
}

ShadingSelection selection(const Look& k) {
    ShadingSelection s;
    s.model = "mtoon";
    s.base_color = k.C;
    s.params = {{"shade-color", {k.shade.r, k.shade.g, k.shade.b}},
                {"shading-toony", {k.toony}},
                {"shading-shift", {k.shift}},
                {"rim-color", {0, 0, 0}},
                {"shadows", {0}}};
    return s;
}

Light key_light() {
    Light l = directional_light({0.5f, 0.8f, 1.0f}, glm::vec3(1.0f, 0.95f, 0.9f), glm::vec3(0.3f, 0.3f, 0.35f));
    l.intensity = 2.0f;
    return l;
}

Mesh with_material(Mesh mesh, const Material& m) {
    mesh.uvs.clear();
    for (const glm::vec3& p : mesh.positions) mesh.uvs.push_back(0.5f * (glm::vec2(p) + 1.0f));
    mesh.materials = {m};
    mesh.face_materials.assign(mesh.triangles.size(), 0);
    return mesh;
}

// The square [-1, 1]^2 at z = 0 facing +z, two triangles.
Mesh square() {
    Mesh m;
    m.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    m.normals.assign(4, glm::vec3(0, 0, 1));
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    return m;
}

RenderOptions options() {
    RenderOptions o;
    o.width = o.height = kSize;
    o.samples = 1;
    return o;
}

// Compares the pixels of a 24 x 24 grid whose centre's point `at` gives (nullopt: skip) with
// expected(point) within 2/255; returns how many were compared.
int compare_grid(const Image& img, const Camera& cam, const std::function<std::optional<glm::vec3>(glm::vec3)>& at,
                 const std::function<glm::vec3(const glm::vec3&)>& expected, const std::string& what) {
    int compared = 0;
    for (int gy = 0; gy < 24; ++gy)
        for (int gx = 0; gx < 24; ++gx) {
            const int px = 8 + gx * 10, py = 8 + gy * 10;
            const std::optional<glm::vec3> p = at(ray_origin(cam, px + 0.5f, py + 0.5f));
            if (!p) continue;
            const glm::vec3 want = expected(*p);
            const uint8_t* got = img.pixel(px, py);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(int(got[c]), to_byte(want[c]), 2)
                    << what << " pixel (" << px << "," << py << ") channel " << c << " at (" << p->x << "," << p->y
                    << "," << p->z << ")";
            ++compared;
        }
    return compared;
}

// The sphere's point under a pixel, away from the outline.
std::optional<glm::vec3> on_sphere(const glm::vec3& origin) {
    const auto n = sphere_normal(origin);
    return n && n->z > 0.3f ? n : std::nullopt;
}
// The square's point under a pixel, a little inside its edges.
std::optional<glm::vec3> on_square(const glm::vec3& origin) {
    if (std::abs(origin.x) > 0.97f || std::abs(origin.y) > 0.97f) return std::nullopt;
    return glm::vec3(origin.x, origin.y, 0.0f);
}

// shadeMultiplyTexture multiplies the shade colour, shadingShiftTexture's red channel times its
// scale adds to the shift (read as sRGB, as three-vrm marks it), and emissive x intensity x
// emissiveTexture adds to the result.
TEST(MtoonMaps, ShadeMultiplyShadingShiftAndEmissiveFollowThreeVrm) {
    const Look k;
    const auto shade_tex = waves(0.0f), shift_tex = waves(1.0f), emissive_tex = waves(2.0f);
    const float scale = 0.6f, intensity = 1.5f;
    const glm::vec3 emissive(0.15f, 0.1f, 0.05f);
    Material m;
    m.name = "vrm";
    m.diffuse = glm::vec3(1.0f);
    m.mtoon = {{"shading-shift-texture-scale", {scale}},
               {"emissive", {emissive.r, emissive.g, emissive.b}},
               {"emissive-intensity", {intensity}}};
    m.mtoon_textures = {{"shade-multiply-texture", shade_tex},
                        {"shading-shift-texture", shift_tex},
                        {"emissive-texture", emissive_tex}};
    const Light light = key_light();
    const Image img = render_ortho(with_material(fine_sphere(), m), light, selection(k), options());

    int shift_srgb_matters = 0, shade_matters = 0, emission_matters = 0;
    auto expected = [&](const glm::vec3& n) {
        const glm::vec2 st = st_of(n);
        const glm::vec3 S = k.shade * sample(*shade_tex, st, true);
        const float shift = k.shift + sample(*shift_tex, st, true).r * scale;
        const glm::vec3 emit = emissive * intensity * sample(*emissive_tex, st, true);
        const glm::vec3 want = three_vrm(k, light, n, S, shift, k.C, emit);
        const float linear_shift = k.shift + sample(*shift_tex, st, false).r * scale;
        shift_srgb_matters +=
            std::abs(to_byte(three_vrm(k, light, n, S, linear_shift, k.C, emit).g) - to_byte(want.g)) > 4;
        shade_matters += std::abs(to_byte(three_vrm(k, light, n, k.shade, shift, k.C, emit).b) - to_byte(want.b)) > 4;
        emission_matters += std::abs(to_byte(three_vrm(k, light, n, S, shift, k.C, {}).r) - to_byte(want.r)) > 4;
        return want;
    };
    const int compared =
        compare_grid(img, ortho_camera(), on_sphere, expected, "shade multiply, shading shift, emissive");
    EXPECT_GE(compared, 250);
    // Each texture, and the shift texture's colour space, changes many pixels: the test sees them.
    EXPECT_GE(shift_srgb_matters, compared / 5);
    EXPECT_GE(shade_matters, compared / 5);
    EXPECT_GE(emission_matters, compared / 3);
}

// three.js's getTangentFrame for a mesh without tangents (normal_fragment_begin, r151+), from the
// screen-space derivatives q0 = dp/dx, q1 = dp/dy (window y up) and st0, st1 of the texture
// coordinates, with GLTFLoader's normalScale (scale, -scale) for such a mesh.
glm::vec3 tangent_frame_normal(const glm::vec3& N, const glm::vec3& q0, const glm::vec3& q1, const glm::vec2& st0,
                               const glm::vec2& st1, const glm::vec3& texel, float scale) {
    const glm::vec3 q1perp = glm::cross(q1, N), q0perp = glm::cross(N, q0);
    const glm::vec3 T = q1perp * st0.x + q0perp * st1.x, B = q1perp * st0.y + q0perp * st1.y;
    const float s = 1.0f / std::sqrt(std::max(glm::dot(T, T), glm::dot(B, B)));
    glm::vec3 m = texel * 2.0f - 1.0f;
    m.x *= scale;
    m.y *= -scale;
    return glm::normalize(T * s * m.x + B * s * m.y + N * m.z);
}

// The normal map on the square: the frame is (x, -y, z) in world space, so with GLTFLoader's
// flipped y a texel's green tilts the normal up the image, as glTF's tangent space has it.
TEST(MtoonMaps, NormalMapOnTheSquareFollowsThreeJsTangentFrame) {
    Look k;
    k.toony = 0.0f;  // a smooth ramp: every tilt of the normal shows
    k.shade = glm::vec3(0.05f);
    const auto normals = waves(0.5f);
    const float scale = 0.8f;
    Material m;
    m.name = "vrm";
    m.diffuse = glm::vec3(1.0f);
    m.mtoon = {{"normal-scale", {scale}}};
    m.mtoon_textures = {{"normal-texture", normals}};
    const Light light = key_light();
    const Image img = render_ortho(with_material(square(), m), light, selection(k), options());
    int y_flip_matters = 0;
    const float h = 1.0f;  // the frame does not depend on the pixel size
    auto normal_at = [&](const glm::vec3& p, float flip) {
        const glm::vec3 texel = sample(*normals, st_of(p), false);
        return tangent_frame_normal({0, 0, 1}, {h, 0, 0}, {0, h, 0}, {h / 2, 0}, {0, -h / 2}, texel, scale) *
               glm::vec3(1, flip, 1);
    };
    auto expected = [&](const glm::vec3& p) {
        const glm::vec3 want = three_vrm(k, light, normal_at(p, 1.0f), k.shade, k.shift, k.C, {});
        y_flip_matters += std::abs(to_byte(three_vrm(k, light, normal_at(p, -1.0f), k.shade, k.shift, k.C, {}).g) -
                                   to_byte(want.g)) > 4;
        return want;
    };
    // The frame itself: T along +x, B along -y, so the normal is (s x, s y, z) normalised.
    const glm::vec3 texel(0.7f, 0.6f, 0.9f), mapped = glm::normalize(glm::vec3(0.4f * scale, 0.2f * scale, 0.8f));
    const glm::vec3 frame = tangent_frame_normal({0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {0.5f, 0}, {0, -0.5f}, texel, scale);
    EXPECT_NEAR(glm::distance(frame, mapped), 0.0f, 1e-5f);
    const int compared = compare_grid(img, ortho_camera(), on_square, expected, "normal map on the square");
    EXPECT_GE(compared, 350);
    EXPECT_GE(y_flip_matters, compared / 4) << "the normal map's y direction hardly shows";
}

// The normal map on the sphere: the frame from the analytic derivatives of the point
// p = (x, y, sqrt(1 - x^2 - y^2)) and of st under the orthographic camera.
TEST(MtoonMaps, NormalMapOnTheSphereFollowsThreeJsTangentFrame) {
    Look k;
    k.toony = 0.0f;
    k.shade = glm::vec3(0.05f);
    const auto normals = waves(0.5f);
    const float scale = 1.0f;
    Material m;
    m.name = "vrm";
    m.diffuse = glm::vec3(1.0f);
    m.mtoon = {{"normal-scale", {scale}}};
    m.mtoon_textures = {{"normal-texture", normals}};
    const Light light = key_light();
    const Image img = render_ortho(with_material(fine_sphere(), m), light, selection(k), options());
    int differs = 0;
    auto expected = [&](const glm::vec3& n) {
        const glm::vec3 q0(1, 0, -n.x / n.z), q1(0, 1, -n.y / n.z);
        const glm::vec3 texel = sample(*normals, st_of(n), false);
        const glm::vec3 mapped = tangent_frame_normal(n, q0, q1, {0.5f, 0}, {0, -0.5f}, texel, scale);
        const glm::vec3 want = three_vrm(k, light, mapped, k.shade, k.shift, k.C, {});
        differs += std::abs(to_byte(three_vrm(k, light, n, k.shade, k.shift, k.C, {}).g) - to_byte(want.g)) > 4;
        return want;
    };
    const int compared = compare_grid(img, ortho_camera(), on_sphere, expected, "normal map on the sphere");
    EXPECT_GE(compared, 250);
    EXPECT_GE(differs, compared / 3) << "the normal map hardly changes the picture";
}

// The square filling the image (2 units high, 256 pixels: 8 pixels a texel) lit head on with
// E = pi and no ambient, so that t = 1 and each pixel is the base texture as stored.
Camera filling_camera() {
    Camera c = ortho_camera();
    c.ortho_height = 2.0f;
    return c;
}
Light head_on() {
    Light l = directional_light({0, 0, 1}, glm::vec3(1.0f), glm::vec3(0.0f));
    l.intensity = kPi;
    return l;
}

Image render_at(const Mesh& mesh, const ShadingSelection& s, float time) {
    Renderer& r = shared_renderer();
    r.set_mesh(mesh);
    RenderOptions o = options();
    o.time = time;
    return r.render(filling_camera(), head_on(), s, o);
}

// The pixel of the base texture read at `st`, under head_on().
glm::vec3 texture_pixel(const Texture& tex, glm::vec2 st) { return reference_srgb(sample(tex, st, true)); }

// Scrolling: the picture moves by speed x time of the texture, 4 texels here (32 pixels), with
// the speeds of the style (--set) on a mesh with a plain base-colour texture.
TEST(MtoonMaps, UvAnimationScrollsTheTexturesBySpeedTimesTime) {
    const auto tex = waves(0.3f);
    Material m;
    m.name = "textured";
    m.diffuse = glm::vec3(1.0f);
    m.texture = tex;
    const Mesh mesh = with_material(square(), m);
    Look k;
    k.C = glm::vec3(1.0f);
    k.toony = 0.9f;
    ShadingSelection s = selection(k);
    s.params["uv-animation-scroll-x-speed"] = {0.125f};  // uv units a second
    s.params["uv-animation-scroll-y-speed"] = {-0.25f};
    const Image still = render_at(mesh, s, 0.0f), moved = render_at(mesh, s, 1.0f);
    // At time 1 a pixel shows what the one 4 texels right of it and 8 texels up showed at 0 (st.y
    // grows down the image: -0.25 reads a quarter of the texture higher up).
    int compared = 0;
    for (int y = 16; y < kSize - 16; y += 7)
        for (int x = 8; x < kSize - 40; x += 7) {
            const int sy = y - 64;
            if (sy < 4) continue;
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(int(moved.pixel(x, y)[c]), int(still.pixel(x + 32, sy)[c]), 1)
                    << "pixel (" << x << "," << y << ") channel " << c;
            ++compared;
        }
    EXPECT_GE(compared, 300);
    const UvAnimation a{0.125f, -0.25f, 0.0f, nullptr};
    compare_grid(
        moved, filling_camera(), on_square,
        [&](const glm::vec3& p) { return texture_pixel(*tex, animated(st_of(p), a, 1.0f)); }, "scrolled");
}

// KHR_texture_transform on the base colour texture (Material::uv_transforms): the matrix
// GLTFLoader gives three-vrm (scale, rotate, then offset) applied to the animated uv, here with a
// scroll at time 1 so the order shows.
TEST(MtoonMaps, TextureTransformMovesTheAnimatedUvAsThreeJs) {
    const auto tex = waves(0.3f);
    Material m;
    m.name = "textured";
    m.diffuse = glm::vec3(1.0f);
    m.texture = tex;
    const glm::mat3 t = io::uv_transform(0.1, -0.2, 0.4, 1.5, 0.75);
    m.uv_transforms["base-color-texture"] = t;
    Look k;
    k.C = glm::vec3(1.0f);
    k.toony = 0.9f;
    ShadingSelection s = selection(k);
    s.params["uv-animation-scroll-x-speed"] = {0.125f};
    const Image img = render_at(with_material(square(), m), s, 1.0f);
    const UvAnimation a{0.125f, 0.0f, 0.0f, nullptr};
    int differs = 0;
    const int compared = compare_grid(
        img, filling_camera(), on_square,
        [&](const glm::vec3& p) {
        const glm::vec2 st = animated(st_of(p), a, 1.0f);
        const glm::vec3 want = texture_pixel(*tex, glm::vec2(t * glm::vec3(st, 1.0f)));
        differs += glm::length(want - texture_pixel(*tex, st)) > 0.1f;
        return want;
        },
        "texture transform");
    EXPECT_GE(differs, compared / 3) << "the transform hardly changes the picture: the test proves little";
}

// Rotation about the uv centre (0.5, 0.5) by rotation speed x time radians, and the mask
// texture's blue channel scaling both where it is not 1: 0 on the right half stops them there.
// The speeds and the mask come with the material (a VRM material's).
TEST(MtoonMaps, UvAnimationTurnsAboutTheUvCentreAndTheMaskStopsIt) {
    const auto tex = waves(0.3f);
    auto mask = texture([](int x, int) { return glm::vec3(0.0f, 0.0f, x < kTexels / 2 ? 1.0f : 0.0f); });
    Material m;
    m.name = "vrm";
    m.diffuse = glm::vec3(1.0f);
    m.texture = tex;
    m.mtoon = {{"uv-animation-rotation-speed", {0.4f}}, {"uv-animation-scroll-x-speed", {0.05f}}};
    m.mtoon_textures = {{"uv-animation-mask-texture", mask}};
    Look k;
    k.C = glm::vec3(1.0f);
    k.toony = 0.9f;
    const ShadingSelection s = selection(k);
    const float time = 1.5f;
    const UvAnimation a{0.05f, 0.0f, 0.4f, mask.get()};
    const Image still = render_at(with_material(square(), m), s, 0.0f);
    const Image turned = render_at(with_material(square(), m), s, time);
    int stopped = 0, moved = 0;
    const int compared = compare_grid(
        turned, filling_camera(), on_square,
        [&](const glm::vec3& p) {
        const glm::vec2 st = st_of(p);
        const glm::vec3 want = texture_pixel(*tex, animated(st, a, time));
        if (st.x > 0.5f + 2.0f / kTexels) {
            ++stopped;  // masked: as at time 0
            EXPECT_EQ(to_byte(want.r), to_byte(texture_pixel(*tex, st).r));
        } else {
            moved += std::abs(to_byte(want.r) - to_byte(texture_pixel(*tex, st).r)) > 8;
        }
        return want;
        },
        "turned and masked");
    EXPECT_GE(compared, 500);
    EXPECT_GE(stopped, 150);
    EXPECT_GE(moved, 100);
    // Without the mask every pixel turns; time 0 is the texture as it is.
    compare_grid(
        still, filling_camera(), on_square, [&](const glm::vec3& p) { return texture_pixel(*tex, st_of(p)); },
        "time 0");
    Material unmasked = m;
    unmasked.mtoon_textures.clear();
    const UvAnimation everywhere{0.05f, 0.0f, 0.4f, nullptr};
    compare_grid(
        render_at(with_material(square(), unmasked), s, time), filling_camera(), on_square,
        [&](const glm::vec3& p) { return texture_pixel(*tex, animated(st_of(p), everywhere, time)); }, "unmasked");
}

}  // namespace
}  // namespace inkshade::test
