// A glTF texture is read as its sampler says, as three.js's GLTFLoader sets the texture up:
// wrapS/wrapT (REPEAT, CLAMP_TO_EDGE, MIRRORED_REPEAT), magFilter NEAREST or LINEAR, mipmaps only
// when minFilter names them, no anisotropy. A quad with uvs over [0, 2]^2 shows a 2 x 2 texture
// magnified to 33 px a texel; every third pixel is compared within 2/255 with OpenGL's sampling
// rules (the OpenGL 4.6 specification, section 8.14, "Texture Minification" and "Magnification")
// evaluated on the CPU: the texel nearest, or the bilinear mix of the four around the point, each
// texel index wrapped as the mode says.
#include <cmath>

#include "inkshade/io.hpp"
#include "inkshade/shading.hpp"
#include "io/gltf_files.hpp"
#include "render/render_fixture.hpp"
#include "support/temp_dir.hpp"

namespace inkshade::test {
namespace {

constexpr int kGl_Nearest = 9728, kGl_Linear = 9729, kGl_LinearMipmapLinear = 9987;
constexpr int kGl_Repeat = 10497, kGl_Clamp = 33071, kGl_Mirrored = 33648;
constexpr int kImage = 132;  // the unit quad; 66 px a uv unit, 33 px a texel

// The quad [0, 1]^2 (z = 0, facing +z) with glTF uvs (t down) over [0, 2]^2, white material,
// kTexturePixels (red, green / blue, white) as its texture with the given sampler.
std::string sampled_quad(const nlohmann::json& sampler) {
    GltfBuilder g;
    int pos = g.floats({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, "VEC3", 3);
    int uv = g.floats({0, 2, 2, 2, 2, 0, 0, 0}, "VEC2", 2);
    int idx = g.data(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}, kUShort, 1, "SCALAR");
    int tex = g.texture_in_buffer(png_bytes(2, 2, kTexturePixels));
    if (!sampler.is_null()) {
        g.doc["samplers"].push_back(sampler);
        g.doc["textures"][size_t(tex)]["sampler"] = 0;
    }
    int mat = g.material({1, 1, 1, 1}, tex);
    int mesh = g.mesh({{"POSITION", pos}, {"TEXCOORD_0", uv}}, idx, mat);
    g.scene({g.node({{"mesh", mesh}})});
    return g.glb();
}

// A texel index wrapped into [0, n) as OpenGL wraps it.
int wrapped(int i, int n, int mode) {
    if (mode == kGl_Clamp) return std::clamp(i, 0, n - 1);
    if (mode == kGl_Mirrored) {
        const int period = ((i % (2 * n)) + 2 * n) % (2 * n);
        return period < n ? period : 2 * n - 1 - period;
    }
    return ((i % n) + n) % n;
}

glm::vec3 texel(int x, int y) {
    const uint8_t* p = &kTexturePixels[size_t(4 * (2 * y + x))];
    return glm::vec3(p[0], p[1], p[2]) / 255.0f;
}

// OpenGL's magnified read of the 2 x 2 texture at glTF uv (s, t).
glm::vec3 sample(float s, float t, bool nearest, int wrap_s, int wrap_t) {
    const float x = s * 2.0f, y = t * 2.0f;  // texel space
    if (nearest) return texel(wrapped(int(std::floor(x)), 2, wrap_s), wrapped(int(std::floor(y)), 2, wrap_t));
    const float u = x - 0.5f, v = y - 0.5f;
    const int i0 = int(std::floor(u)), j0 = int(std::floor(v));
    const float a = u - float(i0), b = v - float(j0);
    const int i[2] = {wrapped(i0, 2, wrap_s), wrapped(i0 + 1, 2, wrap_s)};
    const int j[2] = {wrapped(j0, 2, wrap_t), wrapped(j0 + 1, 2, wrap_t)};
    return (1 - a) * (1 - b) * texel(i[0], j[0]) + a * (1 - b) * texel(i[1], j[0]) + (1 - a) * b * texel(i[0], j[1]) +
           a * b * texel(i[1], j[1]);
}

Image render_quad(const std::string& glb) {
    TempDir dir;
    Renderer& r = shared_renderer();
    r.set_mesh(load_mesh(dir.write("quad.glb", glb)));
    Camera cam = ortho_camera();
    cam.eye = {0.5f, 0.5f, 5.0f};
    cam.target = {0.5f, 0.5f, 0.0f};
    cam.ortho_height = 1.0f;
    RenderOptions o;
    o.width = o.height = kImage;
    o.samples = 1;
    return r.render(cam, ambient_only(), ShadingSelection{}, o);
}

// Compares every third pixel; returns how many differ from the other filter's read by more
// than 8/255 (so that each case shows what it tests).
int compare(const Image& img, bool nearest, int wrap_s, int wrap_t, const std::string& what) {
    int telling = 0;
    for (int py = 1; py < kImage; py += 3)
        for (int px = 1; px < kImage; px += 3) {
            const float s = 2.0f * (float(px) + 0.5f) / kImage, t = 2.0f * (float(py) + 0.5f) / kImage;
            const glm::vec3 want = sample(s, t, nearest, wrap_s, wrap_t);
            const glm::vec3 other = sample(s, t, !nearest, wrap_s, wrap_t);
            if (glm::length(want - other) * 255.0f > 8.0f) ++telling;
            for (int k = 0; k < 3; ++k)
                EXPECT_NEAR(int(img.pixel(px, py)[k]), to_byte(want[k]), 2)
                    << what << " at " << px << "," << py << " channel " << k;
            if (::testing::Test::HasFailure()) return telling;  // one pixel's report is enough
        }
    return telling;
}

TEST(TextureSampler, NearestMagnificationClampedReadsWholeTexels) {
    const Image img = render_quad(sampled_quad(
        {{"magFilter", kGl_Nearest}, {"minFilter", kGl_Nearest}, {"wrapS", kGl_Clamp}, {"wrapT", kGl_Clamp}}));
    EXPECT_GT(compare(img, true, kGl_Clamp, kGl_Clamp, "nearest, clamp"), 500);
}

TEST(TextureSampler, LinearMagnificationMirroredAndRepeat) {
    const Image img = render_quad(sampled_quad(
        {{"magFilter", kGl_Linear}, {"minFilter", kGl_Linear}, {"wrapS", kGl_Mirrored}, {"wrapT", kGl_Repeat}}));
    EXPECT_GT(compare(img, false, kGl_Mirrored, kGl_Repeat, "linear, mirrored x repeat"), 500);
}

// No sampler, or one without filters: magnify LINEAR, minify LINEAR_MIPMAP_LINEAR, REPEAT
// (three.js's defaults for a glTF texture).
TEST(TextureSampler, AbsentSamplerIsLinearRepeat) {
    compare(render_quad(sampled_quad(nullptr)), false, kGl_Repeat, kGl_Repeat, "no sampler");
    compare(render_quad(sampled_quad({{"minFilter", kGl_LinearMipmapLinear}})), false, kGl_Repeat, kGl_Repeat,
            "sampler without magFilter");
}

// One image under two samplers: each texture reads it its own way.
TEST(TextureSampler, TexturesSharingAnImageKeepTheirOwnSamplers) {
    Mesh mesh;
    {
        GltfBuilder g;
        int pos = g.floats({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, "VEC3", 3);
        int uv = g.floats({0, 2, 2, 2, 2, 0, 0, 0}, "VEC2", 2);
        int idx = g.data(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}, kUShort, 1, "SCALAR");
        int tex = g.texture_in_buffer(png_bytes(2, 2, kTexturePixels));
        g.doc["textures"].push_back({{"source", 0}, {"sampler", 0}});
        g.doc["samplers"].push_back({{"magFilter", kGl_Nearest}, {"wrapS", kGl_Clamp}});
        int a = g.material({1, 1, 1, 1}, tex), b = g.material({1, 1, 1, 1}, tex + 1);
        int mesh_a = g.mesh({{"POSITION", pos}, {"TEXCOORD_0", uv}}, idx, a);
        int mesh_b = g.mesh({{"POSITION", pos}, {"TEXCOORD_0", uv}}, idx, b);
        g.scene({g.node({{"mesh", mesh_a}}), g.node({{"mesh", mesh_b}, {"translation", {2, 0, 0}}})});
        TempDir dir;
        mesh = load_mesh(dir.write("two.glb", g.glb()));
    }
    ASSERT_EQ(mesh.materials.size(), 2u);
    const Texture& a = *mesh.materials[0].texture;
    const Texture& b = *mesh.materials[1].texture;
    EXPECT_EQ(a.sampler.mag, TextureFilter::Linear);
    EXPECT_EQ(a.sampler.wrap_s, TextureWrap::Repeat);
    EXPECT_FALSE(a.sampler.anisotropic);
    EXPECT_EQ(b.sampler.mag, TextureFilter::Nearest);
    EXPECT_EQ(b.sampler.wrap_s, TextureWrap::ClampToEdge);
    EXPECT_EQ(b.sampler.wrap_t, TextureWrap::Repeat);
    EXPECT_EQ(b.sampler.mipmap, std::optional<TextureFilter>(TextureFilter::Linear));
    EXPECT_EQ(a.rgba, b.rgba);
}

}  // namespace
}  // namespace inkshade::test
