// Pixels of the classic shading models against CPU evaluations of their formulas
// (docs/shading.md: flat, Gouraud, Lambert, Phong, Blinn-Phong, debug views), on spheres
// whose normals are known.
#include <algorithm>
#include <functional>

#include "geometry/builtin_models.hpp"
#include "render/render_fixture.hpp"

namespace inkshade::test {
namespace {

using Scene = PixelScene;

Scene make_scene(const std::string& model, glm::vec3 light_dir = {1.0f, 1.0f, 2.0f}) {
    Scene s;
    s.light = directional_light(light_dir, glm::vec3(1.0f, 0.95f, 0.9f), glm::vec3(0.1f, 0.12f, 0.15f));
    s.shading.model = model;
    s.shading.base_color = glm::vec3(0.8f, 0.6f, 0.4f);
    s.options.width = s.options.height = kSize;
    s.options.background = glm::vec4(0, 0, 0, 1);
    return s;
}

glm::vec3 lambert_formula(const Scene& s, const glm::vec3& n) {
    glm::vec3 l = glm::normalize(s.light.position - s.light.target);
    return s.shading.base_color * (s.light.color * std::max(glm::dot(n, l), 0.0f) + s.light.ambient);
}

glm::vec3 specular_formula(const Scene& s, const glm::vec3& n, bool blinn, float shininess, glm::vec3 ks) {
    const glm::vec3 l = glm::normalize(s.light.position - s.light.target), v(0, 0, 1);
    if (glm::dot(n, l) <= 0.0f) return glm::vec3(0);
    float base =
        blinn ? std::max(glm::dot(n, glm::normalize(l + v)), 0.0f) : std::max(glm::dot(glm::reflect(-l, n), v), 0.0f);
    return ks * s.light.color * std::pow(base, shininess);
}

class ClassicShading : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        fine_ = new Mesh(builtin::sphere(128, 256));
        coarse_ = new Mesh(builtin::sphere(8, 16));
    }
    static void TearDownTestSuite() {
        delete fine_;
        delete coarse_;
    }
    static Image render(const Mesh& mesh, const Scene& s) {
        Renderer& r = shared_renderer();
        r.set_mesh(mesh);
        return r.render(ortho_camera(), s.light, s.shading, s.options);
    }
    static Mesh* fine_;
    static Mesh* coarse_;
};
Mesh* ClassicShading::fine_ = nullptr;
Mesh* ClassicShading::coarse_ = nullptr;

TEST_F(ClassicShading, LambertMatchesFormulaAtSampledPixels) {
    Scene s = make_scene("lambert");
    Image img = render(*fine_, s);
    EXPECT_GE(compare_on_sphere(img, [&](const glm::vec3& n) { return lambert_formula(s, n); }), 50);
}

TEST_F(ClassicShading, PhongMatchesFormulaAtSampledPixels) {
    Scene s = make_scene("phong");
    s.shading.params["shininess"] = {20};
    s.shading.params["specular"] = {0.5f, 0.4f, 0.3f};
    Image img = render(*fine_, s);
    EXPECT_GE(compare_on_sphere(
                  img,
                  [&](const glm::vec3& n) {
        return lambert_formula(s, n) + specular_formula(s, n, false, 20, {0.5f, 0.4f, 0.3f});
                  }),
              50);
}

TEST_F(ClassicShading, BlinnPhongMatchesFormulaAtSampledPixels) {
    Scene s = make_scene("blinn-phong");
    s.shading.params["shininess"] = {60};
    Image img = render(*fine_, s);
    EXPECT_GE(compare_on_sphere(
                  img,
                  [&](const glm::vec3& n) {
        return lambert_formula(s, n) + specular_formula(s, n, true, 60, glm::vec3(0.5f));
                  }),
              50);
}

// A light from behind and to the side: r.v > 0 on part of the unlit side, where the
// Phong rule used here says there is no highlight (specular only where n.l > 0).
TEST_F(ClassicShading, PhongHasNoSpecularWhereUnlit) {
    Scene s = make_scene("phong", {1.0f, 0.3f, -0.8f});
    s.shading.params["shininess"] = {4};
    Image img = render(*fine_, s);
    EXPECT_GE(compare_on_sphere(
                  img,
                  [&](const glm::vec3& n) {
        return lambert_formula(s, n) + specular_formula(s, n, false, 4, glm::vec3(0.5f));
                  }),
              50);
}

