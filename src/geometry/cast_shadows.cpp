#include "geometry/cast_shadows.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geometry/triangle_vertices.hpp"
#include "geometry/visibility.hpp"

namespace inkshade::geometry {

namespace {

// The ray towards the light from p: a directional light's unit direction, or the vector to a
// point light's position (the ray ends at the light, t = 1).
glm::dvec3 towards_light(const Light& light, const glm::vec3& p) {
    return light.type == LightType::Directional ? glm::dvec3(light.direction_to_light(p))
                                                : glm::dvec3(light.position) - glm::dvec3(p);
}

// Twice the longest edge at each vertex (0 for a vertex of no valid face): how far a coarse
// mesh's own surface can pass in front of a ray leaving it (in_cast_shadow's `acne`).
std::vector<float> acne_distances(const Mesh& mesh) {
    std::vector<float> acne(mesh.positions.size(), 0.0f);
    for (const glm::uvec3& t : mesh.triangles) {
        if (!in_range(t, mesh.positions.size())) continue;
        for (int k = 0; k < 3; ++k) {
            const float e = 2.0f * glm::length(mesh.positions[t[(k + 1) % 3]] - mesh.positions[t[k]]);
            if (!std::isfinite(e)) continue;
            acne[t[k]] = std::max(acne[t[k]], e);
            acne[t[(k + 1) % 3]] = std::max(acne[t[(k + 1) % 3]], e);
        }
    }
    return acne;
}

bool valid_triangle(const Mesh& mesh, const glm::uvec3& t) {
    return in_range(t, mesh.positions.size()) && t.x != t.y && t.y != t.z && t.z != t.x;
}

// Faces per block of the parallel loop: fixed, so the output does not depend on the threads.
constexpr size_t kBlock = 4096;

}  // namespace

bool in_cast_shadow(const RayScene& scene, const Mesh& mesh, const Light& light, const glm::vec3& p, double skip,
                    double acne) {
    const glm::dvec3 dir = towards_light(light, p);
    const double len = glm::length(dir);
    if (!(len > 0.0) || !std::isfinite(len)) return false;
    const bool ends_at_light = light.type != LightType::Directional;
    double t_min = skip / len;
    // A ray leaves a solid at most a few times within `acne`; a bound keeps a degenerate mesh finite.
    for (int hits = 0; hits < 16; ++hits) {
        const std::optional<RayScene::Hit> hit = scene.first_hit(glm::dvec3(p), dir, t_min);
        if (!hit || (ends_at_light && hit->t >= 1.0)) return false;
        const glm::uvec3 t = mesh.triangles[hit->face];
        const glm::dvec3 a(mesh.positions[t.x]), b(mesh.positions[t.y]), c(mesh.positions[t.z]);
        const bool leaves = glm::dot(glm::cross(b - a, c - a), dir) > 0.0;
        if (!leaves || hit->t * len >= acne) return true;
        t_min = hit->t + skip / len;
    }
    return true;
}

std::vector<LineSegment> extract_cast_shadows(const Mesh& mesh, const std::vector<glm::vec3>& normals,
                                              const Light& light, const RayScene& scene) {
    if (normals.size() != mesh.positions.size())
        throw std::invalid_argument("extract_cast_shadows: need one normal per vertex");
    const size_t nv = mesh.positions.size();
    const std::vector<float> acne = acne_distances(mesh);
    const double skip = 10.0 * scene.tolerance();
    // Per vertex: 0 turned away from the light (or in no face), 1 lit, 2 in cast shadow.
    std::vector<uint8_t> state(nv, 0);
    tbb::parallel_for(size_t(0), (nv + kBlock - 1) / kBlock, [&](size_t block) {
        for (size_t v = block * kBlock; v < std::min(nv, (block + 1) * kBlock); ++v) {
            const glm::vec3 p = mesh.positions[v];
            if (acne[v] == 0.0f || !(glm::dot(glm::dvec3(normals[v]), towards_light(light, p)) > 0.0)) continue;
            state[v] = in_cast_shadow(scene, mesh, light, p, skip, acne[v]) ? 2 : 1;
        }
    });
    // The boundary on edge (i, j), from the lower index to the higher, so both faces get its bits.
    const auto crossing = [&](uint32_t i, uint32_t j) {
        const uint32_t lo = std::min(i, j), hi = std::max(i, j);
        const glm::dvec3 a(mesh.positions[lo]), b(mesh.positions[hi]);
        const double edge_acne = std::max(acne[lo], acne[hi]);
        double t0 = 0.0, t1 = 1.0;
        for (int k = 0; k < kCastShadowBisections; ++k) {
            const double t = 0.5 * (t0 + t1);
            const bool shadow = in_cast_shadow(scene, mesh, light, glm::vec3(a + t * (b - a)), skip, edge_acne);
            (shadow == (state[lo] == 2) ? t0 : t1) = t;
        }
        return glm::vec3(a + 0.5 * (t0 + t1) * (b - a));
    };
    const size_t nf = mesh.triangles.size();
    std::vector<std::vector<LineSegment>> blocks((nf + kBlock - 1) / kBlock);
    tbb::parallel_for(size_t(0), blocks.size(), [&](size_t block) {
        for (size_t f = block * kBlock; f < std::min(nf, (block + 1) * kBlock); ++f) {
            const glm::uvec3 t = mesh.triangles[f];
            if (!valid_triangle(mesh, t) || !state[t.x] || !state[t.y] || !state[t.z]) continue;
            if (state[t.x] == state[t.y] && state[t.y] == state[t.z]) continue;
            LineSegment s;
            s.face = uint32_t(f);
            int ends = 0;
            for (int k = 0; k < 3; ++k) {
                const uint32_t i = t[k], j = t[(k + 1) % 3];
                if (state[i] == state[j]) continue;
                (ends == 0 ? s.a : s.b) = crossing(i, j);
                (ends == 0 ? s.edge_a : s.edge_b) = edge_key(i, j);
                ++ends;
            }
            blocks[block].push_back(s);
        }
    });
    std::vector<LineSegment> segments;
    for (const auto& b : blocks) segments.insert(segments.end(), b.begin(), b.end());
    return segments;
}

}  // namespace inkshade::geometry
