// BaseColorUse: how the base colour meets a mesh's own colours (docs/shading.md, "Base
// colour"). Multiply (--base-color) multiplies them; Fallback (a style's base-color) tints only
// a mesh without colours of its own; Only (ink's mesh-colors = false) is the base colour alone.
#include "render/render_fixture.hpp"

namespace inkshade::test {
namespace {

// Lit only by ambient A = 1 (E = 0): lambert and gouraud pixels are exactly C.
Light ambient_only() { return directional_light({0, 0, 1}, glm::vec3(0), glm::vec3(1)); }

RenderOptions small() {
    RenderOptions o;
    o.width = o.height = 64;
    o.samples = 1;
    return o;
}

// The square [-1, 1]^2 facing +z, uvs over the whole of it, no colours.
Mesh square() {
    Mesh m;
    m.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    m.normals.assign(4, glm::vec3(0, 0, 1));
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    return m;
}

Mesh with_material(Material material) {
    Mesh m = square();
    m.materials = {std::move(material)};
    m.face_materials = {0, 0};
    return m;
}

// A 2 x 2 texture of one colour: (108,173,223), the texel of the report that textures came out dark.
const glm::u8vec3 kTexel(108, 173, 223);
Mesh textured_square() {
    auto t = std::make_shared<Texture>();
    t->source = "uniform";
    t->width = t->height = 2;
    for (int i = 0; i < 4; ++i) t->rgba.insert(t->rgba.end(), {kTexel.r, kTexel.g, kTexel.b, 255});
    Material m;
    m.name = "textured";
    m.diffuse = glm::vec3(1.0f);
    m.texture = t;
    return with_material(m);
}

const glm::vec3 kBase(0.5f, 1.0f, 0.8f);
const glm::vec3 kVertex(0.2f, 0.4f, 0.6f);
const glm::vec3 kDiffuse(1.0f, 0.25f, 0.5f);
const glm::vec3 kTexelValue = glm::vec3(kTexel) / 255.0f;  // display convention: as stored

struct Case {
    const char* name;
    Mesh mesh;
    glm::vec3 own;  // the mesh's own colour (white: none)
    bool has_own;   // colours of its own: the base colour of a style does not tint it
};

std::vector<Case> cases() {
    Mesh vertex_colored = square();
    vertex_colored.colors.assign(4, kVertex);
    Material white;
    white.diffuse = glm::vec3(1.0f);  // glTF's default material: no colour of its own
    Material kd;
    kd.diffuse = kDiffuse;
    return {{"no colours", square(), glm::vec3(1.0f), false},
            {"white material", with_material(white), glm::vec3(1.0f), false},
            {"vertex colours", vertex_colored, kVertex, true},
            {"material colour", with_material(kd), kDiffuse, true},
            {"texture", textured_square(), kTexelValue, true}};
}

void expect_centre(const Image& img, const glm::vec3& want, const std::string& what) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(int(img.pixel(32, 32)[k]), to_byte(want[k]), 1) << what << " channel " << k;
}

Image render_with(const Mesh& mesh, BaseColorUse use, const char* model = "lambert") {
    ShadingSelection sel;
    sel.model = model;
    sel.base_color = kBase;
    sel.base_color_use = use;
    return render_ortho(mesh, ambient_only(), sel, small());
}

TEST(BaseColorUse, MultiplyTintsEveryMesh) {
    for (const Case& c : cases()) expect_centre(render_with(c.mesh, BaseColorUse::Multiply), kBase * c.own, c.name);
}

TEST(BaseColorUse, FallbackTintsOnlyMeshesWithoutColoursOfTheirOwn) {
    for (const Case& c : cases()) {
        // Sanity: the cases differ where the rule says (a tint of 1 would hide a wrong rule).
        ASSERT_NE(kBase * c.own, c.own) << c.name;
        expect_centre(render_with(c.mesh, BaseColorUse::Fallback), c.has_own ? c.own : kBase * c.own, c.name);
    }
}

TEST(BaseColorUse, OnlyIsTheBaseColourWhateverTheMesh) {
    for (const char* model : {"lambert", "gouraud", "flat"})
        for (const Case& c : cases())
            expect_centre(render_with(c.mesh, BaseColorUse::Only, model), kBase, std::string(model) + ", " + c.name);
}

TEST(BaseColorUse, OnlyLeavesAnUncolouredMeshBitForBit) {
    // Without colours of its own a mesh draws with the same program either way (no variant).
    const Mesh mesh = square();
    EXPECT_EQ(render_with(mesh, BaseColorUse::Only).rgba, render_with(mesh, BaseColorUse::Multiply).rgba);
}

}  // namespace
}  // namespace inkshade::test
