// Face and vertex normals. Per-face work runs in parallel (TBB); accumulation into vertices is
// a sequential scatter in face order, so results are bit-identical from run to run.
#include "geometry/normals.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>

namespace inkshade::geometry {
namespace {

constexpr size_t kGrain = 16384;  // faces per TBB task: small meshes stay on one thread

bool valid(const glm::uvec3& t, size_t n) { return t.x < n && t.y < n && t.z < n; }

}  // namespace

std::vector<glm::vec3> face_normals(const Mesh& mesh) {
    const auto& p = mesh.positions;
    const auto& tris = mesh.triangles;
    std::vector<glm::vec3> out(tris.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, tris.size(), kGrain), [&](const auto& range) {
        for (size_t f = range.begin(); f != range.end(); ++f) {
            const glm::uvec3 t = tris[f];
            out[f] = valid(t, p.size()) ? unit_normal(p[t.x], p[t.y], p[t.z]) : glm::vec3(0.0f);
        }
    });
    return out;
}

// Thürmer & Wüthrich 1998, "Computing vertex normals from polygonal facets": weighting each
// face's normal by its angle at the vertex makes the result independent of how the surface
// around the vertex is triangulated.
std::vector<glm::vec3> angle_weighted_vertex_normals(const Mesh& mesh) {
    return angle_weighted_vertex_normals(mesh, face_normals(mesh));
}

std::vector<glm::vec3> angle_weighted_vertex_normals(const Mesh& mesh, const std::vector<glm::vec3>& fn) {
    const auto& p = mesh.positions;
    const auto& tris = mesh.triangles;
    std::vector<glm::vec3> angles(tris.size());  // interior angle at each corner
    tbb::parallel_for(tbb::blocked_range<size_t>(0, tris.size(), kGrain), [&](const auto& range) {
        for (size_t f = range.begin(); f != range.end(); ++f) {
            const glm::uvec3 t = tris[f];
            if (fn[f] == glm::vec3(0.0f)) continue;  // degenerate or invalid: contributes nothing
            const glm::vec3 a = p[t.x], b = p[t.y], c = p[t.z];
            angles[f] = {angle_between(b - a, c - a), angle_between(c - b, a - b), angle_between(a - c, b - c)};
        }
    });
    std::vector<glm::vec3> sum(p.size(), glm::vec3(0.0f));
    for (size_t f = 0; f < tris.size(); ++f) {
        if (fn[f] == glm::vec3(0.0f)) continue;
        for (int k = 0; k < 3; ++k) sum[tris[f][k]] += angles[f][k] * fn[f];
    }
    tbb::parallel_for(tbb::blocked_range<size_t>(0, sum.size(), kGrain), [&](const auto& range) {
        for (size_t v = range.begin(); v != range.end(); ++v) {
            const float len = glm::length(sum[v]);
            // Isolated vertices (and ones whose faces cancel out) still need a usable normal.
            sum[v] = (len > 0.0f && std::isfinite(len)) ? sum[v] / len : glm::vec3(0.0f, 0.0f, 1.0f);
        }
    });
    return sum;
}

std::vector<glm::vec3> area_weighted_vertex_normals(const Mesh& mesh) {
    const auto& p = mesh.positions;
    std::vector<glm::dvec3> sum(p.size(), glm::dvec3(0.0));
    for (const glm::uvec3& t : mesh.triangles) {
        if (t.x >= p.size() || t.y >= p.size() || t.z >= p.size()) continue;
        const glm::dvec3 a(p[t.x]), b(p[t.y]), c(p[t.z]);
        const glm::dvec3 n = glm::cross(b - a, c - a);
        if (!std::isfinite(n.x + n.y + n.z)) continue;
        for (int k = 0; k < 3; ++k) sum[t[k]] += n;
    }
    std::vector<glm::vec3> out(p.size());
    for (size_t v = 0; v < p.size(); ++v) {
        const double len = glm::length(sum[v]);
        out[v] = (len > 0.0 && std::isfinite(len)) ? glm::vec3(sum[v] / len) : glm::vec3(0.0f, 0.0f, 1.0f);
    }
    return out;
}

float corner_weight(const Mesh& mesh, size_t f, int k, NormalWeighting weighting) {
    const glm::uvec3 t = mesh.triangles[f];
    const glm::vec3 a = mesh.positions[t[k]], b = mesh.positions[t[(k + 1) % 3]], c = mesh.positions[t[(k + 2) % 3]];
    if (weighting == NormalWeighting::Angle) return angle_between(b - a, c - a);
    const float area2 = float(glm::length(glm::cross(glm::dvec3(b) - glm::dvec3(a), glm::dvec3(c) - glm::dvec3(a))));
    return std::isfinite(area2) ? area2 : 0.0f;
}

bool normals_are_sane(const Mesh& mesh) {
    if (mesh.normals.size() != mesh.positions.size()) return false;
    for (const glm::vec3& n : mesh.normals) {
        const float len2 = glm::dot(n, n);
        if (!is_finite(n) || !(len2 > 0.0f) || !std::isfinite(len2)) return false;
    }
    return true;
}

void ensure_vertex_normals(Mesh& mesh, NormalWeighting weighting) {
    if (!normals_are_sane(mesh)) {
        mesh.normals = weighting == NormalWeighting::Area ? area_weighted_vertex_normals(mesh)
                                                          : angle_weighted_vertex_normals(mesh);
        return;
    }
    for (glm::vec3& n : mesh.normals) n = glm::normalize(n);
}

}  // namespace inkshade::geometry
