// The threejs-* models against CPU evaluations of three.js r187's material formulas (issue 10,
// docs/threejs.md), in linear light, then the standard sRGB encode (three.js's pow 0.41666 is
// within 0.002/255 of it): every compared pixel within 1/255, on a sphere and a torus knot seen
// from an oblique orthographic camera, silhouettes and overlaps excluded.
#include <cmath>
#include <functional>
#include <string>

#include "geometry/builtin_models.hpp"
#include "render/ortho_raycast.hpp"
#include "render/render_fixture.hpp"

namespace inkshade::test {
namespace {


// IEC 61966-2-1, the reference both for decoding the sRGB parameters and for the output.
float decode(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }
float encode(float c) {
    c = std::clamp(c, 0.0f, 1.0f);
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}
glm::vec3 decode(glm::vec3 c) { return {decode(c.r), decode(c.g), decode(c.b)}; }
glm::vec3 encode(glm::vec3 c) { return {encode(c.r), encode(c.g), encode(c.b)}; }
glm::vec3 hex(uint32_t rgb) {
    return glm::vec3(float(rgb >> 16 & 255), float(rgb >> 8 & 255), float(rgb & 255)) / 255.0f;
}

// A three.js scene as the tests set it up: the material's values as typed (sRGB), the light as
// three.js holds it (linear colour, intensity), the Inkshade scene that renders it.
struct ThreeScene {
    std::string model;
    glm::vec3 color = hex(0xffffff), emissive = hex(0x000000), specular = hex(0x111111);
    float shininess = 30, emissive_intensity = 1;
    std::vector<float> gradient;  // empty: MeshToonMaterial's default
    glm::vec3 base{1.0f};         // Inkshade base colour (stands in for vertex colours)
    bool point = false;
    glm::vec3 light_pos{2.0f, 3.0f, 4.0f};  // directional: from here towards the origin
    glm::vec3 light_color{1.0f, 0.95f, 0.9f};
    float intensity = 2.5f, decay = 2.0f;
    glm::vec3 ambient{0.3f, 0.35f, 0.4f};
    float ambient_intensity = 0.8f;

