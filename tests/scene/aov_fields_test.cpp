// The surface-field AOVs against analytic answers: on a sphere of radius R, n·v from the camera
// geometry and κr = k1 = k2 = 1/R; on a torus (R, r), k1 = 1/r, k2 = cos θ / (R + r cos θ) and
// κr by Euler's formula for the view direction, the principal directions projected into the
// image; the p90 factors recomputed from the fields (docs/aov.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "geometry/builtin_models.hpp"
#include "inkshade/aov.hpp"
#include "render/render_fixture.hpp"

namespace inkshade {
namespace {

using test::shared_renderer;

Camera oblique_camera(glm::vec3 eye) {
    Camera c;
    c.eye = eye;
    c.target = {0.1f, -0.05f, 0.0f};  // off centre: the model is not on the optical axis
    c.fov_degrees = 40.0f;
    c.near_plane = 1.0f;
    c.far_plane = 20.0f;
    return c;
}

AovImages render_fields(const Camera& camera, std::initializer_list<Aov> list, int width, int height) {
    RenderOptions options;
    options.width = width;
    options.height = height;
    options.aovs.add(Aov::Depth);
    for (Aov a : list) options.aovs.add(a);
    AovImages aovs;
    Light light;
    light.position = {1.0f, 2.0f, 3.0f};
    shared_renderer().render(camera, light, ShadingSelection{}, {}, options, aovs);
    return aovs;
}

// Pixel (x, y) and its depth to the world (pinhole K of the camera file, OpenCV axes).
glm::dvec3 world_point(const Camera& c, int width, int height, int x, int y, double d) {
    const double f = 0.5 * height / std::tan(0.5 * glm::radians(double(c.fov_degrees)));
    const glm::dvec3 cv((x + 0.5 - 0.5 * width) * d / f, (y + 0.5 - 0.5 * height) * d / f, d);
    return glm::dvec3(glm::inverse(glm::dmat4(c.view())) * glm::dvec4(cv.x, -cv.y, -cv.z, 1.0));
}

// numpy.percentile(|v|, 90): linear between the ranks around 0.9 (n - 1), written out here.
double reference_p90(std::vector<double> v) {
    for (double& x : v) x = std::abs(x);
    std::sort(v.begin(), v.end());
    const double rank = 0.9 * double(v.size() - 1);
    const size_t lo = size_t(std::floor(rank)), hi = std::min(lo + 1, v.size() - 1);
    return v[lo] + (rank - double(lo)) * (v[hi] - v[lo]);
}

float p90_of(const AovImages& a, const std::string& name) {
    for (const auto& [n, v] : a.field_scales.p90)
        if (n == name) return v;
    ADD_FAILURE() << "no p90 for " << name;
    return 0.0f;
}

TEST(AovFields, SphereNdotvAndCurvatures) {
    const double radius = 1.5;
    shared_renderer().set_mesh(builtin::sphere(128, 256, float(radius)));
    const Camera c = oblique_camera({3.0f, 2.2f, 5.0f});
    const int w = 200, h = 160;
    const AovImages a = render_fields(c, {Aov::Ndotv, Aov::Kr, Aov::Dwkr, Aov::K1, Aov::K2, Aov::ShadingScales}, w, h);
    ASSERT_EQ(a.ndotv.size(), size_t(w * h));
    ASSERT_EQ(a.shading.size(), size_t(kShadingScales));
    double worst_ndotv = 0.0, worst_k = 0.0, worst_dwkr = 0.0, worst_shading = 0.0;
    std::vector<double> kr, dwkr;
    int n = 0;
    const glm::dvec3 to_light = glm::normalize(glm::dvec3(1.0, 2.0, 3.0));  // directional, from position to target 0
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y * w + x);
            if (a.depth[i] == 0.0f) {
                EXPECT_EQ(a.ndotv[i], 0.0f);  // the background
                EXPECT_EQ(a.kr[i], 0.0f);
                continue;
            }
            const glm::dvec3 p = world_point(c, w, h, x, y, a.depth[i]);
            const glm::dvec3 normal = glm::normalize(p), view = glm::normalize(glm::dvec3(c.eye) - p);
            worst_ndotv = std::max(worst_ndotv, std::abs(a.ndotv[i] - glm::dot(normal, view)));
            for (float k : {a.kr[i], a.k1[i], a.k2[i]}) worst_k = std::max(worst_k, std::abs(k * radius - 1.0));
            worst_dwkr = std::max(worst_dwkr, std::abs(a.dwkr[i]) * radius * radius);
            // Smoothing a sphere's normals leaves them radial: every scale shades as the sphere.
            for (const std::vector<float>& s : a.shading)
                worst_shading = std::max(worst_shading, std::abs(s[i] - std::max(0.0, glm::dot(normal, to_light))));
            kr.push_back(a.kr[i]);
            dwkr.push_back(a.dwkr[i]);
            ++n;
        }
    ASSERT_GT(n, 8000);
    EXPECT_LT(worst_ndotv, 2e-3);
    EXPECT_LT(worst_k, 0.01);     // κr = k1 = k2 = 1/R
    EXPECT_LT(worst_dwkr, 0.05);  // 0 on a sphere: curvature does not change
    EXPECT_LT(worst_shading, 0.01);
    EXPECT_NEAR(p90_of(a, "kr"), reference_p90(kr), 1e-6);
    EXPECT_NEAR(p90_of(a, "dwkr"), reference_p90(dwkr), 1e-6);
    EXPECT_GT(a.field_scales.feature_size, 0.0f);
    EXPECT_EQ(a.field_scales.shading_sigmas.size(), size_t(kShadingScales));
}

