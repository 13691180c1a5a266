// Base-colour textures reach C in every model built on common/surface.glsl: read in the frame's
// colour convention (the bytes as stored by default; decoded from sRGB, the output encoded, with
// --srgb and in the three.js and mtoon-threejs conventions), placed by the uvs (v = 0 at the
// image bottom), multiplied by the material and base colours, and mtoon's per-material VRM
// parameters.
#include <cmath>

#include "inkshade/io.hpp"
#include "inkshade/shading.hpp"
#include "io/gltf_files.hpp"
#include "render/render_fixture.hpp"
#include "support/temp_dir.hpp"

namespace inkshade::test {
namespace {

// The sRGB EOTF (IEC 61966-2-1) of a byte: what a GL_SRGB8_ALPHA8 sample returns.
float srgb_decode(uint8_t byte) {
    float c = float(byte) / 255.0f;
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

// The sRGB OETF, the output encode of the linear convention.
float srgb_encode(float c) { return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f; }

// Lit only by ambient A = 1 (E = 0): lambert, flat and mtoon all output exactly C.

RenderOptions single_sample(int size = kSize, bool srgb_output = false) {
    RenderOptions o;
    o.width = o.height = size;
    o.samples = 1;
    o.srgb_output = srgb_output;
    return o;
}

// 4 x 4 distinct colours (cell (col, row), row 0 = the image's top row), each blown up to a
// kBlock x kBlock block, so bilinear filtering near a block's centre returns its exact colour.
constexpr int kCells = 4, kBlock = 8, kTexSize = kCells * kBlock;
glm::u8vec3 cell_color(int col, int row) {
    return {uint8_t(20 + 70 * col), uint8_t(30 + 65 * row), uint8_t(200 - 12 * (4 * row + col))};
}

std::shared_ptr<const Texture> cell_texture() {
    auto t = std::make_shared<Texture>();
    t->source = "cells";
    t->width = t->height = kTexSize;
    for (int y = 0; y < kTexSize; ++y)
        for (int x = 0; x < kTexSize; ++x) {
            glm::u8vec3 c = cell_color(x / kBlock, y / kBlock);
            t->rgba.insert(t->rgba.end(), {c.r, c.g, c.b, 255});
        }
    return t;
}

// The square [-1, 1]^2 in z = 0 facing +z, uvs (0, 0) at the bottom-left to (1, 1) at the
// top-right, split at x = 0 into a left (material 0) and a right (material `right`) half.
Mesh quad(std::vector<Material> materials, uint32_t right = 0) {
    Mesh m;
    m.positions = {{-1, -1, 0}, {0, -1, 0}, {0, 1, 0}, {-1, 1, 0}, {0, -1, 0}, {1, -1, 0}, {1, 1, 0}, {0, 1, 0}};
    for (const glm::vec3& p : m.positions) m.uvs.push_back(0.5f * (glm::vec2(p) + 1.0f));
    m.normals.assign(m.positions.size(), glm::vec3(0, 0, 1));
    m.triangles = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}};
    m.materials = std::move(materials);
    m.face_materials = {0, 0, right, right};
    return m;
}

Material textured(glm::vec3 diffuse = glm::vec3(1.0f)) {
    Material m;
    m.name = "cells";
    m.diffuse = diffuse;
    m.texture = cell_texture();
    return m;
}

// Pixel under the centre of cell (col, row) of the texture on quad() with the test camera.
glm::ivec2 cell_pixel(int col, int row) {
    glm::vec2 uv((col + 0.5f) / kCells, 1.0f - (row + 0.5f) / kCells);
    glm::vec2 p = project(ortho_camera(), glm::vec3(2.0f * uv - 1.0f, 0.0f));
    return glm::ivec2(glm::floor(p));
}

enum class Convention { Display, Linear };

// Every cell's centre pixel is its texel times `tint` in the convention, within `tolerance`/255:
// byte * tint as stored (display), or encode(decode(byte) * tint) (linear).
void expect_cells(const Image& img, glm::vec3 tint, const std::string& what,
                  Convention convention = Convention::Display, int tolerance = 1) {
    for (int row = 0; row < kCells; ++row)
        for (int col = 0; col < kCells; ++col) {
            glm::ivec2 p = cell_pixel(col, row);
            glm::u8vec3 c = cell_color(col, row);
            const uint8_t* got = img.pixel(p.x, p.y);
            for (int k = 0; k < 3; ++k) {
                const float want = convention == Convention::Display ? float(c[k]) / 255.0f * tint[k]
                                                                     : srgb_encode(srgb_decode(c[k]) * tint[k]);
                EXPECT_NEAR(int(got[k]), to_byte(want), tolerance)
                    << what << ": cell (" << col << "," << row << ") at pixel (" << p.x << "," << p.y << ") channel "
                    << k;
            }
        }
}

TEST(Texture, EachTexelAppearsWhereItsUvsPutItAsStored) {
    for (const char* model : {"lambert", "flat", "gouraud"}) {
        ShadingSelection sel;
        sel.model = model;
        Image img = render_ortho(quad({textured()}), ambient_only(), sel, single_sample());
        // Row 0 of the image (the top) lands at v = 1, the top of the quad: not flipped. Display
        // convention: the bytes reach the pixels unchanged (decoding them and writing the
        // linear value unencoded darkened (108,173,223) to (38,106,188)).
        expect_cells(img, glm::vec3(1.0f), model);
    }
}

// The acceptance of the colour conventions: an unlit textured quad comes back texel for texel
// (within 1/255) in each. Unlit: lambert, flat and gouraud under ambient 1 alone; threejs-basic
// (light-independent, linear: decoded, then encoded); mtoon's threejs convention under ambient pi
// (gi = A/pi * C = C).
TEST(Texture, UnlitQuadReproducesItsTexelsInEveryConvention) {
    struct Case {
        const char* model;
        bool srgb_output;
        Convention convention;
        glm::vec3 ambient{1.0f};
        const char* convention_param = nullptr;
    };
    const float pi = 3.14159265f;
    for (const Case& c : {Case{"lambert", false, Convention::Display}, Case{"flat", false, Convention::Display},
                          Case{"gouraud", false, Convention::Display}, Case{"lambert", true, Convention::Linear},
                          Case{"gouraud", true, Convention::Linear}, Case{"threejs-basic", false, Convention::Linear},
                          Case{"threejs-basic", true, Convention::Linear},
                          Case{"mtoon", false, Convention::Linear, glm::vec3(pi), "threejs"},
                          Case{"mtoon", false, Convention::Display, glm::vec3(1.0f), "seeds"}}) {
        ShadingSelection sel;
        sel.model = c.model;
        if (c.convention_param) {
            sel.params["convention"] = {std::string(c.convention_param) == "threejs" ? 1.0f : 0.0f};
            sel.params["shadows"] = {0.0f};
        }
        const Light light = directional_light({0, 0, 1}, glm::vec3(0), c.ambient);
        Image img = render_ortho(quad({textured()}), light, sel, single_sample(kSize, c.srgb_output));
        const std::string what = std::string(c.model) + (c.srgb_output ? " --srgb" : "") +
                                 (c.convention_param ? std::string(" convention=") + c.convention_param : "");
        expect_cells(img, glm::vec3(1.0f), what, c.convention);
        // Both conventions give the texel back, so the two expectations agree within 1.
        expect_cells(img, glm::vec3(1.0f), what + " (as stored)", Convention::Display, 1);
    }
}

TEST(Texture, MultipliesMaterialAndBaseColour) {
    ShadingSelection sel;
    sel.base_color = glm::vec3(1.0f, 0.5f, 1.0f);
    const glm::vec3 diffuse(0.5f, 1.0f, 0.25f);
    Image img = render_ortho(quad({textured(diffuse)}), ambient_only(), sel, single_sample());
    expect_cells(img, diffuse * sel.base_color, "lambert");
    // Linear convention: the decoded texel times the (linear) colours, encoded.
    Image linear = render_ortho(quad({textured(diffuse)}), ambient_only(), sel, single_sample(kSize, true));
    expect_cells(linear, diffuse * sel.base_color, "lambert --srgb", Convention::Linear);
}

TEST(Texture, MtoonUsesTheTexture) {
    ShadingSelection sel;
    sel.model = "mtoon";
    sel.params["shadows"] = {0.0f};
    sel.params["convention"] = {0.0f};  // seeds: the texel as it is
    Image img = render_ortho(quad({textured()}), ambient_only(), sel, single_sample());
    expect_cells(img, glm::vec3(1.0f), "mtoon");  // E = 0: out = A * C
}

TEST(Texture, MaterialWithoutTextureKeepsItsColourExactly) {
    Material plain;
    plain.diffuse = glm::vec3(0.3f, 0.6f, 0.9f);
    ShadingSelection sel;
    Image img = render_ortho(quad({textured(), plain}, 1), ambient_only(), sel, single_sample());
    // The right half is drawn with the white texel: byte for byte what it is without textures.
    Image untextured = render_ortho(quad({plain}), ambient_only(), sel, single_sample());
    const int x = 3 * kSize / 4, y = kSize / 2;
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(int(img.pixel(x, y)[k]), int(untextured.pixel(x, y)[k])) << "channel " << k;
        EXPECT_NEAR(int(img.pixel(x, y)[k]), to_byte(plain.diffuse[k]), 1) << "channel " << k;
    }
    glm::ivec2 p = cell_pixel(0, 0);
    EXPECT_NEAR(int(img.pixel(p.x, p.y)[0]), int(cell_color(0, 0).r), 1);
}