// The brightest specular pixel lies where the analytic mirror direction says: for a
// directional light and an orthographic view, n = normalize(l + v) at the peak.
TEST_F(ClassicShading, PhongHighlightPeakAtMirrorPoint) {
    for (const char* model : {"phong", "blinn-phong"}) {
        Scene s = make_scene(model, {-0.6f, 0.5f, 1.0f});
        s.shading.base_color = glm::vec3(0);  // specular only
        s.light.ambient = glm::vec3(0);
        s.shading.params["shininess"] = {400};
        Image img = render(*fine_, s);
        int best = -1;
        glm::vec2 sum(0);
        int count = 0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                int g = img.pixel(x, y)[1];
                if (g > best) best = g, sum = glm::vec2(0), count = 0;
                if (g == best) sum += glm::vec2(x + 0.5f, y + 0.5f), ++count;
            }
        glm::vec3 l = glm::normalize(s.light.position), v(0, 0, 1);
        glm::vec2 want = project(ortho_camera(), glm::normalize(l + v));
        glm::vec2 got = sum / float(count);
        EXPECT_GT(best, 100) << model;
        EXPECT_LT(glm::length(got - want), 2.0f)
            << model << " peak at " << got.x << "," << got.y << " expected " << want.x << "," << want.y;
    }
}

// Flat and Gouraud depend on the tessellation: on a coarse sphere, ray-cast the actual
// triangle under each pixel and evaluate the formula with its face normal (flat) or with
// the per-vertex Lambert colours interpolated barycentrically (gouraud).
int compare_on_mesh(const Mesh& mesh, const Image& img, const std::function<glm::vec3(const Hit&)>& expected) {
    const Camera cam = ortho_camera();
    int compared = 0;
    for (int gy = 0; gy < 32; ++gy)
        for (int gx = 0; gx < 32; ++gx) {
            int px = 4 + gx * 8, py = 4 + gy * 8;
            auto hit = cast_down(mesh, ray_origin(cam, px + 0.5f, py + 0.5f));
            if (!hit) continue;
            // Only pixels whose whole footprint lies on one triangle (MSAA would blend two).
            bool interior = true;
            for (float dx : {-0.7f, 0.7f})
                for (float dy : {-0.7f, 0.7f}) {
                    auto h = cast_down(mesh, ray_origin(cam, px + 0.5f + dx, py + 0.5f + dy));
                    interior = interior && h && h->triangle == hit->triangle;
                }
            if (!interior) continue;
            glm::vec3 want = expected(*hit);
            const uint8_t* got = img.pixel(px, py);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(int(got[c]), to_byte(want[c]), 2) << "pixel (" << px << "," << py << ") channel " << c;
            ++compared;
        }
    return compared;
}

TEST_F(ClassicShading, FlatIsLambertWithFaceNormals) {
    Scene s = make_scene("flat");
    Image img = render(*coarse_, s);
    const Mesh& m = *coarse_;
    EXPECT_GE(compare_on_mesh(
                  m, img,
                  [&](const Hit& h) {
        const glm::uvec3 t = m.triangles[h.triangle];
        glm::vec3 n =
            glm::normalize(glm::cross(m.positions[t.y] - m.positions[t.x], m.positions[t.z] - m.positions[t.x]));
        return lambert_formula(s, n);
                  }),
              50);
}

TEST_F(ClassicShading, GouraudInterpolatesVertexLambert) {
    Scene s = make_scene("gouraud");
    Image img = render(*coarse_, s);
    const Mesh& m = *coarse_;
    EXPECT_GE(compare_on_mesh(
                  m, img,
                  [&](const Hit& h) {
        const glm::uvec3 t = m.triangles[h.triangle];
        glm::vec3 c(0);
        for (int k = 0; k < 3; ++k) c += h.barycentric[k] * lambert_formula(s, glm::normalize(m.normals[t[k]]));
        return c;
                  }),
              50);
}

// On the coarse sphere per-pixel Lambert (interpolated normals) is not per-vertex Lambert.
TEST_F(ClassicShading, LambertDiffersFromGouraudOnCoarseMesh) {
    Image a = render(*coarse_, make_scene("lambert")), b = render(*coarse_, make_scene("gouraud"));
    int max_diff = 0;
    for (size_t i = 0; i < a.rgba.size(); ++i) max_diff = std::max(max_diff, std::abs(int(a.rgba[i]) - int(b.rgba[i])));
    EXPECT_GT(max_diff, 8);
}

TEST_F(ClassicShading, NormalViewEncodesAnalyticNormal) {
    Scene s = make_scene("normal");
    Image img = render(*fine_, s);
    EXPECT_GE(compare_on_sphere(img, [](const glm::vec3& n) { return 0.5f * n + 0.5f; }), 50);
}

TEST_F(ClassicShading, NdotvViewIsCosineToViewer) {
    Scene s = make_scene("ndotv");
    Image img = render(*fine_, s);
    EXPECT_GE(compare_on_sphere(img, [](const glm::vec3& n) { return glm::vec3(n.z); }), 50);
}

