// Shared pieces of the GL tests: one headless renderer per test binary, an orthographic
// camera looking down -z, and a CPU ray caster that recovers what each pixel sees.
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <memory>
#include <optional>

#include <glm/glm.hpp>

#include "geometry/builtin_models.hpp"
#include "inkshade/camera.hpp"
#include "inkshade/renderer.hpp"

namespace inkshade::test {

// One GL context for the whole binary (creating contexts is slow on llvmpipe).
inline Renderer& shared_renderer() {
    static std::unique_ptr<Renderer> renderer = std::make_unique<Renderer>();
    return *renderer;
}

constexpr int kSize = 256;
constexpr float kPi = 3.14159265358979f;

// The sRGB transfer function (IEC 61966-2-1) of the tests' CPU references, clamped to [0, 1]:
// written out here, apart from the product's linear_to_srgb.
inline float reference_srgb(float c) {
    c = std::clamp(c, 0.0f, 1.0f);
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}
inline glm::vec3 reference_srgb(const glm::vec3& c) { return {reference_srgb(c.r), reference_srgb(c.g), reference_srgb(c.b)}; }

// The unit sphere most pixel tests render: fine enough (128 x 256) that interpolated normals
// match the analytic ones within the 2/255 tolerance. Built once per test binary.
inline const Mesh& fine_sphere() {
    static const Mesh sphere = builtin::sphere(128, 256);
    return sphere;
}

// Orthographic camera on +z looking at the origin; the view is 2.5 units high.
inline Camera ortho_camera() {
    Camera c;
    c.eye = {0, 0, 5};
    c.target = {0, 0, 0};
    c.up = {0, 1, 0};
    c.orthographic = true;
    c.ortho_height = 2.5f;
    c.near_plane = 1.0f;
    c.far_plane = 10.0f;
    return c;
}

// What a pixel test renders: the light, the shading model with its parameters, the image.
struct PixelScene {
    Light light;
    ShadingSelection shading;
    RenderOptions options;
    glm::vec3 l() const { return glm::normalize(light.position - light.target); }  // towards the light
};

// A directional light shining from `direction` (towards the light) onto the origin.
inline Light directional_light(const glm::vec3& direction, const glm::vec3& color, const glm::vec3& ambient) {
    Light l;
    l.type = LightType::Directional;
    l.target = glm::vec3(0);
    l.position = glm::normalize(direction) * 10.0f;
    l.color = color;
    l.ambient = ambient;
    return l;
}

// World-space ray through image point (x, y) in pixels (top-left origin, y down) for the
// orthographic camera above: origin on the near plane, direction -z.
// Lit only by ambient A = 1 (E = 0): a lambert pixel is exactly C (base colour times the
// vertex, material or texture colour).
inline Light ambient_only() { return directional_light({0, 0, 1}, glm::vec3(0), glm::vec3(1)); }

inline glm::vec3 ray_origin(const Camera& c, float x, float y, int w = kSize, int h = kSize) {
    float half_h = 0.5f * c.ortho_height, half_w = half_h * float(w) / float(h);
    float wx = (x / float(w) * 2.0f - 1.0f) * half_w;
    float wy = (1.0f - y / float(h) * 2.0f) * half_h;
    return {wx, wy, c.eye.z};
}

// Image position of a world point under the same camera.
inline glm::vec2 project(const Camera& c, const glm::vec3& p, int w = kSize, int h = kSize) {
    float half_h = 0.5f * c.ortho_height, half_w = half_h * float(w) / float(h);
    return {(p.x / half_w + 1.0f) * 0.5f * float(w), (1.0f - p.y / half_h) * 0.5f * float(h)};
}

struct Hit {
    int triangle = -1;
    glm::vec3 point{0.0f};
    glm::vec3 barycentric{0.0f};  // weights of the triangle's vertices 0, 1, 2
};

// Nearest hit of the ray (origin, -z) on the mesh (Moller-Trumbore), or nullopt.
inline std::optional<Hit> cast_down(const Mesh& mesh, const glm::vec3& origin) {
    const glm::vec3 dir(0, 0, -1);
    std::optional<Hit> best;
    float best_t = INFINITY;
    for (size_t f = 0; f < mesh.triangles.size(); ++f) {
        const glm::vec3 a = mesh.positions[mesh.triangles[f].x], b = mesh.positions[mesh.triangles[f].y],
                        c = mesh.positions[mesh.triangles[f].z];
        glm::vec3 e1 = b - a, e2 = c - a, pv = glm::cross(dir, e2);
        float det = glm::dot(e1, pv);
        if (std::abs(det) < 1e-12f) continue;
        glm::vec3 tv = origin - a;
        float u = glm::dot(tv, pv) / det;
        if (u < 0 || u > 1) continue;
        glm::vec3 qv = glm::cross(tv, e1);
        float v = glm::dot(dir, qv) / det;
        if (v < 0 || u + v > 1) continue;
        float t = glm::dot(e2, qv) / det;
        if (t > 0 && t < best_t) {
            best_t = t;
            best = Hit{int(f), origin + t * dir, {1 - u - v, u, v}};
        }
    }
    return best;
}

// Ray/sphere (centre 0, radius r) for the analytic normal at a pixel; nullopt on a miss.
inline std::optional<glm::vec3> sphere_normal(const glm::vec3& origin, float r = 1.0f) {
    float d2 = origin.x * origin.x + origin.y * origin.y;
    if (d2 >= r * r) return std::nullopt;
    return glm::vec3(origin.x, origin.y, std::sqrt(r * r - d2)) / r;
}

inline int to_byte(float v) { return int(std::lround(255.0f * std::clamp(v, 0.0f, 1.0f))); }

// Renders `mesh` with the orthographic test camera.
inline Image render_ortho(const Mesh& mesh, const Light& light, const ShadingSelection& shading,
                          const RenderOptions& options) {
    Renderer& r = shared_renderer();
    r.set_mesh(mesh);
    return r.render(ortho_camera(), light, shading, options);
}

// Compares, at every pixel of a 24x24 grid inside the unit sphere's disc with n.z > min_nz
// (away from the outline), the rendered colour with expected(n) within 2/255, n the analytic
// normal under the pixel centre; returns how many pixels were compared.
inline int compare_on_sphere(const Image& img, const std::function<glm::vec3(const glm::vec3&)>& expected,
                             float min_nz = 0.2f, const std::string& what = "") {
    const Camera cam = ortho_camera();
    int compared = 0;
    for (int gy = 0; gy < 24; ++gy)
        for (int gx = 0; gx < 24; ++gx) {
            int px = 8 + gx * 10, py = 8 + gy * 10;
            auto n = sphere_normal(ray_origin(cam, px + 0.5f, py + 0.5f));
            if (!n || n->z < min_nz) continue;
            glm::vec3 want = expected(*n);
            const uint8_t* got = img.pixel(px, py);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(int(got[c]), to_byte(want[c]), 2)
                    << what << " pixel (" << px << "," << py << ") channel " << c << " n=(" << n->x << "," << n->y
                    << "," << n->z << ")";
            ++compared;
        }
    return compared;
}

}  // namespace inkshade::test