TEST(Texture, UvsWithoutTextureRenderLikeNoUvs) {
    Material plain;
    plain.diffuse = glm::vec3(0.3f, 0.6f, 0.9f);
    Mesh with_uvs = quad({plain});
    Mesh without = with_uvs;
    without.uvs.clear();
    ShadingSelection sel;
    sel.model = "mtoon";
    const Light light = directional_light({-1, 1, 2}, glm::vec3(0.9f), glm::vec3(0.1f));
    Image a = render_ortho(with_uvs, light, sel, single_sample(64));
    Image b = render_ortho(without, light, sel, single_sample(64));
    EXPECT_EQ(a.rgba, b.rgba);
    // A texture without uvs is not sampled either (nothing says where it goes).
    Mesh no_uvs_textured = quad({textured(plain.diffuse)});
    no_uvs_textured.uvs.clear();
    Image c = render_ortho(no_uvs_textured, light, sel, single_sample(64));
    EXPECT_EQ(c.rgba, b.rgba);
}

TEST(Texture, MinifiedCheckerAveragesInLinearLight) {
    // A 1-texel black/white checker seen at ~2.5 texels per pixel: mip levels built in linear
    // light hold half the light, the byte 188 a screen shows for it, read as stored (display) or
    // decoded to 0.5 and encoded again (linear); averaging the bytes would give 128 (0.21 of the
    // light, too dark), and no mipmaps would alias into black and white pixels.
    auto checker = std::make_shared<Texture>();
    checker->width = checker->height = 64;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            uint8_t v = (x + y) % 2 ? 255 : 0;
            checker->rgba.insert(checker->rgba.end(), {v, v, v, 255});
        }
    Material m;
    m.diffuse = glm::vec3(1.0f);
    m.texture = checker;
    ShadingSelection sel;
    for (const bool srgb_output : {false, true}) {
        Image img = render_ortho(quad({m}), ambient_only(), sel, single_sample(32, srgb_output));
        int compared = 0;
        for (int y = 10; y < 22; ++y)
            for (int x = 10; x < 22; ++x, ++compared)
                EXPECT_NEAR(int(img.pixel(x, y)[0]), 188, 3) << x << "," << y << (srgb_output ? " --srgb" : "");
        EXPECT_EQ(compared, 144);
    }
}

