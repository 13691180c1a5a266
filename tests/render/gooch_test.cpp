// Pixels of the `gooch` model against a CPU evaluation of Gooch et al. 1998's formula
// (docs/shading.md) on a unit sphere with analytic normals.
#include <algorithm>
#include <cmath>

#include "geometry/builtin_models.hpp"
#include "render/render_fixture.hpp"

namespace inkshade::test {
namespace {

struct GoochParams {
    float blue = 0.4f, yellow = 0.4f, alpha = 0.2f, beta = 0.6f;
    bool specular = false;
    float shininess = 32.0f;

    ParamValues to_params() const {
        return {{"blue", {blue}},
                {"yellow", {yellow}},
                {"alpha", {alpha}},
                {"beta", {beta}},
                {"specular", {specular ? 1.0f : 0.0f}},
                {"shininess", {shininess}}};
    }
};

struct Scene : PixelScene {
    GoochParams gooch;
};

Scene make_scene(const GoochParams& g, glm::vec3 light_dir = {1.0f, 1.0f, 2.0f}) {
    Scene s;
    s.light.type = LightType::Directional;
    s.light.target = glm::vec3(0);
    s.light.position = glm::normalize(light_dir) * 10.0f;
    s.shading.model = "gooch";
    s.shading.base_color = glm::vec3(0.8f, 0.3f, 0.2f);
    s.shading.params = g.to_params();
    s.options.width = s.options.height = kSize;
    s.options.background = glm::vec4(0, 0, 0, 1);
    s.gooch = g;
    return s;
}

// t*k_warm + (1-t)*k_cool, t = (1 + n.l)/2 (warm towards the light), plus the white highlight.
glm::vec3 gooch_formula(const Scene& s, const glm::vec3& n) {
    const GoochParams& g = s.gooch;
    const glm::vec3 kd = s.shading.base_color, l = s.l(), v(0, 0, 1);
    glm::vec3 cool = glm::vec3(0, 0, g.blue) + g.alpha * kd;
    glm::vec3 warm = glm::vec3(g.yellow, g.yellow, 0) + g.beta * kd;
    float ndotl = glm::dot(n, l), t = 0.5f * (1.0f + ndotl);
    glm::vec3 c = t * warm + (1.0f - t) * cool;
    if (g.specular && ndotl > 0.0f)
        c += glm::vec3(std::pow(std::max(glm::dot(glm::reflect(-l, n), v), 0.0f), g.shininess));
    return c;
}

int compare_on_sphere(const Image& img, const Scene& s) {
    return test::compare_on_sphere(img, [&](const glm::vec3& n) { return gooch_formula(s, n); });
}

class Gooch : public ::testing::Test {
protected:
    static Image render(const Scene& s) {
        Renderer& r = shared_renderer();
        r.set_mesh(fine_sphere());
        return r.render(ortho_camera(), s.light, s.shading, s.options);
    }
};

TEST_F(Gooch, DefaultsMatchFormulaAtSampledPixels) {
    Scene s = make_scene(GoochParams{});
    s.shading.params.clear();  // the registered defaults are the paper's
    EXPECT_GE(compare_on_sphere(render(s), s), 50);
}

TEST_F(Gooch, ParametersAndHighlightMatchFormula) {
    GoochParams g;
    g.blue = 0.55f;
    g.yellow = 0.3f;
    g.alpha = 0.35f;
    g.beta = 0.45f;
    g.specular = true;
    g.shininess = 12.0f;
    Scene s = make_scene(g, {-0.7f, 0.4f, 1.0f});
    EXPECT_GE(compare_on_sphere(render(s), s), 50);
}

// Warm faces the light: the pixel whose normal points at the light is yellower (more red and
// green, less blue) than one facing away (the minus sign or swapped colours some write-ups
// print would invert this).
TEST_F(Gooch, WarmFacesTheLightCoolFacesAway) {
    Scene s = make_scene(GoochParams{}, {1.0f, 0.0f, 0.4f});
    s.shading.base_color = glm::vec3(0.5f);
    Image img = render(s);
    const glm::vec3 toward = s.l(), away = glm::normalize(glm::vec3(-0.95f, 0.0f, 0.3f));
    glm::vec2 pt = project(ortho_camera(), toward), pa = project(ortho_camera(), away);
    const uint8_t* lit = img.pixel(int(pt.x), int(pt.y));
    const uint8_t* dark = img.pixel(int(pa.x), int(pa.y));
    EXPECT_GT(int(lit[0]), int(dark[0]) + 60);
    EXPECT_GT(int(lit[1]), int(dark[1]) + 60);
    EXPECT_LT(int(lit[2]), int(dark[2]) - 30);
    // And both equal the formula at their analytic normals.
    for (auto [p, n] : {std::pair{pt, toward}, std::pair{pa, away}}) {
        glm::vec3 m = *sphere_normal(ray_origin(ortho_camera(), std::floor(p.x) + 0.5f, std::floor(p.y) + 0.5f));
        glm::vec3 want = gooch_formula(s, m);
        const uint8_t* got = img.pixel(int(p.x), int(p.y));
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(int(got[c]), to_byte(want[c]), 2);
    }
}

}  // namespace
}  // namespace inkshade::test