    ShadingSelection shading() const {
        ShadingSelection s;
        s.model = model;
        s.base_color = base;
        auto rgb = [](glm::vec3 c) { return ParamValue{c.r, c.g, c.b}; };
        if (model != "threejs-normal") s.params["color"] = rgb(color);
        if (model == "threejs-basic" || model == "threejs-normal") return s;
        s.params["emissive"] = rgb(emissive);
        s.params["emissive-intensity"] = {emissive_intensity};
        s.params["light-intensity"] = {intensity};
        s.params["ambient-intensity"] = {ambient_intensity};
        s.params["light-decay"] = {decay};
        if (model == "threejs-phong") {
            s.params["specular"] = rgb(specular);
            s.params["shininess"] = {shininess};
        }
        if (model == "threejs-toon" && !gradient.empty()) {
            s.params["use-gradient-map"] = {1.0f};
            s.params["gradient-map"] = gradient;
        }
        return s;
    }
    Light light() const {
        Light l;
        l.type = point ? LightType::Point : LightType::Directional;
        l.position = light_pos;
        l.target = glm::vec3(0.0f);
        l.color = light_color;
        l.ambient = ambient;
        return l;
    }
};

// three.js's value at surface point p with normal n seen along -v, before the encode; `u_out`
// receives the toon driver 0.5 n.l + 0.5 (for skipping band edges).
glm::vec3 threejs_formula(const ThreeScene& s, const glm::vec3& p, const glm::vec3& n, const glm::vec3& v,
                          float* u_out = nullptr) {
    const glm::vec3 C = s.base * decode(s.color);
    if (s.model == "threejs-basic") return C;
    glm::vec3 l = glm::normalize(s.light_pos - (s.point ? p : glm::vec3(0.0f)));
    glm::vec3 E = s.light_color * s.intensity;
    if (s.point) {
        const float d = glm::length(s.light_pos - p);
        E /= std::max(std::pow(d, s.decay), 0.01f);
    }
    const glm::vec3 A = s.ambient * s.ambient_intensity;
    const glm::vec3 emit = decode(s.emissive) * s.emissive_intensity;
    const float ndotl = glm::dot(n, l);
    if (s.model == "threejs-lambert") return C / kPi * (E * std::max(ndotl, 0.0f) + A) + emit;
    if (s.model == "threejs-phong") {
        const glm::vec3 irradiance = E * std::max(ndotl, 0.0f);
        const glm::vec3 h = glm::normalize(l + v);
        const float vh = std::max(glm::dot(v, h), 0.0f), nh = std::max(glm::dot(n, h), 0.0f);
        const glm::vec3 S = decode(s.specular);
        const glm::vec3 F = S + (1.0f - S) * std::exp2((-5.55473f * vh - 6.98316f) * vh);
        const glm::vec3 spec = irradiance * F * (s.shininess + 2.0f) / (8.0f * kPi) * std::pow(nh, s.shininess);
        return C / kPi * (irradiance + A) + spec + emit;
    }
    // threejs-toon
    const float u = 0.5f * ndotl + 0.5f;
    if (u_out) *u_out = u;
    float g = u < 0.7f ? 0.7f : 1.0f;
    if (!s.gradient.empty()) {
        const int count = int(s.gradient.size());
        g = s.gradient[size_t(std::clamp(int(std::floor(u * float(count))), 0, count - 1))];
    }
    return C / kPi * (E * g + A) + emit;
}

// The band (toon) a driver value falls in: pixels whose corners span two bands are edges.
int band(const ThreeScene& s, float u) {
    if (s.gradient.empty()) return u < 0.7f ? 0 : 1;
    return std::clamp(int(std::floor(u * float(s.gradient.size()))), 0, int(s.gradient.size()) - 1);
}

struct Stats {
    int compared = 0, highlight = 0;
};

// Renders the mesh from `camera` and compares every 4th pixel whose footprint is one smooth sheet.
Stats compare(const Mesh& mesh, const Camera& camera, const ThreeScene& s, int size = kSize) {
    Renderer& r = shared_renderer();
    r.set_mesh(mesh);
    RenderOptions o;
    o.width = o.height = size;
    o.background = glm::vec4(0, 0, 0, 1);
    const Image img = r.render(camera, s.light(), s.shading(), o);
    const OrthoRaycaster rays(mesh, camera, size, size);
    const glm::vec3 v = -rays.view_direction();
    Stats st;
    for (int py = 1; py < size - 1; py += 4)
        for (int px = 1; px < size - 1; px += 4) {
            auto hit = rays.interior(px, py);
            if (!hit) continue;
            glm::vec3 want;
            if (s.model == "threejs-normal") {
                // View space: x right, y up, z towards the viewer; no encode.
                const glm::vec3 nv(glm::dot(hit->normal, rays.right()), glm::dot(hit->normal, rays.up()),
                                   glm::dot(hit->normal, v));
                want = 0.5f * nv + 0.5f;
            } else {
                float u = 0.0f;
                want = encode(threejs_formula(s, hit->point, hit->normal, v, &u));
                if (s.model == "threejs-toon") {
                    bool edge = false;
                    for (float dx : {-1.0f, 1.0f})
                        for (float dy : {-1.0f, 1.0f}) {
                            auto h = rays.cast(float(px) + 0.5f + dx, float(py) + 0.5f + dy);
                            float uc = 0.0f;
                            if (h) threejs_formula(s, h->point, h->normal, v, &uc);
                            edge = edge || !h || band(s, uc) != band(s, u);
                        }
                    if (edge) continue;
                }
                if (s.model == "threejs-phong") {
                    ThreeScene diffuse_only = s;
                    diffuse_only.specular = glm::vec3(0.0f);
                    diffuse_only.model = "threejs-lambert";
                    const glm::vec3 d = threejs_formula(diffuse_only, hit->point, hit->normal, v);
                    const glm::vec3 full = threejs_formula(s, hit->point, hit->normal, v);
                    if (full.g - d.g > 0.02f) ++st.highlight;
                }
            }
            const uint8_t* got = img.pixel(px, py);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(int(got[c]), to_byte(want[c]), 1)
                    << s.model << " pixel (" << px << "," << py << ") channel " << c << " n=(" << hit->normal.x << ","
                    << hit->normal.y << "," << hit->normal.z << ")";
            ++st.compared;
        }
    return st;
}

Camera oblique_ortho(float height) {
    Camera c;
    c.eye = glm::normalize(glm::vec3(0.4f, 0.6f, 1.0f)) * 6.0f;
    c.target = glm::vec3(0.0f);
    c.up = glm::vec3(0, 1, 0);
    c.orthographic = true;
    c.ortho_height = height;
    c.near_plane = 1.0f;
    c.far_plane = 12.0f;
    return c;
}

class ThreejsShading : public ::testing::Test {
protected:
    static void SetUpTestSuite() { knot_ = new Mesh(builtin::torus_knot(2, 3, 0.3f, 512, 64)); }
    static void TearDownTestSuite() { delete knot_; }
    // Each setup on the sphere and on the torus knot, at least 100 pixels each.
    static void check_both(const ThreeScene& s) {
        const Stats sphere = compare(fine_sphere(), oblique_ortho(2.5f), s);
        EXPECT_GE(sphere.compared, 100) << s.model << " sphere";
        const Stats knot = compare(*knot_, oblique_ortho(3.6f), s);
        EXPECT_GE(knot.compared, 100) << s.model << " torus knot";
        last_ = {sphere.compared + knot.compared, sphere.highlight + knot.highlight};
    }
    static Mesh* knot_;
    static Stats last_;
};
Mesh* ThreejsShading::knot_ = nullptr;
Stats ThreejsShading::last_;

TEST_F(ThreejsShading, LambertMatchesMeshLambertMaterial) {
    ThreeScene s;
    s.model = "threejs-lambert";
    s.color = hex(0xff8800);
    s.emissive = hex(0x102030);
    s.base = glm::vec3(0.9f, 1.0f, 0.8f);  // vertex/texture colour multiplies `color`
    check_both(s);
}

// A point light close to the model: E / max(d^2, 0.01) varies over the surface.
TEST_F(ThreejsShading, LambertPointLightFallsOffWithInverseSquareDistance) {
    ThreeScene s;
    s.model = "threejs-lambert";
    s.color = hex(0xccddee);
    s.point = true;
    s.light_pos = glm::vec3(1.2f, 1.5f, 2.0f);
    s.intensity = 9.0f;
    s.ambient_intensity = 0.2f;
    check_both(s);
}

TEST_F(ThreejsShading, PhongMatchesMeshPhongMaterialIncludingHighlight) {
    ThreeScene s;
    s.model = "threejs-phong";
    s.color = hex(0x3366cc);
    s.specular = hex(0x888888);
    s.shininess = 40;
    s.emissive = hex(0x080000);
    check_both(s);
    EXPECT_GE(last_.highlight, 20) << "the highlight must be among the compared pixels";
}

// MeshPhongMaterial's defaults (specular 0x111111, shininess 30), lit from behind and to the
// side: at v.h = 0.48 the Schlick term F nearly triples the specular colour, so the rim
// highlight is mostly Fresnel and (s + 2)/(8 pi) normalisation, the part of three.js's Phong
// highlight that a plain Phong or Blinn-Phong shader does not reproduce.
TEST_F(ThreejsShading, PhongDefaultsMatchMeshPhongMaterialWithGrazingFresnel) {
    ThreeScene s;
    s.model = "threejs-phong";
    s.color = hex(0xffffff);
    s.light_pos = glm::vec3(-4.0f, 1.0f, -2.0f);
    s.intensity = 3.0f;
    check_both(s);
    EXPECT_GE(last_.highlight, 20) << "the highlight must be among the compared pixels";
}

TEST_F(ThreejsShading, ToonDefaultTwoTonesMatchMeshToonMaterial) {
    ThreeScene s;
    s.model = "threejs-toon";
    s.color = hex(0x44aa88);
    s.emissive = hex(0x000010);
    check_both(s);
}

TEST_F(ThreejsShading, ToonGradientMapIsReadNearest) {
    ThreeScene s;
    s.model = "threejs-toon";
    s.color = hex(0xffaa00);
    s.gradient = {0.1f, 0.45f, 0.7f, 0.95f};
    check_both(s);
}

TEST_F(ThreejsShading, NormalIsViewSpaceNormalWithoutEncode) {
    ThreeScene s;
    s.model = "threejs-normal";
    check_both(s);
}

TEST_F(ThreejsShading, BasicIsTheColourItself) {
    ThreeScene s;
    s.model = "threejs-basic";
    s.color = hex(0x80c040);
    s.base = glm::vec3(0.5f, 1.0f, 1.0f);
    check_both(s);
}

// three.js's parameter names and defaults (MeshPhongMaterial: color 0xffffff, specular 0x111111,
// shininess 30, emissive 0x000000, emissiveIntensity 1; lights: intensity 1, decay 2, distance 0),
// the colours typed as sRGB.
TEST(ThreejsModels, ParametersHaveThreejsNamesAndDefaults) {
    const ShadingModel& phong = shading_model("threejs-phong");
    auto def = [&](const ShadingModel& m, const char* name) {
        const ParamSpec* p = m.param(name);
        EXPECT_NE(p, nullptr) << m.name << "." << name;
        return p ? p->default_value : ParamValue{};
    };
    EXPECT_EQ(def(phong, "color"), (ParamValue{1, 1, 1}));
    EXPECT_EQ(def(phong, "specular"), (ParamValue{0x11 / 255.0f, 0x11 / 255.0f, 0x11 / 255.0f}));
    EXPECT_EQ(def(phong, "shininess"), ParamValue{30.0f});
    EXPECT_EQ(def(phong, "emissive"), (ParamValue{0, 0, 0}));
    EXPECT_EQ(def(phong, "emissive-intensity"), ParamValue{1.0f});
    EXPECT_EQ(def(phong, "light-intensity"), ParamValue{1.0f});
    EXPECT_EQ(def(phong, "ambient-intensity"), ParamValue{1.0f});
    EXPECT_EQ(def(phong, "light-decay"), ParamValue{2.0f});
    EXPECT_EQ(def(phong, "light-distance"), ParamValue{0.0f});
    for (const char* name : {"color", "specular", "emissive"}) EXPECT_TRUE(phong.param(name)->srgb) << name;
    EXPECT_EQ(def(shading_model("threejs-toon"), "use-gradient-map"), ParamValue{0.0f});
    for (const char* model : {"threejs-basic", "threejs-lambert", "threejs-toon"})
        EXPECT_EQ(def(shading_model(model), "color"), (ParamValue{1, 1, 1})) << model;
    EXPECT_TRUE(shading_model("threejs-normal").params.empty());
}

// With the sRGB parameters, a white MeshBasicMaterial of colour 0x336699 writes exactly 0x336699.
TEST(ThreejsColors, BasicWritesItsHexColourBack) {
    ThreeScene s;
    s.model = "threejs-basic";
    s.color = hex(0x336699);
    RenderOptions o;
    o.width = o.height = 64;
    o.samples = 1;
    Renderer& r = shared_renderer();
    r.set_mesh(fine_sphere());
    const Image img = r.render(ortho_camera(), s.light(), s.shading(), o);
    const uint8_t* p = img.pixel(32, 32);
    EXPECT_EQ(int(p[0]), 0x33);
    EXPECT_EQ(int(p[1]), 0x66);
    EXPECT_EQ(int(p[2]), 0x99);
}

}  // namespace
}  // namespace inkshade::test