TEST(Texture, GlbQuadShowsItsTextureUpright) {
    // End to end through the glTF reader: a 2 x 2 texture (red, green / blue, white) on the unit
    // quad, base colour factor (0.5, 0.25, 1); glTF's top-left uv origin must come out upright.
    TempDir dir;
    Mesh mesh = load_mesh(dir.write("quad.glb", textured_quad().glb()));
    Camera cam = ortho_camera();
    cam.eye = {0.5f, 0.5f, 5.0f};
    cam.target = {0.5f, 0.5f, 0.0f};
    cam.ortho_height = 1.0f;
    // 66 px: the texel centres (16.5 and 49.5 px) are pixel centres.
    Renderer& r = shared_renderer();
    r.set_mesh(mesh);
    ShadingSelection sel;
    Image img = r.render(cam, ambient_only(), sel, single_sample(66));
    const glm::vec3 factor(0.5f, 0.25f, 1.0f);
    struct Expect {
        int x, y;
        glm::vec3 texel;
        const char* name;
    };
    for (const Expect& e :
         {Expect{16, 16, {1, 0, 0}, "top-left red"}, Expect{49, 16, {0, 1, 0}, "top-right green"},
          Expect{16, 49, {0, 0, 1}, "bottom-left blue"}, Expect{49, 49, {1, 1, 1}, "bottom-right white"}})
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(int(img.pixel(e.x, e.y)[k]), to_byte(e.texel[k] * factor[k]), 2) << e.name << " channel " << k;
}

