// A VRM 0.x avatar's MToon material, from the file to the pixels: a unit sphere written as a GLB
// with extensions.VRM.materialProperties, loaded, and drawn with the values three-vrm 3.x's
// VRMMaterialsV0CompatPlugin ports it to (colours gamma-decoded with x^2.2, _ShadeToony and
// _ShadeShift as toony' = lerp(toony, 1, 0.5 + 0.5 shift), shift' = -shift - (1 - toony'),
// _EmissionColor as emissiveFactor), worked out here from the properties and compared with
// mtoon.frag's formula on the CPU.
#include <cmath>

#include "inkshade/io.hpp"
#include "io/gltf_files.hpp"
#include "render/render_fixture.hpp"
#include "support/temp_dir.hpp"

namespace inkshade::test {
namespace {

// The fine sphere as a GLB with one material (glTF uvs: t = 1 - v, the planar projection).
GltfBuilder sphere_glb(const nlohmann::json& material_properties) {
    const Mesh& s = fine_sphere();
    std::vector<float> pos, nrm, uv;
    for (size_t i = 0; i < s.positions.size(); ++i) {
        const glm::vec3 p = s.positions[i], n = s.normals[i];
        pos.insert(pos.end(), {p.x, p.y, p.z});
        nrm.insert(nrm.end(), {n.x, n.y, n.z});
        uv.insert(uv.end(), {0.5f * p.x + 0.5f, 1.0f - (0.5f * p.y + 0.5f)});
    }
    std::vector<uint32_t> idx;
    for (const glm::uvec3& t : s.triangles) idx.insert(idx.end(), {t.x, t.y, t.z});
    GltfBuilder g;
    const int p = g.floats(pos, "VEC3", 3), n = g.floats(nrm, "VEC3", 3), t = g.floats(uv, "VEC2", 2);
    const int i = g.data(idx, kUInt, 1, "SCALAR");
    const int mat = g.material({1, 1, 1, 1});
    const int mesh = g.mesh({{"POSITION", p}, {"NORMAL", n}, {"TEXCOORD_0", t}}, i, mat);
    g.scene({g.node({{"mesh", mesh}})});
    g.doc["extensions"]["VRM"] = {{"materialProperties", material_properties}};
    return g;
}

float gamma(float c) { return std::pow(c, 2.2f); }
glm::vec3 gamma(const glm::vec3& c) { return {gamma(c.r), gamma(c.g), gamma(c.b)}; }

TEST(Vrm0Mtoon, SphereRendersWithThePropertiesAsThreeVrmPortsThem) {
    // MToon 0.x's properties, in its gamma-encoded colours.
    const glm::vec3 color(0.9f, 0.7f, 0.5f), shade(0.5f, 0.3f, 0.6f), rim(0.6f, 0.5f, 0.3f), emission(0.3f, 0.2f, 0.1f);
    const float shade_shift = 0.2f, shade_toony = 0.5f, rim_power = 2.0f, rim_lift = 0.1f, rim_mix = 0.5f;
    const nlohmann::json props =
        nlohmann::json::array({{{"name", "skin"},
                                {"shader", "VRM/MToon"},
                                {"floatProperties",
                                 {{"_ShadeShift", shade_shift},
                                  {"_ShadeToony", shade_toony},
                                  {"_RimFresnelPower", rim_power},
                                  {"_RimLift", rim_lift},
                                  {"_RimLightingMix", rim_mix}}},
                                {"vectorProperties",
                                 {{"_Color", {color.r, color.g, color.b, 1}},
                                  {"_ShadeColor", {shade.r, shade.g, shade.b, 1}},
                                  {"_RimColor", {rim.r, rim.g, rim.b, 1}},
                                  {"_EmissionColor", {emission.r, emission.g, emission.b, 1}}}},
                                {"textureProperties", nlohmann::json::object()}}});
    TempDir dir;
    const Mesh mesh = load_mesh(dir.write("avatar.vrm", sphere_glb(props).glb()));

    // VRMMaterialsV0CompatPlugin's port, and mtoon.frag (threejs convention, orthographic camera
    // on +z: v from the point to the eye).
    const float toony = shade_toony + (1.0f - shade_toony) * (0.5f + 0.5f * shade_shift);
    const float shift = -shade_shift - (1.0f - toony);
    const glm::vec3 C = gamma(color), S = gamma(shade), R = gamma(rim), emissive = gamma(emission);
    Light light = directional_light({-1.0f, 1.5f, 2.0f}, glm::vec3(1.0f, 0.95f, 0.9f), glm::vec3(0.3f, 0.3f, 0.35f));
    light.intensity = 2.0f;
    const glm::vec3 l = glm::normalize(light.position - light.target), E = light.color * light.intensity,
                    A = light.ambient, eye = ortho_camera().eye;
    auto expected = [&](const glm::vec3& n) {
        const float a = -1.0f + toony, b = 1.0f - toony;
        const float t = std::clamp((glm::dot(n, l) + shift - a) / (b - a), 0.0f, 1.0f);
        const glm::vec3 v = glm::normalize(eye - n);
        const glm::vec3 r = R * std::pow(std::clamp(1.0f - glm::dot(n, v) + rim_lift, 0.0f, 1.0f), rim_power) *
                            glm::mix(glm::vec3(1.0f), (E + A) / kPi, rim_mix);
        return reference_srgb(E / kPi * glm::mix(S, C, t) + A / kPi * C + r + emissive);
    };
    ShadingSelection s;
    s.model = "mtoon";
    s.params = {{"shadows", {0}}};
    RenderOptions o;
    o.width = o.height = kSize;
    o.samples = 1;
    const Image img = render_ortho(mesh, light, s, o);
    EXPECT_GE(compare_on_sphere(img, expected, 0.3f, "VRM 0.x sphere"), 250);

    // The port matters: the 0.x values taken as 1.0 ones (no gamma, toony and shift as written)
    // give another picture.
    int differs = 0;
    const Camera cam = ortho_camera();
    for (int y = 8; y < kSize; y += 10)
        for (int x = 8; x < kSize; x += 10) {
            const auto n = sphere_normal(ray_origin(cam, x + 0.5f, y + 0.5f));
            if (!n || n->z < 0.3f) continue;
            const float a = -1.0f + shade_toony, b = 1.0f - shade_toony;
            const float t = std::clamp((glm::dot(*n, l) + shade_shift - a) / (b - a), 0.0f, 1.0f);
            const glm::vec3 naive = reference_srgb(E / kPi * glm::mix(shade, color, t) + A / kPi * color + emission);
            differs += std::abs(to_byte(naive.g) - int(img.pixel(x, y)[1])) > 8;
        }
    EXPECT_GE(differs, 150);
}

}  // namespace
}  // namespace inkshade::test
