// mtoon's outline against three-vrm 3.5.5's mtoon.vert (OUTLINE): on the unit sphere the ring runs
// from the silhouette to the farthest image point of a back face moved out as three-vrm moves
// it, evaluated here on the CPU (worldCoordinates: p + width * n; screenCoordinates
// (OUTLINE_WIDTH_SCREEN): p + width * n * vViewPosition.z / projectionMatrix[1].y), within 1 px,
// under orthographic and perspective cameras; its colour is outlineColorFactor * mix(1, lit
// colour, outlineLightingMixFactor), lit with the outward normal; a material's own outline values
// draw it per material.
#include <cmath>

#include "render/render_fixture.hpp"
#include "render/sphere_ring.hpp"

namespace inkshade::test {
namespace {


enum class Mode { World = 1, Screen = 2 };

// A green surface (shade and lit colour green, lit by E/pi = 1), a blue unlit outline.
ShadingSelection green_with_outline(Mode mode, float width) {
    ShadingSelection s;
    s.model = "mtoon";
    s.base_color = {0, 1, 0};
    s.params = {{"shade-color", {0, 1, 0}},
                {"shadows", {0}},
                {"outline-width-mode", {float(mode)}},
                {"outline-width", {width}},
                {"outline-color", {0, 0, 1}},
                {"outline-lighting-mix", {0}}};
    return s;
}

Light frontal_light() {
    Light l = directional_light({0, 0, 1}, glm::vec3(1), glm::vec3(0));
    l.intensity = kPi;
    return l;
}

Image render_sphere(const Camera& camera, const ShadingSelection& s, int size, const Mesh& mesh = fine_sphere()) {
    Renderer& r = shared_renderer();
    r.set_mesh(mesh);
    RenderOptions o;
    o.width = o.height = size;
    return r.render(camera, frontal_light(), s, o);
}

// three-vrm's outline vertex (mtoon.vert) for the unit sphere's point p (normal p), in clip space:
// the offset outlineWidthFactor * n, times the view depth over P[1][1] in screen coordinates.
glm::vec4 outline_clip(const Camera& c, Mode mode, float width, const glm::vec3& p) {
    const glm::mat4 proj = c.projection(1.0f), vp = proj * c.view();
    float offset = width;
    if (mode == Mode::Screen) offset *= -(c.view() * glm::vec4(p, 1.0f)).z / proj[1][1];
    return vp * glm::vec4(p + offset * p, 1.0f);
}

// The outer edge of the ring in pixels: the farthest image point of a back face's vertex moved
// out, over the great circle through the silhouette (the sphere is symmetric about the view axis).
float outline_outer_radius(const Camera& c, Mode mode, float width, int size) {
    float best = 0.0f;
    for (int i = 0; i < 40000; ++i) {
        const float phi = 2.0f * kPi * float(i) / 40000.0f;
        const glm::vec3 p(std::cos(phi), 0.0f, std::sin(phi));
        const bool back_facing = c.orthographic ? glm::dot(p, c.eye - c.target) < 0.0f : glm::dot(p, p - c.eye) > 0.0f;
        if (!back_facing) continue;
        const glm::vec4 clip = outline_clip(c, mode, width, p);
        best = std::max(best, std::abs(clip.x / clip.w) * 0.5f * float(size));
    }
    return best;
}

// World units: the ring is the silhouette of the sphere of radius 1 + width.
TEST(MtoonOutline, WorldCoordinatesRingIsTheSilhouetteOfTheGrownSphere) {
    const int size = 256;
    const float width = 0.06f;
    for (const Camera& cam : {ortho_camera(), perspective(5.0f)}) {
        const float inner = silhouette_radius(cam, size), outer = outline_outer_radius(cam, Mode::World, width, size);
        // The closed form: orthographic (1 + w) H / height; perspective tan = r / sqrt(d^2 - r^2).
        const float r = 1.0f + width, d = glm::length(cam.eye);
        const float analytic =
            cam.orthographic
                ? r * float(size) / cam.ortho_height
                : r / std::sqrt(d * d - r * r) / std::tan(glm::radians(0.5f * cam.fov_degrees)) * 0.5f * float(size);
        EXPECT_NEAR(outer, analytic, 0.05f);
        EXPECT_GT(outer - inner, 5.0f);
        expect_ring(render_sphere(cam, green_with_outline(Mode::World, width), size), inner, outer,
                    cam.orthographic ? "orthographic" : "perspective");
    }
}

// three-vrm 3.5.5 scales the offset by the view depth over P[1][1]: a perspective ring is
// width * H / 2 pixels at any distance; an orthographic one width * depth * H / 2, wider with depth.
TEST(MtoonOutline, ScreenCoordinatesRingFollowsThreeVrmsDepthScale) {
    const int size = 256;
    for (float distance : {4.0f, 8.0f}) {
        const float width = 0.02f;
        Camera cam = ortho_camera();
        cam.eye = {0, 0, distance};
        cam.far_plane = 20.0f;
        const float inner = silhouette_radius(cam, size), outer = outline_outer_radius(cam, Mode::Screen, width, size);
        // The silhouette circle lies at the sphere's centre depth.
        EXPECT_NEAR(outer - inner, width * distance * float(size) / 2.0f, 0.05f);
        expect_ring(render_sphere(cam, green_with_outline(Mode::Screen, width), size), inner, outer,
                    "orthographic at " + std::to_string(distance));
    }
    for (float distance : {5.0f, 9.0f}) {
        const float width = 0.1f;
        const Camera cam = perspective(distance);
        const float inner = silhouette_radius(cam, size), outer = outline_outer_radius(cam, Mode::Screen, width, size);
        // The offset's depth grows with the distance as the projection shrinks it: about w H / 2.
        EXPECT_NEAR(outer - inner, width * float(size) / 2.0f, 0.1f * width * float(size));
        expect_ring(render_sphere(cam, green_with_outline(Mode::Screen, width), size), inner, outer,
                    "perspective at " + std::to_string(distance));
    }
}

// A non-square image: the offset is along the normal in the world, so the ring is as wide left
// and right as up and down.
TEST(MtoonOutline, ScreenCoordinatesRingIsRoundInAWideImage) {
    const float width = 0.02f;
    Renderer& r = shared_renderer();
    r.set_mesh(fine_sphere());
    RenderOptions o;
    o.width = 384;
    o.height = 256;
    const Camera cam = ortho_camera();
    const Image img = r.render(cam, frontal_light(), green_with_outline(Mode::Screen, width), o);
    const glm::vec2 centre(192.0f, 128.0f);
    const float inner = 256.0f / cam.ortho_height;
    const float depth = glm::length(cam.eye - cam.target);
    for (float a : {0.0f, 0.5f * kPi, kPi, 1.5f * kPi}) {
        const Ring ring = ring_along(img, centre, a + 0.01f);
        EXPECT_NEAR(ring.outer - ring.inner, width * depth * 256.0f / 2.0f, 1.0f) << "angle " << a;
        EXPECT_NEAR(ring.inner, inner, 1.0f) << "angle " << a;
    }
}

// three.js negates a BackSide material's normal and three-vrm's outline negates it back: the
// ring is lit with the outward normal. A light from +x (across the view) lights the ring's right
// side (n.l = 1: the lit colour) and shades its left side (n.l = -1: the shade colour).
TEST(MtoonOutline, RingIsLitWithTheOutwardNormal) {
    const int size = 256;
    const float width = 0.08f;
    const glm::vec3 C(0.8f, 0.6f, 0.4f), S(0.1f, 0.2f, 0.5f);
    Renderer& r = shared_renderer();
    r.set_mesh(fine_sphere());
    RenderOptions o;
    o.width = o.height = size;
    Light light = directional_light({1, 0, 0}, glm::vec3(1), glm::vec3(0));
    light.intensity = kPi;  // E / pi = 1
    ShadingSelection s;
    s.model = "mtoon";
    s.base_color = C;
    s.params = {{"shadows", {0}},
                {"shade-color", {S.r, S.g, S.b}},
                {"outline-width-mode", {float(Mode::World)}},
                {"outline-width", {width}},
                {"outline-color", {1, 1, 1}},
                {"outline-lighting-mix", {1}}};
    const Image img = r.render(ortho_camera(), light, s, o);
    const float middle = silhouette_radius(ortho_camera(), size) + 0.5f * width * float(size) / 2.5f;
    for (float a : {-0.3f, 0.0f, 0.3f}) {
        const int y = int(128.0f + middle * std::sin(a));
        const int right = int(128.0f + middle * std::cos(a)), left = int(128.0f - middle * std::cos(a));
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(int(img.pixel(right, y)[k]), to_byte(reference_srgb(C[k])), 1) << "right, angle " << a;
            EXPECT_NEAR(int(img.pixel(left, y)[k]), to_byte(reference_srgb(S[k])), 1) << "left, angle " << a;
        }
    }
}

// outlineColorFactor * mix(1, lit, outlineLightingMixFactor), lit by the ambient light alone
// (E = 0) so the lit colour A/pi * C is the same wherever the ring's faces point.
TEST(MtoonOutline, ColourMixesTheOutlineColourWithTheLitColour) {
    const int size = 256;
    const float width = 0.08f;  // about 20 px
    const glm::vec3 C(0.8f, 0.6f, 0.4f), A(2.0f, 2.5f, 3.0f), oc(0.9f, 0.5f, 0.3f);
    Renderer& r = shared_renderer();
    r.set_mesh(fine_sphere());
    RenderOptions o;
    o.width = o.height = size;
    const Light light = directional_light({0, 0, 1}, glm::vec3(0), A);
    const float middle = silhouette_radius(ortho_camera(), size) + 0.5f * width * float(size) / 2.5f;
    for (float mix : {0.0f, 0.4f, 1.0f}) {
        ShadingSelection s;
        s.model = "mtoon";
        s.base_color = C;
        s.params = {{"shadows", {0}},
                    {"outline-width-mode", {float(Mode::World)}},
                    {"outline-width", {width}},
                    {"outline-color", {oc.r, oc.g, oc.b}},
                    {"outline-lighting-mix", {mix}}};
        const Image img = r.render(ortho_camera(), light, s, o);
        for (int i = 0; i < 8; ++i) {
            const float a = 2.0f * kPi * (float(i) + 0.5f) / 8.0f;
            const int x = int(128.0f + middle * std::cos(a)), y = int(128.0f + middle * std::sin(a));
            for (int k = 0; k < 3; ++k) {
                const float lit = A[k] / kPi * C[k];
                EXPECT_NEAR(int(img.pixel(x, y)[k]), to_byte(reference_srgb(oc[k] * (1.0f + (lit - 1.0f) * mix))), 1)
                    << "mix " << mix << " channel " << k << " at " << x << "," << y;
            }
        }
    }
}

// A VRM material's outline values (Material::mtoon) draw its outline where the style has none,
// unless use-material-params is off; without an outline mode nothing is drawn around the sphere.
TEST(MtoonOutline, MaterialsCarryTheirOwnOutline) {
    const int size = 256;
    const float width = 0.05f;
    Mesh sphere = fine_sphere();
    Material m;
    m.name = "vrm";
    m.diffuse = glm::vec3(1.0f);
    m.mtoon = {{"shade-color", {0, 1, 0}},
               {"outline-width-mode", {float(Mode::World)}},
               {"outline-width", {width}},
               {"outline-color", {0, 0, 1}},
               {"outline-lighting-mix", {0}}};
    sphere.materials = {m};
    sphere.face_materials.assign(sphere.triangles.size(), 0);
    ShadingSelection s = green_with_outline(Mode::World, 0.0f);
    s.params["outline-width-mode"] = {0};
    const Camera cam = ortho_camera();
    const float inner = silhouette_radius(cam, size);
    expect_ring(render_sphere(cam, s, size, sphere), inner, outline_outer_radius(cam, Mode::World, width, size),
                "material outline");
    s.params["use-material-params"] = {0};
    expect_ring(render_sphere(cam, s, size, sphere), inner, inner, "use-material-params off");
    sphere.materials[0].mtoon["outline-width-mode"] = {0};
    s.params["use-material-params"] = {1};
    expect_ring(render_sphere(cam, s, size, sphere), inner, inner, "material without outline");
}

TEST(MtoonOutline, DefaultsAreMToonMaterials) {
    const ShadingModel& m = shading_model("mtoon");
    EXPECT_EQ(m.param("outline-width-mode")->default_value, ParamValue{0});
    EXPECT_EQ(m.param("outline-width")->default_value, ParamValue{0});
    EXPECT_EQ(m.param("outline-color")->default_value, (ParamValue{0, 0, 0}));
    EXPECT_EQ(m.param("outline-lighting-mix")->default_value, ParamValue{1});
}

}  // namespace
}  // namespace inkshade::test
