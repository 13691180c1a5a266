// fresnel (rim glow): pixels against f = clamp(1 - |n.v|, 0, 1)^power on a sphere, and the
// inside-out artefact of naive rim shaders ruled out on an inverted mesh (windings and normals
// flipped), a mesh with only its normals flipped, and an open hemisphere seen from inside.
#include <algorithm>
#include <functional>

#include "geometry/builtin_models.hpp"
#include "render/render_fixture.hpp"

namespace inkshade::test {
namespace {

using Scene = PixelScene;

Scene fresnel_scene(const std::string& mode) {
    Scene s;
    s.light = directional_light(glm::vec3(1.0f, 1.0f, 2.0f), glm::vec3(0.9f), glm::vec3(0.1f));
    s.shading.model = "fresnel";
    s.shading.base_color = glm::vec3(0.5f, 0.35f, 0.25f);
    s.shading.params["mode"] = {mode == "add" ? 0.0f : 1.0f};
    s.shading.params["power"] = {2.5f};
    s.shading.params["intensity"] = {0.9f};
    s.shading.params["glow-color"] = {0.4f, 0.7f, 1.0f};
    s.options.width = s.options.height = kSize;
    s.options.background = glm::vec4(0, 0, 0, 1);
    return s;
}

// The formula with n the normal facing the viewer (v = +z).
glm::vec3 fresnel_formula(const Scene& s, const glm::vec3& n) {
    const glm::vec3 l = glm::normalize(s.light.position - s.light.target), glow(0.4f, 0.7f, 1.0f);
    float f = std::pow(std::clamp(1.0f - std::abs(n.z), 0.0f, 1.0f), 2.5f);
    glm::vec3 rim = 0.9f * glow * f;
    bool add = s.shading.params.at("mode")[0] == 0.0f;
    glm::vec3 base =
        add ? s.shading.base_color * (s.light.color * std::max(glm::dot(n, l), 0.0f) + s.light.ambient) : glm::vec3(0);
    return base + rim;
}

Image render(const Mesh& mesh, const Scene& s) {
    Renderer& r = shared_renderer();
    r.set_mesh(mesh);
    return r.render(ortho_camera(), s.light, s.shading, s.options);
}

// Compares a 24x24 grid of pixels inside the unit disc (n.v > 0.15, away from the outline)
// with expected(n), n = the viewer-facing sphere normal under the pixel; returns the count.
int compare_on_disc(const Image& img, const std::function<glm::vec3(const glm::vec3&)>& expected) {
    return compare_on_sphere(img, expected, 0.15f);
}

// Mean green level of pixels whose viewer-facing n.v lies in [lo, hi).
double mean_green(const Image& img, float lo, float hi) {
    const Camera cam = ortho_camera();
    double sum = 0;
    int count = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            auto n = sphere_normal(ray_origin(cam, x + 0.5f, y + 0.5f), 0.99f);
            if (!n || n->z < lo || n->z >= hi) continue;
            sum += img.pixel(x, y)[1];
            ++count;
        }
    EXPECT_GT(count, 50);
    return count ? sum / count : 0.0;
}

// Rim (n.v < 0.3) much brighter than the centre (n.v > 0.95), which is dark in replace mode.
void expect_rim_not_centre(const Image& img, const char* what) {
    double rim = mean_green(img, 0.05f, 0.3f), centre = mean_green(img, 0.95f, 1.01f);
    EXPECT_GT(rim, 60.0) << what;
    EXPECT_LT(centre, 3.0) << what;
    EXPECT_GT(rim, centre + 50.0) << what;
}

Mesh inverted(Mesh m, bool flip_windings, bool flip_normals) {
    if (flip_windings)
        for (glm::uvec3& t : m.triangles) std::swap(t.y, t.z);
    if (flip_normals)
        for (glm::vec3& n : m.normals) n = -n;
    return m;
}

// The half of the unit sphere behind the origin (z <= 0): a bowl opening towards the camera.
Mesh back_hemisphere() {
    Mesh sphere = builtin::sphere(128, 256);
    Mesh bowl;
    std::vector<int> remap(sphere.positions.size(), -1);
    for (const glm::uvec3& t : sphere.triangles) {
        if (sphere.positions[t.x].z > 1e-6f || sphere.positions[t.y].z > 1e-6f || sphere.positions[t.z].z > 1e-6f)
            continue;
        glm::uvec3 nt;
        for (int k = 0; k < 3; ++k) {
            uint32_t v = t[k];
            if (remap[v] < 0) {
                remap[v] = int(bowl.positions.size());
                bowl.positions.push_back(sphere.positions[v]);
                bowl.normals.push_back(sphere.normals[v]);
            }
            nt[k] = uint32_t(remap[v]);
        }
        bowl.triangles.push_back(nt);
    }
    return bowl;
}

class Fresnel : public ::testing::Test {};

TEST_F(Fresnel, AddModeMatchesFormulaAtSampledPixels) {
    Scene s = fresnel_scene("add");
    Image img = render(fine_sphere(), s);
    EXPECT_GE(compare_on_disc(img, [&](const glm::vec3& n) { return fresnel_formula(s, n); }), 50);
}

TEST_F(Fresnel, ReplaceModeIsRimAloneAtSampledPixels) {
    Scene s = fresnel_scene("replace");
    Image img = render(fine_sphere(), s);
    EXPECT_GE(compare_on_disc(img, [&](const glm::vec3& n) { return fresnel_formula(s, n); }), 50);
    expect_rim_not_centre(img, "sphere");
}

// The inside-out artefact of naive rim shaders: normals facing away from the viewer light the
// centre and darken the rim. Reversed windings with inward normals must look exactly like the outward sphere.
TEST_F(Fresnel, InvertedSphereStillGlowsAtTheSilhouette) {
    const Mesh inside_out = inverted(fine_sphere(), true, true);
    for (const char* mode : {"add", "replace"}) {
        Scene s = fresnel_scene(mode);
        Image img = render(inside_out, s);
        EXPECT_GE(compare_on_disc(img, [&](const glm::vec3& n) { return fresnel_formula(s, n); }), 50) << mode;
        if (std::string(mode) == "replace") expect_rim_not_centre(img, "inverted sphere");
    }
}

// Front faces whose normals point inwards (a broken file): the rim still sits at the silhouette.
TEST_F(Fresnel, InwardNormalsOnFrontFacesStillGlowAtTheSilhouette) {
    Scene s = fresnel_scene("replace");
    Image img = render(inverted(fine_sphere(), false, true), s);
    EXPECT_GE(compare_on_disc(img, [&](const glm::vec3& n) { return fresnel_formula(s, n); }), 50);
    expect_rim_not_centre(img, "inward normals");
}

// An open bowl seen from inside: the visible surface is the inside of the far hemisphere,
// whose viewer-facing normal is -p = (-x, -y, z) under the pixel where the front of a sphere
// has (x, y, z): the same n.v, a mirrored n.l.
TEST_F(Fresnel, OpenHemisphereSeenFromInsideHasRimAndDarkCentre) {
    const Mesh bowl = back_hemisphere();
    ASSERT_GT(bowl.triangles.size(), 1000u);
    Scene s = fresnel_scene("replace");
    Image img = render(bowl, s);
    EXPECT_GE(compare_on_disc(img, [&](const glm::vec3& n) { return fresnel_formula(s, n); }), 50);
    expect_rim_not_centre(img, "hemisphere inside");
    // With the base shading added, the inside is lit with the normal -p (two-sided Lambert).
    Scene a = fresnel_scene("add");
    Image lit = render(bowl, a);
    EXPECT_GE(compare_on_disc(lit, [&](const glm::vec3& n) { return fresnel_formula(a, {-n.x, -n.y, n.z}); }), 50);
}

TEST_F(Fresnel, LargerPowerNarrowsTheRim) {
    Scene s = fresnel_scene("replace");
    s.shading.params["power"] = {1.0f};
    double wide = mean_green(render(fine_sphere(), s), 0.4f, 0.6f);
    s.shading.params["power"] = {8.0f};
    double narrow = mean_green(render(fine_sphere(), s), 0.4f, 0.6f);
    EXPECT_GT(wide, narrow + 50.0);
}

}  // namespace
}  // namespace inkshade::test
