// Pixels of the `palette` model against a CPU evaluation of the cosine palette
// a + b*cos(2*pi*(c*t + d)) (Inigo Quilez, "palettes") for several drivers, on a unit
// sphere with analytic normals and positions.
#include <algorithm>
#include <cmath>
#include <functional>

#include "geometry/builtin_models.hpp"
#include "render/render_fixture.hpp"

namespace inkshade::test {
namespace {

enum Driver { kNdotl = 0, kHalfLambert, kNdotv, kHeight, kX, kZ };

struct PaletteParams {
    glm::vec3 a{0.5f}, b{0.5f}, c{1.0f}, d{0.0f, 0.33f, 0.67f};
    Driver driver = kNdotl;
    bool lit = false;

    ParamValues to_params() const {
        return {{"a", {a.r, a.g, a.b}}, {"b", {b.r, b.g, b.b}},      {"c", {c.r, c.g, c.b}},
                {"d", {d.r, d.g, d.b}}, {"driver", {float(driver)}}, {"lit", {lit ? 1.0f : 0.0f}}};
    }
};

struct Scene : PixelScene {
    PaletteParams palette;
};

Scene make_scene(const PaletteParams& p, glm::vec3 light_dir = {1.0f, 1.0f, 2.0f}) {
    Scene s;
    s.light = directional_light(light_dir, glm::vec3(1.0f, 0.9f, 0.8f), glm::vec3(0.1f, 0.12f, 0.15f));
    s.shading.model = "palette";
    s.shading.base_color = glm::vec3(0.3f);  // unused by palette
    s.shading.params = p.to_params();
    s.options.width = s.options.height = kSize;
    s.options.background = glm::vec4(0, 0, 0, 1);
    s.palette = p;
    return s;
}

// The unit sphere's bounding box is [-1, 1]^3, so the normalised coordinates are (p + 1)/2;
// on the unit sphere the surface point p equals the analytic normal n.
glm::vec3 palette_formula(const Scene& s, const glm::vec3& n) {
    const PaletteParams& p = s.palette;
    const glm::vec3 l = s.l(), v(0, 0, 1);
    float ndotl = glm::dot(n, l), t = 0;
    switch (p.driver) {
        case kNdotl: t = std::max(ndotl, 0.0f); break;
        case kHalfLambert: t = 0.5f * ndotl + 0.5f; break;
        case kNdotv: t = std::max(glm::dot(n, v), 0.0f); break;
        case kHeight: t = 0.5f * (n.y + 1.0f); break;
        case kX: t = 0.5f * (n.x + 1.0f); break;
        case kZ: t = 0.5f * (n.z + 1.0f); break;
    }
    glm::vec3 c = p.a + p.b * glm::cos(6.28318530718f * (p.c * t + p.d));
    if (p.lit) c *= s.light.color * std::max(ndotl, 0.0f) + s.light.ambient;
    return c;
}

int compare_on_sphere(const Image& img, const Scene& s) {
    return test::compare_on_sphere(
        img, [&](const glm::vec3& n) { return palette_formula(s, n); }, 0.2f,
        "driver " + std::to_string(int(s.palette.driver)));
}

class Palette : public ::testing::Test {
protected:
    static Image render(const Scene& s) {
        Renderer& r = shared_renderer();
        r.set_mesh(fine_sphere());
        return r.render(ortho_camera(), s.light, s.shading, s.options);
    }
};

TEST_F(Palette, DefaultsMatchFormulaOnNdotl) {
    Scene s = make_scene(PaletteParams{});
    s.shading.params.clear();  // registered defaults: IQ's rainbow on max(n.l, 0)
    EXPECT_GE(compare_on_sphere(render(s), s), 50);
}

TEST_F(Palette, EveryDriverMatchesFormula) {
    PaletteParams p;
    p.a = {0.5f, 0.45f, 0.4f};
    p.b = {0.4f, 0.5f, 0.3f};
    p.c = {1.5f, 1.0f, 0.5f};
    p.d = {0.1f, 0.3f, 0.8f};
    for (Driver driver : {kNdotl, kHalfLambert, kNdotv, kHeight, kX, kZ}) {
        p.driver = driver;
        Scene s = make_scene(p, {-0.8f, 0.6f, 0.5f});
        EXPECT_GE(compare_on_sphere(render(s), s), 50) << "driver " << int(driver);
    }
}

TEST_F(Palette, LitMultipliesByLambertPlusAmbient) {
    PaletteParams p;
    p.driver = kHeight;
    p.lit = true;
    Scene s = make_scene(p);
    EXPECT_GE(compare_on_sphere(render(s), s), 50);
}

// A list value with one number repeats over r, g, b: c = 2 is c = (2, 2, 2).
TEST_F(Palette, SingleListValueRepeatsOverChannels) {
    PaletteParams p;
    p.driver = kHalfLambert;
    p.c = glm::vec3(2.0f);
    Scene s = make_scene(p);
    s.shading.params["c"] = {2.0f};
    EXPECT_GE(compare_on_sphere(render(s), s), 50);
}

}  // namespace
}  // namespace inkshade::test
