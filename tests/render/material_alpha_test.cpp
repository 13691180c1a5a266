// glTF alpha modes and double-sided materials as three.js r187 draws a GLTFLoader material:
// MASK keeps a fragment where baseColorFactor.a x texture alpha >= alphaCutoff (alphaTest),
// BLEND composites "over" (NormalBlending) after the opaque materials, back to front or by
// renderOrder, and a DoubleSide material lights its back faces with the normal negated. The
// expected pixels come from the CPU (the texture's bilinear alpha, the blend equation) or from
// renders of the same surfaces drawn opaque.
#include <cmath>
#include <memory>

#include "render/render_fixture.hpp"

namespace inkshade::test {
namespace {

constexpr int kTexels = 32;

// A quad over [x0, x1] x [y0, y1] at height z, uvs (x + 1)/2, (y + 1)/2, one material; facing +z
// (counter-clockwise seen from the camera) unless `away`; vertex normals `normal`.
Mesh quad(float x0, float x1, float y0, float y1, float z, uint32_t material, bool away = false,
          glm::vec3 normal = {0, 0, 1}) {
    Mesh m;
    m.positions = {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}};
    m.normals.assign(4, normal);
    for (const glm::vec3& p : m.positions) m.uvs.push_back(0.5f * (glm::vec2(p) + 1.0f));
    m.triangles = away ? std::vector<glm::uvec3>{{0, 2, 1}, {0, 3, 2}} : std::vector<glm::uvec3>{{0, 1, 2}, {0, 2, 3}};
    m.face_materials.assign(2, material);
    return m;
}

// Appends b's geometry to a (materials by index).
Mesh join(Mesh a, const Mesh& b) {
    const uint32_t base = uint32_t(a.positions.size());
    a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
    a.normals.insert(a.normals.end(), b.normals.begin(), b.normals.end());
    a.uvs.insert(a.uvs.end(), b.uvs.begin(), b.uvs.end());
    for (const glm::uvec3& t : b.triangles) a.triangles.push_back(t + base);
    a.face_materials.insert(a.face_materials.end(), b.face_materials.begin(), b.face_materials.end());
    return a;
}

Material material(glm::vec3 colour, AlphaMode mode, float alpha = 1.0f, FaceSides sides = FaceSides::Front) {
    Material m;
    m.name = "gltf";
    m.diffuse = colour;
    m.alpha = alpha;
    m.alpha_mode = mode;
    m.sides = sides;
    return m;
}

// kTexels x 4 texels, white, alpha rising across from 0 to 255.
std::shared_ptr<Texture> alpha_ramp() {
    auto t = std::make_shared<Texture>();
    t->source = "alpha ramp";
    t->width = kTexels;
    t->height = 4;
    for (int y = 0; y < t->height; ++y)
        for (int x = 0; x < kTexels; ++x)
            for (uint8_t c :
                 {uint8_t(255), uint8_t(255), uint8_t(255), uint8_t(std::lround(255.0f * x / (kTexels - 1)))})
                t->rgba.push_back(c);
    return t;
}

// GL's bilinear read of the ramp's alpha at s, repeating (the texture's wrap mode).
float ramp_alpha(float s) {
    const float x = s * kTexels - 0.5f;
    const int x0 = int(std::floor(x));
    const float f = x - float(x0);
    auto texel = [](int i) {
        i = ((i % kTexels) + kTexels) % kTexels;
        return float(std::lround(255.0f * i / (kTexels - 1))) / 255.0f;
    };
    return (1.0f - f) * texel(x0) + f * texel(x0 + 1);
}

ShadingSelection model(const std::string& name) {
    ShadingSelection s;
    s.model = name;
    if (name == "mtoon") s.params = {{"shadows", {0}}};
    return s;
}

RenderOptions options(glm::vec4 background) {
    RenderOptions o;
    o.width = o.height = kSize;
    o.samples = 1;
    o.background = background;
    return o;
}

Light key_light() { return directional_light({0.3f, 0.5f, 1.0f}, glm::vec3(0.9f), glm::vec3(0.3f)); }

// Pixel centres of the image whose world point lies inside [x0, x1] x [y0, y1] by a margin.
template <class F>
void for_pixels_in(float x0, float x1, float y0, float y1, F&& f) {
    const Camera cam = ortho_camera();
    for (int py = 2; py < kSize; py += 3)
        for (int px = 2; px < kSize; px += 3) {
            const glm::vec3 o = ray_origin(cam, px + 0.5f, py + 0.5f);
            if (o.x > x0 + 0.02f && o.x < x1 - 0.02f && o.y > y0 + 0.02f && o.y < y1 - 0.02f) f(px, py, o);
        }
}

// "alpha MASK cutoff": the fragment stays exactly where baseColorFactor.a x the texture's alpha
// is at least alphaCutoff (three.js: `if (diffuseColor.a < alphaTest) discard`), in every model.
TEST(MaterialAlpha, MaskKeepsPixelsWhereAlphaIsAtLeastTheCutoff) {
    for (const char* name : {"mtoon", "lambert", "threejs-lambert", "gooch", "cel"}) {
        Mesh m = quad(-1, 1, -1, 1, 0, 0);
        Material mat = material({0.2f, 0.6f, 0.4f}, AlphaMode::Mask, 0.9f);
        mat.alpha_cutoff = 0.45f;
        mat.texture = alpha_ramp();
        m.materials = {mat};
        const Image img = render_ortho(m, key_light(), model(name), options(glm::vec4(0)));
        int kept = 0, cut = 0;
        for_pixels_in(-1, 1, -1, 1, [&](int px, int py, const glm::vec3& o) {
            const float alpha = mat.alpha * ramp_alpha(0.5f * (o.x + 1.0f));
            if (std::abs(alpha - mat.alpha_cutoff) < 1.5f / 255.0f) return;  // texel rounding
            const bool keep = alpha >= mat.alpha_cutoff;
            EXPECT_EQ(int(img.pixel(px, py)[3]), keep ? 255 : 0)
                << name << " pixel (" << px << "," << py << ") alpha " << alpha;
            (keep ? kept : cut) += 1;
        });
        EXPECT_GT(kept, 1000) << name;
        EXPECT_GT(cut, 1000) << name;

        // OPAQUE ignores alpha: the whole quad.
        m.materials[0].alpha_mode = AlphaMode::Opaque;
        const Image opaque = render_ortho(m, key_light(), model(name), options(glm::vec4(0)));
        for_pixels_in(-1, 1, -1, 1, [&](int px, int py, const glm::vec3&) {
            EXPECT_EQ(int(opaque.pixel(px, py)[3]), 255) << name << " opaque pixel (" << px << "," << py << ")";
        });
    }
}

// BLEND: drawn after the opaque materials whatever the file order, composited as three.js's
// NormalBlending, out = a * front + (1 - a) * behind, `front` being what the same surface draws
// when opaque; nothing behind it is hidden (no depth written).
TEST(MaterialAlpha, BlendIsCompositedOverWhatIsBehindAfterOpaqueMaterials) {
    const float a = 0.4f;
    for (const char* name : {"mtoon", "lambert", "threejs-phong"}) {
        // The blended quad (material 0, first in the file) in front of the opaque one.
        Mesh scene = join(quad(-1, 0.5f, -1, 1, 0.5f, 0), quad(-0.5f, 1, -1, 1, 0, 1));
        scene.materials = {material({0.1f, 0.2f, 0.9f}, AlphaMode::Blend, a),
                           material({0.9f, 0.3f, 0.1f}, AlphaMode::Opaque)};
        const glm::vec4 white(1.0f);
        const Image blended = render_ortho(scene, key_light(), model(name), options(white));
        Mesh front_opaque = scene;
        front_opaque.materials[0].alpha_mode = AlphaMode::Opaque;
        const Image front = render_ortho(front_opaque, key_light(), model(name), options(white));
        Mesh back_only = quad(-0.5f, 1, -1, 1, 0, 0);
        back_only.materials = {scene.materials[1]};
        const Image behind = render_ortho(back_only, key_light(), model(name), options(white));
        int overlap = 0;
        for_pixels_in(-1, 0.5f, -1, 1, [&](int px, int py, const glm::vec3& o) {
            if (std::abs(o.x + 0.5f) < 0.03f) return;  // the back quad's edge
            overlap += o.x > -0.5f;
            for (int c = 0; c < 3; ++c) {
                const float want = a * front.pixel(px, py)[c] + (1.0f - a) * behind.pixel(px, py)[c];
                EXPECT_NEAR(float(blended.pixel(px, py)[c]), want, 2.0f)
                    << name << " pixel (" << px << "," << py << ") channel " << c;
            }
            EXPECT_EQ(int(blended.pixel(px, py)[3]), 255);
        });
        EXPECT_GT(overlap, 1000) << name;
    }
}

// Blended materials sort back to front (file order is front first here), unless renderOrder
// (three-vrm's render queue) says otherwise; with transparentWithZWrite the first one drawn hides
// the blended one behind it. Lambert lit by the ambient light alone draws exactly C.
TEST(MaterialAlpha, BlendedMaterialsSortBackToFrontThenByRenderOrder) {
    const glm::vec3 F(0.9f, 0.1f, 0.2f), K(0.1f, 0.3f, 0.9f), W(1.0f);
    const float aF = 0.5f, aK = 0.6f;
    Mesh scene = join(quad(-1, 1, -1, 1, 0.5f, 0), quad(-1, 1, -1, 1, 0.0f, 1));
    scene.materials = {material(F, AlphaMode::Blend, aF), material(K, AlphaMode::Blend, aK)};
    auto check = [&](const Mesh& m, glm::vec3 want, const char* what) {
        const Image img = render_ortho(m, ambient_only(), model("lambert"), options(glm::vec4(W, 1.0f)));
        for_pixels_in(-1, 1, -1, 1, [&](int px, int py, const glm::vec3&) {
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(int(img.pixel(px, py)[c]), to_byte(want[c]), 2)
                    << what << " pixel (" << px << "," << py << ") channel " << c;
        });
    };
    const glm::vec3 behind_first = aF * F + (1 - aF) * (aK * K + (1 - aK) * W);
    const glm::vec3 front_first = aK * K + (1 - aK) * (aF * F + (1 - aF) * W);
    ASSERT_GT(glm::length(behind_first - front_first), 0.1f);
    check(scene, behind_first, "back to front");
    scene.materials[0].render_order = -1;  // the front one first
    check(scene, front_first, "render order");
    scene.materials[0].blend_depth_write = true;  // and it hides the one behind
    check(scene, aF * F + (1 - aF) * W, "transparentWithZWrite");
}

// Sides: a glTF single-sided material shows no back faces (three.js FrontSide); a double-sided
// one lights a back face with its normal negated (three.js DoubleSide: normal *= faceDirection),
// exactly as a front face with that normal; Inkshade's default turns the normal towards the
// viewer instead. The quads face away from the camera; their normals point at it (+z), against
// their winding, where the two rules differ.
TEST(MaterialAlpha, DoubleSidedBackFacesAreLitWithTheNegatedNormal) {
    const glm::vec3 C(0.5f, 0.4f, 0.3f);
    const Light light = directional_light({0, 0, 1}, glm::vec3(0.8f), glm::vec3(0.2f));
    for (const char* name : {"mtoon", "lambert", "threejs-lambert"}) {
        auto render = [&](FaceSides sides, bool away, glm::vec3 normal) {
            Mesh m = quad(-1, 1, -1, 1, 0, 0, away, normal);
            m.materials = {material(C, AlphaMode::Opaque, 1.0f, sides)};
            return render_ortho(m, light, model(name), options(glm::vec4(0)));
        };
        const Image single = render(FaceSides::Front, true, {0, 0, 1});
        const Image both = render(FaceSides::Double, true, {0, 0, 1});
        const Image seen = render(FaceSides::Seen, true, {0, 0, 1});
        const Image mirror = render(FaceSides::Seen, false, {0, 0, -1});  // a front face with normal -z
        int differs = 0;
        for_pixels_in(-1, 1, -1, 1, [&](int px, int py, const glm::vec3&) {
            EXPECT_EQ(int(single.pixel(px, py)[3]), 0) << name << " back face of a single-sided material";
            for (int c = 0; c < 4; ++c)
                EXPECT_EQ(int(both.pixel(px, py)[c]), int(mirror.pixel(px, py)[c]))
                    << name << " pixel (" << px << "," << py << ") channel " << c;
            differs += std::abs(int(both.pixel(px, py)[0]) - int(seen.pixel(px, py)[0])) > 8;
            if (std::string(name) == "lambert") {  // C (E max(n.l, 0) + A), n = -z: C A
                EXPECT_NEAR(int(both.pixel(px, py)[0]), to_byte(C.r * 0.2f), 1);
            }
        });
        EXPECT_GT(differs, 1000) << name << ": the rules hardly differ here, the test proves little";
    }
}

}  // namespace
}  // namespace inkshade::test
