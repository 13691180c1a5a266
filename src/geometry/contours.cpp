// Occluding contours from per-vertex n·v. Faces are processed in fixed-size blocks in parallel
// (TBB); each block writes its own list and the lists are joined in block order, so the output
// is in face order whatever the thread count.
#include "geometry/contours.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "geometry/face_segments.hpp"

#include "geometry/normals.hpp"

namespace inkshade::geometry {
namespace {

constexpr size_t kGrain = 16384;  // faces (or vertices) per TBB task: small meshes stay on one thread

bool valid(const glm::uvec3& t, size_t n) { return t.x < n && t.y < n && t.z < n; }

}  // namespace

ViewVector::ViewVector(const Camera& camera) : eye_(camera.eye), orthographic_(camera.orthographic) {
    const glm::dvec3 d = glm::dvec3(camera.eye) - glm::dvec3(camera.target);
    const double len = glm::length(d);
    ortho_dir_ = len > 0.0 && std::isfinite(len) ? d / len : glm::dvec3(0.0, 0.0, 1.0);
}

glm::dvec3 ViewVector::at(const glm::vec3& p) const {
    if (orthographic_) return ortho_dir_;
    const glm::dvec3 d = eye_ - glm::dvec3(p);
    const double len = glm::length(d);
    return len > 0.0 && std::isfinite(len) ? d / len : glm::dvec3(0.0);
}

EdgeCrossing edge_zero_crossing(const Mesh& mesh, const std::vector<float>& g, uint32_t i, uint32_t j) {
    if (j < i) std::swap(i, j);
    const double gi = g[i], gj = g[j];
    EdgeCrossing c;
    c.t = gi / (gi - gj);  // signs differ, so gi − gj ≠ 0 and t ∈ [0, 1]
    const glm::dvec3 pi(mesh.positions[i]), pj(mesh.positions[j]);
    c.p = glm::vec3(pi + c.t * (pj - pi));
    return c;
}

std::vector<float> view_dot_normal(const Mesh& mesh, const std::vector<glm::vec3>& normals, const Camera& camera) {
    if (normals.size() != mesh.positions.size())
        throw std::invalid_argument("view_dot_normal: need one normal per vertex");
    const ViewVector view(camera);
    std::vector<float> g(normals.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, g.size(), kGrain), [&](const auto& range) {
        for (size_t v = range.begin(); v != range.end(); ++v) {
            const double d = glm::dot(glm::dvec3(normals[v]), view.at(mesh.positions[v]));
            g[v] = std::isfinite(d) ? float(d) : 0.0f;
        }
    });
    return g;
}

std::vector<LineSegment> extract_contours(const Mesh& mesh, const std::vector<glm::vec3>& normals,
                                          const Camera& camera) {
    const std::vector<float> g = view_dot_normal(mesh, normals, camera);
    const auto& tris = mesh.triangles;
    const size_t n = mesh.positions.size();
    return collect_face_segments(tris.size(), [&](size_t f, std::vector<LineSegment>& out) {
        const glm::uvec3 t = tris[f];
        if (!valid(t, n)) return;
        const bool pos[3] = {g[t.x] >= 0.0f, g[t.y] >= 0.0f, g[t.z] >= 0.0f};
        if (pos[0] == pos[1] && pos[1] == pos[2]) return;
        // k: the vertex whose sign differs from the other two.
        const int k = pos[1] == pos[2] ? 0 : (pos[0] == pos[2] ? 1 : 2);
        const uint32_t vk = t[k], vnext = t[(k + 1) % 3], vprev = t[(k + 2) % 3];
        LineSegment s;
        s.face = uint32_t(f);
        s.edge_a = edge_key(vk, vnext);
        s.edge_b = edge_key(vprev, vk);
        if (s.edge_a == s.edge_b) return;  // repeated index: no segment
        s.a = edge_zero_crossing(mesh, g, vk, vnext).p;
        s.b = edge_zero_crossing(mesh, g, vprev, vk).p;
        // Triangle (k, a, b) is counter-clockwise, so k lies left of a → b: keep g ≥ 0 left.
        if (!pos[k]) {
            std::swap(s.a, s.b);
            std::swap(s.edge_a, s.edge_b);
        }
        out.push_back(s);
    });
}

std::vector<SilhouetteEdge> mesh_silhouette_edges(const Mesh& mesh, const Camera& camera) {
    const auto& tris = mesh.triangles;
    const size_t n = mesh.positions.size();
    const std::vector<glm::vec3> fn = face_normals(mesh);
    const ViewVector view(camera);

    // Facing per face: +1 front, −1 back, 0 degenerate or invalid.
    std::vector<int8_t> facing(tris.size(), 0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, tris.size(), kGrain), [&](const auto& range) {
        for (size_t f = range.begin(); f != range.end(); ++f) {
            const glm::uvec3 t = tris[f];
            if (!valid(t, n) || fn[f] == glm::vec3(0.0f)) continue;
            const glm::vec3 c = (mesh.positions[t.x] + mesh.positions[t.y] + mesh.positions[t.z]) / 3.0f;
            const double d = glm::dot(glm::dvec3(fn[f]), view.at(c));
            facing[f] = d > 0.0 ? 1 : (d < 0.0 ? -1 : 0);
        }
    });

    // (edge key, facing) pairs sorted by key; a group is a silhouette when it has both facings.
    std::vector<std::pair<uint64_t, int8_t>> edges;
    edges.reserve(3 * tris.size());
    for (size_t f = 0; f < tris.size(); ++f) {
        if (facing[f] == 0) continue;
        const glm::uvec3 t = tris[f];
        for (int e = 0; e < 3; ++e) {
            const uint32_t i = t[e], j = t[(e + 1) % 3];
            if (i != j) edges.emplace_back(edge_key(i, j), facing[f]);
        }
    }
    tbb::parallel_sort(edges.begin(), edges.end());

    std::vector<SilhouetteEdge> out;
    for (size_t i = 0; i < edges.size();) {
        size_t j = i;
        bool front = false, back = false;
        for (; j < edges.size() && edges[j].first == edges[i].first; ++j) (edges[j].second > 0 ? front : back) = true;
        if (front && back) out.push_back({uint32_t(edges[i].first >> 32), uint32_t(edges[i].first & 0xffffffffu)});
        i = j;
    }
    return out;
}

}  // namespace inkshade::geometry