TEST(Texture, EveryModelRendersATexturedMesh) {
    // Each model's textured variant compiles, links and shows the texture: against the same quad
    // with a plain white material, most of the 16 cells' centres change. Debug views show
    // geometry only, threejs-normal (MeshNormalMaterial) colours by the normal: the texture
    // changes nothing there.
    Material plain;
    plain.diffuse = glm::vec3(1.0f);
    for (const ShadingModel* model : shading_models()) {
        ShadingSelection sel;
        sel.model = model->name;
        const Image img = render_ortho(quad({textured()}), ambient_only(), sel, single_sample());
        const Image white = render_ortho(quad({plain}), ambient_only(), sel, single_sample());
        int changed = 0;
        for (int row = 0; row < kCells; ++row)
            for (int col = 0; col < kCells; ++col) {
                const glm::ivec2 p = cell_pixel(col, row);
                int most = 0;
                for (int k = 0; k < 3; ++k)
                    most = std::max(most, std::abs(img.pixel(p.x, p.y)[k] - white.pixel(p.x, p.y)[k]));
                changed += most > 8;
            }
        // palette and stipple map the light's intensity to their own colours and dots.
        const bool ignores_texture = model->debug_view || model->name == "threejs-normal" || model->name == "palette" ||
                                     model->name == "stipple";
        if (ignores_texture)
            EXPECT_EQ(changed, 0) << model->name;
        else
            EXPECT_GE(changed, 10) << model->name;
    }
}

// mtoon lit from behind (n.l = -1, A = 0): out = E * S, the shade colour alone.
Image mtoon_shade(const Mesh& mesh, bool use_material_params) {
    ShadingSelection sel;
    sel.model = "mtoon";
    sel.params["shadows"] = {0.0f};
    sel.params["shade-color"] = {0.0f, 0.0f, 1.0f};
    sel.params["convention"] = {0.0f};  // seeds: out = E * S as it is
    sel.params["use-material-params"] = {use_material_params ? 1.0f : 0.0f};
    return render_ortho(mesh, directional_light({0, 0, -1}, glm::vec3(1), glm::vec3(0)), sel, single_sample(64));
}

TEST(Texture, MtoonTakesEachMaterialsVrmParameters) {
    Material vrm, plain;
    vrm.name = "face";
    vrm.mtoon["shade-color"] = {1.0f, 0.0f, 0.0f};
    vrm.mtoon["shading-toony"] = {0.9f};
    vrm.mtoon["outline-width"] = {0.01f};  // without an outline-width-mode: no outline
    plain.name = "plain";
    Mesh mesh = quad({vrm, plain}, 1);
    mesh.uvs.clear();  // no texture: material draws happen for the parameters alone

    Image on = mtoon_shade(mesh, true);
    const uint8_t* left = on.pixel(16, 32);
    const uint8_t* right = on.pixel(48, 32);
    EXPECT_EQ(int(left[0]), 255);  // the material's shade colour
    EXPECT_EQ(int(left[2]), 0);
    EXPECT_EQ(int(right[0]), 0);  // the style's, restored after the VRM material's draw
    EXPECT_EQ(int(right[2]), 255);

    Image off = mtoon_shade(mesh, false);
    EXPECT_EQ(int(off.pixel(16, 32)[0]), 0);  // restyled: the style's shade colour everywhere
    EXPECT_EQ(int(off.pixel(16, 32)[2]), 255);
}

}  // namespace
}  // namespace inkshade::test