// Calls visit(i, p) for each pixel the surface covers: its index and its world point (from the
// depth AOV).
template <class Visit>
void for_covered_pixels(const AovImages& a, const Camera& c, Visit visit) {
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            const size_t i = size_t(y * a.width + x);
            if (a.depth[i] != 0.0f) visit(i, world_point(c, a.width, a.height, x, y, a.depth[i]));
        }
}

// n·v at point p of a sphere about the origin.
double sphere_ndotv(const Camera& c, const glm::dvec3& p) {
    return glm::dot(glm::normalize(p), glm::normalize(glm::dvec3(c.eye) - p));
}

// Faces the GPU draws sorted by material (here: glTF double-sided materials, every other face
// each) are still read as the mesh's own faces: n·v on the sphere as without materials.
TEST(AovFields, FacesSortedByMaterialKeepTheirFields) {
    const double radius = 1.5;
    Mesh sphere = builtin::sphere(64, 128, float(radius));
    for (const char* name : {"a", "b"}) {
        Material m;
        m.name = name;
        m.sides = FaceSides::Double;
        sphere.materials.push_back(m);
    }
    sphere.face_materials.resize(sphere.triangles.size());
    for (size_t f = 0; f < sphere.triangles.size(); ++f) sphere.face_materials[f] = uint32_t(f % 2);
    shared_renderer().set_mesh(std::move(sphere));
    const Camera c = oblique_camera({3.0f, 2.2f, 5.0f});
    const int w = 160, h = 120;
    const AovImages a = render_fields(c, {Aov::Ndotv, Aov::K1}, w, h);
    double worst_ndotv = 0.0, worst_k = 0.0;
    int n = 0;
    for_covered_pixels(a, c, [&](size_t i, const glm::dvec3& p) {
        worst_ndotv = std::max(worst_ndotv, std::abs(a.ndotv[i] - sphere_ndotv(c, p)));
        worst_k = std::max(worst_k, std::abs(a.k1[i] * radius - 1.0));
        ++n;
    });
    ASSERT_GT(n, 4000);
    EXPECT_LT(worst_ndotv, 4e-3);
    EXPECT_LT(worst_k, 0.02);
}

// A mesh of more faces than one draw call takes (GpuMesh draws 2^20 a call): the faces of the
// second call, the sphere's last ten of 360 longitude columns, face the camera and must be
// read as the faces they are.
TEST(AovFields, FacesOfALaterDrawCallKeepTheirNumbers) {
    const double radius = 1.0;
    Mesh sphere = builtin::sphere(1500, 360, float(radius));
    ASSERT_GT(sphere.triangles.size(), size_t(1) << 20);
    shared_renderer().set_mesh(std::move(sphere));
    Camera c = oblique_camera({4.0f, 0.4f, 0.2f});  // the columns at longitude just below 2π: +x, z >= 0
    c.target = {0.0f, 0.0f, 0.0f};
    const int w = 96, h = 72;
    const AovImages a = render_fields(c, {Aov::Ndotv}, w, h);
    double worst = 0.0;
    int n = 0, later = 0;
    for_covered_pixels(a, c, [&](size_t i, const glm::dvec3& p) {
        worst = std::max(worst, std::abs(a.ndotv[i] - sphere_ndotv(c, p)));
        const double longitude = std::atan2(-p.z, p.x);  // builtin::sphere's φ, in (−π, π]
        later += longitude < 0.0 && longitude > -glm::radians(9.0);
        ++n;
    });
    ASSERT_GT(n, 1500);
    EXPECT_GT(later, 60);  // pixels on faces of the second draw call
    EXPECT_LT(worst, 4e-3);
}

// The torus of builtin::torus: S(u, v) = ((R + r cos v) cos u, (R + r cos v) sin u, r sin v).
struct TorusFrame {
    glm::dvec3 normal, meridian, parallel;  // meridian: along v (k = 1/r); parallel: along u
    double k_meridian, k_parallel;
};

TorusFrame torus_frame(const glm::dvec3& p, double major, double minor) {
    const double u = std::atan2(p.y, p.x), v = std::atan2(p.z, std::hypot(p.x, p.y) - major);
    TorusFrame f;
    f.normal = {std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v)};
    f.meridian = {-std::sin(v) * std::cos(u), -std::sin(v) * std::sin(u), std::cos(v)};
    f.parallel = {-std::sin(u), std::cos(u), 0.0};
    f.k_meridian = 1.0 / minor;
    f.k_parallel = std::cos(v) / (major + minor * std::cos(v));
    return f;
}

