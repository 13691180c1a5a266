// Fans are found vertex by vertex over the vertex's own faces (a few, typically six): no
// mesh-wide edge table or union-find over 3F corners, and the vertices run in parallel.
// Normal ids are numbered vertex by vertex and, within a vertex, in order of each fan's lowest
// face, so the result does not depend on the thread count.
#include "geometry/auto_smooth.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "geometry/normals.hpp"

namespace inkshade::geometry {
namespace {

constexpr size_t kGrain = 4096;  // vertices per TBB task

// The faces around each vertex, in face order: faces[offsets[v] .. offsets[v + 1]).
struct VertexFaces {
    std::vector<uint32_t> offsets, faces;
};

struct Scratch {  // per-task buffers of fans_at
    std::vector<uint32_t> parent, fan, root_fan;
    std::vector<std::pair<uint32_t, uint32_t>> spokes;  // (other vertex, local face)
};

VertexFaces vertex_faces(const Mesh& mesh) {
    const size_t n = mesh.positions.size();
    VertexFaces vf;
    vf.offsets.assign(n + 1, 0);
    for (const glm::uvec3& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) ++vf.offsets[t[k] + 1];
    std::partial_sum(vf.offsets.begin(), vf.offsets.end(), vf.offsets.begin());
    vf.faces.resize(vf.offsets[n]);
    std::vector<uint32_t> fill(vf.offsets.begin(), vf.offsets.end() - 1);
    for (size_t f = 0; f < mesh.triangles.size(); ++f)
        for (int k = 0; k < 3; ++k) vf.faces[fill[mesh.triangles[f][k]]++] = uint32_t(f);
    return vf;
}

// Fan of each of vertex v's faces (local indices 0..k-1 into `star`), numbered in order of
// each fan's first face; returns the number of fans. Degenerate faces get their own fan.
// Two faces of the star share the edge (v, w) when both have w; the edge is smooth when
// exactly these two faces have it and their normals are close enough. The (w, face) pairs are
// sorted, so a vertex with thousands of faces (the centre of a triangle fan) costs k log k.
uint32_t fans_at(uint32_t v, const Mesh& mesh, const std::vector<glm::vec3>& fn, const uint32_t* star, size_t k,
                 float cos_limit, Scratch& s) {
    s.parent.resize(k);
    std::iota(s.parent.begin(), s.parent.end(), 0u);
    auto find = [&](uint32_t i) {
        while (s.parent[i] != i) i = s.parent[i] = s.parent[s.parent[i]];
        return i;
    };
    s.spokes.clear();
    for (size_t a = 0; a < k; ++a) {
        if (a > 0 && star[a] == star[a - 1]) continue;  // a face listed twice (repeated index)
        const glm::uvec3 t = mesh.triangles[star[a]];
        for (int c = 0; c < 3; ++c)
            if (t[c] != v && (c == 0 || t[c] != t[c - 1]) && !(c == 2 && t[2] == t[0]))
                s.spokes.emplace_back(t[c], uint32_t(a));
    }
    std::sort(s.spokes.begin(), s.spokes.end());
    for (size_t i = 0; i < s.spokes.size();) {
        size_t j = i;
        while (j < s.spokes.size() && s.spokes[j].first == s.spokes[i].first) ++j;
        if (j - i == 2) {
            const uint32_t a = s.spokes[i].second, b = s.spokes[i + 1].second;
            const glm::vec3 na = fn[star[a]], nb = fn[star[b]];
            if (na != glm::vec3(0.0f) && nb != glm::vec3(0.0f) && glm::dot(na, nb) >= cos_limit)
                s.parent[find(a)] = find(b);
        }
        i = j;
    }
    s.fan.assign(k, 0);
    s.root_fan.assign(k, ~0u);
    uint32_t count = 0;
    for (size_t a = 0; a < k; ++a) {
        uint32_t& id = s.root_fan[find(uint32_t(a))];
        if (id == ~0u) id = count++;
        s.fan[a] = id;
    }
    return count;
}

}  // namespace

void auto_smooth(Mesh& mesh, float angle_degrees, NormalWeighting weighting) {
    mesh.shading_normals.clear();
    mesh.shading_normal_ids.clear();
    if (!(angle_degrees < 180.0f) || mesh.triangles.empty()) return;
    const size_t n = mesh.positions.size();
    for (const glm::uvec3& t : mesh.triangles)
        if (t.x >= n || t.y >= n || t.z >= n) return;  // load_mesh validates first; nothing to split here
    const std::vector<glm::vec3> fn = face_normals(mesh);
    const VertexFaces vf = vertex_faces(mesh);
    // Compared as a dot product of unit normals; the small slack keeps exactly-at-limit edges
    // (a 30° split of a 12-gon prism) on the smooth side whatever the rounding.
    const float cos_limit = std::cos(glm::radians(std::max(angle_degrees, 0.0f))) - 1e-6f;

    // Pass 1: fans per vertex. Pass 2: their normals, numbered after a prefix sum.
    std::vector<uint32_t> fan_count(n + 1, 0);
    std::vector<uint32_t> corner_fan(vf.faces.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, kGrain), [&](const auto& range) {
        Scratch scratch;
        for (size_t v = range.begin(); v != range.end(); ++v) {
            const size_t begin = vf.offsets[v], k = vf.offsets[v + 1] - begin;
            fan_count[v + 1] = fans_at(uint32_t(v), mesh, fn, vf.faces.data() + begin, k, cos_limit, scratch);
            std::copy(scratch.fan.begin(), scratch.fan.end(), corner_fan.begin() + begin);
        }
    });
    bool any_split = false;
    for (size_t v = 0; v < n && !any_split; ++v) any_split = fan_count[v + 1] > 1;
    if (!any_split) return;
    std::partial_sum(fan_count.begin(), fan_count.end(), fan_count.begin());

    std::vector<glm::vec3> sums(fan_count[n], glm::vec3(0.0f));
    std::vector<glm::uvec3> ids(mesh.triangles.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, kGrain), [&](const auto& range) {
        for (size_t v = range.begin(); v != range.end(); ++v) {
            int c = -1;
            for (uint32_t i = vf.offsets[v]; i < vf.offsets[v + 1]; ++i) {
                const uint32_t f = vf.faces[i];
                const glm::uvec3 t = mesh.triangles[f];
                // The face's next corner at v: a face with a repeated index is listed once per
                // corner, consecutively.
                c = (i > vf.offsets[v] && vf.faces[i - 1] == f) ? c + 1 : 0;
                while (t[c] != v) ++c;
                // A repeated face's second listing shares the first one's fan.
                const uint32_t first = (i > vf.offsets[v] && vf.faces[i - 1] == f) ? corner_fan[i - 1] : corner_fan[i];
                const uint32_t id = fan_count[v] + first;
                ids[f][c] = id;  // each (face, corner) is written by its vertex's task only
                sums[id] += corner_weight(mesh, f, c, weighting) * fn[f];
            }
        }
    });
    for (size_t v = 0; v < n; ++v) {
        for (uint32_t id = fan_count[v]; id < fan_count[v + 1]; ++id) {
            const float len = glm::length(sums[id]);
            // A fan of degenerate faces has no direction of its own: the smooth normal.
            sums[id] = len > 0.0f && std::isfinite(len) ? sums[id] / len
                       : v < mesh.normals.size()        ? mesh.normals[v]
                                                        : glm::vec3(0.0f, 0.0f, 1.0f);
        }
    }
    mesh.shading_normals = std::move(sums);
    mesh.shading_normal_ids = std::move(ids);
}

}  // namespace inkshade::geometry