TEST_F(ClassicShading, WViewIsTangentProjectionOfView) {
    Scene s = make_scene("w");
    Image img = render(*fine_, s);
    EXPECT_GE(compare_on_sphere(
                  img,
                  [](const glm::vec3& n) {
        glm::vec3 v(0, 0, 1);
        return 0.5f * (v - glm::dot(n, v) * n) + 0.5f;
                  }),
              50);
}

TEST_F(ClassicShading, ViewViewIsConstantForOrthographicCamera) {
    Scene s = make_scene("view");
    Image img = render(*fine_, s);
    EXPECT_GE(compare_on_sphere(img, [](const glm::vec3&) { return glm::vec3(0.5f, 0.5f, 1.0f); }), 50);
}

// Two-sided lighting: through a hole in an open sphere the inner back wall is lit with the
// normal flipped towards the viewer (no black or inverted inside).
TEST_F(ClassicShading, OpenMeshShowsLitInside) {
    Mesh open = *fine_;
    std::erase_if(open.triangles, [&](const glm::uvec3& t) { return open.positions[t.x].z > 0.5f; });
    Scene s = make_scene("lambert", {0.2f, 0.3f, 1.0f});
    Image img = render(open, s);
    glm::vec3 want = lambert_formula(s, glm::vec3(0, 0, 1));  // inner wall at (0,0,-1), flipped
    const uint8_t* got = img.pixel(kSize / 2, kSize / 2);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(int(got[c]), to_byte(want[c]), 2) << c;
}

// Back faces are culled only when none can be seen: from inside a closed sphere the camera
// sees the inner wall, not the background.
TEST_F(ClassicShading, CameraInsideClosedMeshSeesInnerWall) {
    Scene s = make_scene("ndotv");
    s.options.background = glm::vec4(1, 0, 0, 1);
    Camera inside;
    inside.eye = glm::vec3(0, 0, 0.2f);
    inside.target = glm::vec3(0, 0, -1);
    inside.near_plane = 0.01f;
    inside.far_plane = 10.0f;
    Renderer& r = shared_renderer();
    r.set_mesh(*fine_);
    Image img = r.render(inside, s.light, s.shading, s.options);
    const uint8_t* c = img.pixel(kSize / 2, kSize / 2);
    EXPECT_EQ(int(c[0]), int(c[1])) << "background (red) visible: back faces were culled";
    EXPECT_GT(int(c[1]), 240);  // n.v = 1 at the inner wall straight ahead
}

TEST_F(ClassicShading, SameRenderTwiceIsByteIdentical) {
    Scene s = make_scene("phong");
    Image a = render(*fine_, s), b = render(*fine_, s);
    EXPECT_EQ(a.rgba, b.rgba);
}

TEST_F(ClassicShading, SrgbOptionEncodesOutput) {
    Scene s = make_scene("lambert");
    s.options.srgb_output = true;
    Image img = render(*fine_, s);
    auto srgb = [](float c) {
        c = std::clamp(c, 0.0f, 1.0f);
        return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
    };
    EXPECT_GE(compare_on_sphere(
                  img,
                  [&](const glm::vec3& n) {
        glm::vec3 c = lambert_formula(s, n);
        return glm::vec3(srgb(c.r), srgb(c.g), srgb(c.b));
                  }),
              50);
}

TEST_F(ClassicShading, TransparentBackgroundHasZeroAlphaAndOpaqueModel) {
    Scene s = make_scene("lambert");
    s.options.background = glm::vec4(0, 0, 0, 0);
    Image img = render(*fine_, s);
    EXPECT_EQ(img.pixel(2, 2)[3], 0);
    EXPECT_EQ(img.pixel(kSize / 2, kSize / 2)[3], 255);
}

}  // namespace
}  // namespace inkshade::test

namespace inkshade::test {
namespace {

// samples = 1 means no multisampling: a silhouette pixel is either model or background, with
// MSAA (default 4) some edge pixels blend the two.
TEST(Framebuffer, OneSampleMeansNoAntialiasing) {
    Mesh sphere = builtin::sphere(32, 64);
    Renderer& r = shared_renderer();
    r.set_mesh(sphere);
    ShadingSelection sel;
    sel.model = "normal";
    Light light;
    auto blended = [&](int samples) {
        RenderOptions o;
        o.width = o.height = 96;
        o.samples = samples;
        o.background = glm::vec4(0, 0, 0, 1);
        Image img = r.render(ortho_camera(), light, sel, o);
        int count = 0;  // pixels that are neither background nor a full-coverage normal colour
        for (int y = 0; y < 96; ++y)
            for (int x = 0; x < 96; ++x) {
                const uint8_t* p = img.pixel(x, y);
                int sum = p[0] + p[1] + p[2];
                if (sum > 0 && p[2] < 120) ++count;  // front normals have z >= 0: blue >= 127
            }
        return count;
    };
    EXPECT_EQ(blended(1), 0);
    EXPECT_GT(blended(4), 10);
}

}  // namespace
}  // namespace inkshade::test