// The image direction (x right, y down) of world direction d at p, by finite differences of
// the projection: a reference apart from the product's derivative.
glm::dvec2 projected_direction(const Camera& c, int w, int h, const glm::dvec3& p, const glm::dvec3& d) {
    const glm::dmat4 vp = glm::dmat4(c.projection(float(w) / float(h))) * glm::dmat4(c.view());
    auto pixel = [&](const glm::dvec3& q) {
        const glm::dvec4 clip = vp * glm::dvec4(q, 1.0);
        return glm::dvec2((clip.x / clip.w + 1.0) * 0.5 * w, (1.0 - clip.y / clip.w) * 0.5 * h);
    };
    return glm::normalize(pixel(p + 1e-4 * d) - pixel(p - 1e-4 * d));
}

TEST(AovFields, TorusCurvaturesAndDirections) {
    const double major = 1.0, minor = 0.4;
    shared_renderer().set_mesh(builtin::torus(float(major), float(minor), 256, 128));
    const Camera c = oblique_camera({1.5f, -2.5f, 3.0f});
    const int w = 240, h = 180;
    const AovImages a = render_fields(c, {Aov::Kr, Aov::K1, Aov::K2, Aov::Pdir1, Aov::Pdir2}, w, h);
    double err_k1 = 0.0, err_k2 = 0.0, err_kr = 0.0, err_dir = 0.0;
    std::vector<double> k1;
    int n = 0, directions = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y * w + x);
            if (a.depth[i] == 0.0f) continue;
            const glm::dvec3 p = world_point(c, w, h, x, y, a.depth[i]);
            const TorusFrame f = torus_frame(p, major, minor);
            err_k1 = std::max(err_k1, std::abs(a.k1[i] - f.k_meridian) * minor);
            err_k2 = std::max(err_k2, std::abs(a.k2[i] - f.k_parallel) * minor);
            // Euler: κr = k1 cos²φ + k2 sin²φ, φ between w (v in the tangent plane) and pdir1.
            const glm::dvec3 view = glm::normalize(glm::dvec3(c.eye) - p);
            const glm::dvec3 wv = view - glm::dot(view, f.normal) * f.normal;
            const double w2 = glm::dot(wv, wv), cos_phi = glm::dot(wv, f.meridian);
            if (w2 > 0.1) {  // where w vanishes κr's direction turns fast across a face
                const double kr = (f.k_meridian * cos_phi * cos_phi + f.k_parallel * (w2 - cos_phi * cos_phi)) / w2;
                err_kr = std::max(err_kr, std::abs(a.kr[i] - kr) * minor);
            }
            // Principal directions: the axis (either sign) of the projected meridian and parallel.
            const glm::dvec2 d1(a.pdir1[2 * i], a.pdir1[2 * i + 1]), d2(a.pdir2[2 * i], a.pdir2[2 * i + 1]);
            EXPECT_NEAR(glm::length(d1), 1.0, 1e-4);
            EXPECT_TRUE(d1.x > 0.0 || (d1.x == 0.0 && d1.y > 0.0));
            if (std::abs(glm::dot(f.normal, view)) > 0.3) {  // away from the contour's foreshortening
                err_dir = std::max({err_dir, 1.0 - std::abs(glm::dot(d1, projected_direction(c, w, h, p, f.meridian))),
                                    1.0 - std::abs(glm::dot(d2, projected_direction(c, w, h, p, f.parallel)))});
                ++directions;
            }
            k1.push_back(a.k1[i]);
            ++n;
        }
    ASSERT_GT(n, 8000);
    ASSERT_GT(directions, 4000);
    // Measured (256 x 128 torus, 240 x 180): 0.0002, 0.0007, 0.0099 and 3.7e-7.
    EXPECT_LT(err_k1, 0.005);  // relative to 1/r
    EXPECT_LT(err_k2, 0.005);
    EXPECT_LT(err_kr, 0.02);
    EXPECT_LT(err_dir, 1e-5);  // 1 - cos of the angle: under 0.26 degrees
    EXPECT_NEAR(p90_of(a, "k1"), reference_p90(k1), 1e-6);
}

TEST(AovFields, NamesAndFiles) {
    EXPECT_EQ(aov_named("NdotV"), Aov::Ndotv);
    EXPECT_EQ(aov_named("shading-scales"), Aov::ShadingScales);
    AovSet set;
    set.add(Aov::Pdir1);
    set.add(Aov::ShadingScales);
    const std::vector<std::string> files = aov_file_names("out/a.png", set, {});
    const std::vector<std::string> want = {"a.pdir1.exr",      "a.shading-s0.png", "a.shading-s1.png",
                                           "a.shading-s2.png", "a.shading-s3.png", "a.shading-s4.png",
                                           "a.camera.json"};
    EXPECT_EQ(files, want);
}

}  // namespace
}  // namespace inkshade
