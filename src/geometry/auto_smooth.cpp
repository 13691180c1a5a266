// Hard edges come from hard_edge_flags (hard_edges.hpp). Fans are then found vertex by vertex
// over the vertex's own faces (a few, typically six): no mesh-wide edge table or union-find
// over 3F corners, and the vertices run in parallel. Normal ids are numbered vertex by vertex
// and, within a vertex, in order of each fan's lowest face, so the result does not depend on
// the thread count.
#include "geometry/auto_smooth.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>

#include "geometry/hard_edge_groups.hpp"
#include "geometry/hard_edges.hpp"
#include "geometry/normals.hpp"
#include "geometry/vertex_faces.hpp"

namespace inkshade::geometry {
namespace {

constexpr size_t kGrain = 4096;  // vertices per TBB task

struct Scratch {  // per-task buffers of fans_at
    std::vector<uint32_t> parent, fan, root_fan;
    std::vector<std::pair<uint32_t, uint32_t>> spokes;  // (other vertex, local face)

    uint32_t find(uint32_t i) {
        while (parent[i] != i) i = parent[i] = parent[parent[i]];
        return i;
    }
};

// Whether face f's edge between its corners at v and w is hard (hard_edge_flags).
bool is_hard(const Mesh& mesh, const std::vector<uint8_t>& hard, uint32_t f, uint32_t v, uint32_t w) {
    const glm::uvec3 t = mesh.triangles[f];
    for (int k = 0; k < 3; ++k) {
        const uint32_t a = t[k], b = t[(k + 1) % 3];
        if ((a == v && b == w) || (a == w && b == v)) return (hard[f] >> k) & 1u;
    }
    return true;
}

// Numbers the union-find sets of the star in order of their first face into s.fan; returns
// the count. Degenerate faces (zero normal), joined to nothing, go to the one fan of the
// others when there is one: they add nothing to its normal, and a vertex with one fan needs
// no split.
uint32_t number_fans(const std::vector<glm::vec3>& fn, const uint32_t* star, size_t k, Scratch& s) {
    uint32_t only = ~0u;  // the one root of the non-degenerate faces, ~0u for none, ~1u for several
    for (size_t a = 0; a < k && only != ~1u; ++a)
        if (fn[star[a]] != glm::vec3(0.0f)) {
            const uint32_t root = s.find(uint32_t(a));
            only = only == ~0u || only == root ? root : ~1u;
        }
    s.fan.assign(k, 0);
    s.root_fan.assign(k, ~0u);
    uint32_t count = 0;
    for (size_t a = 0; a < k; ++a) {
        const bool joins_only = only < k && fn[star[a]] == glm::vec3(0.0f);
        uint32_t& id = s.root_fan[joins_only ? only : s.find(uint32_t(a))];
        if (id == ~0u) id = count++;
        s.fan[a] = id;
    }
    return count;
}

// Fan of each of vertex v's faces (local indices 0..k-1 into `star`); returns the number of
// fans. Two faces of the star share the edge (v, w) when both have w; they join when exactly
// these two faces have it, neither is degenerate and the edge is not hard. The (w, face) pairs
// are sorted, so a vertex with thousands of faces (the centre of a triangle fan) costs k log k.
uint32_t fans_at(uint32_t v, const Mesh& mesh, const std::vector<glm::vec3>& fn, const std::vector<uint8_t>& hard,
                 const uint32_t* star, size_t k, Scratch& s) {
    s.parent.resize(k);
    std::iota(s.parent.begin(), s.parent.end(), 0u);
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
            if (fn[star[a]] != glm::vec3(0.0f) && fn[star[b]] != glm::vec3(0.0f) &&
                !is_hard(mesh, hard, star[a], v, s.spokes[i].first))
                s.parent[s.find(a)] = s.find(b);
        }
        i = j;
    }
    return number_fans(fn, star, k, s);
}

// Whether a hard edge ends at v: else its faces form one fan, found without sorting.
bool hard_edge_at(uint32_t v, const Mesh& mesh, const std::vector<uint8_t>& hard, const uint32_t* star, size_t k) {
    for (size_t a = 0; a < k; ++a) {
        if (!hard[star[a]]) continue;
        const glm::uvec3 t = mesh.triangles[star[a]];
        for (int c = 0; c < 3; ++c)
            if (((hard[star[a]] >> c) & 1u) && (t[c] == v || t[(c + 1) % 3] == v)) return true;
    }
    return false;
}

// Corner k of face f's shading normal id. A vertex of one fan has one id; at a vertex of
// several, the face's fan is found by a binary search of its star (in face order); a face with
// a repeated index is listed once per corner there, consecutively, and its corners share the
// first listing's fan.
uint32_t corner_id(const Mesh& mesh, const VertexFaces& vf, const std::vector<uint32_t>& fan_start,
                   const uint32_t* corner_fan, uint32_t f, int k) {
    const uint32_t v = mesh.triangles[f][k];
    if (fan_start[v + 1] - fan_start[v] <= 1) return fan_start[v];
    const uint32_t* at = std::lower_bound(vf.begin(v), vf.end(v), f);
    return fan_start[v] + corner_fan[at - vf.faces.data()];
}

// Each fan's unit normal at the vertices of `summed` (those of several fans, and of one without
// a smooth normal): its faces' weighted normals summed; a fan of degenerate faces has no
// direction of its own and takes the smooth normal. Every other vertex has one fan, which takes
// its smooth normal (auto_smooth).
void fan_normals(const Mesh& mesh, const VertexFaces& vf, const std::vector<glm::vec3>& fn,
                 const std::vector<uint32_t>& fan_start, const uint32_t* corner_fan,
                 const std::vector<uint32_t>& summed, NormalWeighting weighting, std::vector<glm::vec3>& normals) {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, mesh.positions.size(), kGrain), [&](const auto& range) {
        for (size_t v = range.begin(); v != range.end(); ++v)
            for (uint32_t id = fan_start[v]; id < fan_start[v + 1]; ++id)
                normals[id] = v < mesh.normals.size() ? mesh.normals[v] : glm::vec3(0.0f, 0.0f, 1.0f);
    });
    tbb::parallel_for(tbb::blocked_range<size_t>(0, summed.size(), 256), [&](const auto& range) {
        std::vector<glm::vec3> sums;
        for (size_t s = range.begin(); s != range.end(); ++s) {
            const uint32_t v = summed[s];
            sums.assign(fan_start[v + 1] - fan_start[v], glm::vec3(0.0f));
            const bool one_fan = sums.size() == 1;  // corner_fan is not written there
            int c = -1;
            for (uint32_t i = vf.offsets[v]; i < vf.offsets[v + 1]; ++i) {
                const uint32_t f = vf.faces[i];
                const glm::uvec3 t = mesh.triangles[f];
                const bool again = i > vf.offsets[v] && vf.faces[i - 1] == f;  // the face's next corner at v
                c = again ? c + 1 : 0;
                while (t[c] != v) ++c;
                sums[one_fan ? 0
                     : again ? corner_fan[i - 1]
                             : corner_fan[i]] += corner_weight(mesh, f, c, weighting) * fn[f];
            }
            for (size_t j = 0; j < sums.size(); ++j) {
                const float len = glm::length(sums[j]);
                if (len > 0.0f && std::isfinite(len))
                    normals[fan_start[v] + j] = sums[j] / len;
                else if (v >= mesh.normals.size())
                    normals[fan_start[v] + j] = glm::vec3(0.0f, 0.0f, 1.0f);
            }
        }
    });
}

}  // namespace

void auto_smooth(Mesh& mesh, float angle_degrees, NormalWeighting weighting) {
    if (!(angle_degrees < 180.0f) || mesh.triangles.empty()) {
        mesh.shading_normals.clear();
        mesh.shading_normal_ids.clear();
        return;
    }
    auto_smooth(mesh, angle_degrees, weighting, face_normals(mesh));
}

void auto_smooth(Mesh& mesh, float angle_degrees, NormalWeighting weighting, const std::vector<glm::vec3>& fn) {
    mesh.shading_normals.clear();
    mesh.shading_normal_ids.clear();
    if (!(angle_degrees < 180.0f) || mesh.triangles.empty() || fn.size() != mesh.triangles.size()) return;
    const size_t n = mesh.positions.size();
    for (const glm::uvec3& t : mesh.triangles)
        if (t.x >= n || t.y >= n || t.z >= n) return;  // load_mesh validates first; nothing to split here
    // Compared as a dot product of unit normals; the small slack keeps exactly-at-limit edges
    // (a 30° split of a 12-gon prism) on the smooth side whatever the rounding.
    const float cos_limit = std::cos(glm::radians(std::max(angle_degrees, 0.0f))) - 1e-6f;
    HardEdgeFlags flags = hard_edge_flags(mesh, fn, cos_limit);
    drop_small_hard_edge_groups(mesh, flags.flags);
    const std::vector<uint8_t>& hard = flags.flags;
    const VertexFaces& vf = flags.stars;  // empty at vertices far from a hard edge
    if (std::all_of(hard.begin(), hard.end(), [](uint8_t h) { return h == 0; })) return;

    // Pass 1: fans per vertex, where a hard edge ends. Pass 2: their ids, numbered after a
    // prefix sum, and normals. corner_fan is written at vertices of several fans only, so the
    // pages of the rest are never touched.
    std::vector<uint32_t> fan_start(n + 1, 0);
    const std::unique_ptr<uint32_t[]> corner_fan(new uint32_t[vf.faces.size()]);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, kGrain), [&](const auto& range) {
        Scratch scratch;
        for (size_t v = range.begin(); v != range.end(); ++v) {
            const size_t begin = vf.offsets[v], k = vf.offsets[v + 1] - begin;
            const uint32_t* star = vf.faces.data() + begin;
            if (!hard_edge_at(uint32_t(v), mesh, hard, star, k)) {
                fan_start[v + 1] = flags.referenced[v] ? 1 : 0;
                continue;
            }
            fan_start[v + 1] = fans_at(uint32_t(v), mesh, fn, hard, star, k, scratch);
            if (fan_start[v + 1] > 1) std::copy(scratch.fan.begin(), scratch.fan.end(), corner_fan.get() + begin);
        }
    });
    std::vector<uint32_t> summed;  // vertices of several fans, and of one without a smooth normal
    bool any_split = false;
    for (size_t v = 0; v < n; ++v) {
        any_split |= fan_start[v + 1] > 1;
        if (fan_start[v + 1] > 1 || (fan_start[v + 1] == 1 && v >= mesh.normals.size())) summed.push_back(uint32_t(v));
    }
    if (!any_split) return;
    std::partial_sum(fan_start.begin(), fan_start.end(), fan_start.begin());

    std::vector<glm::uvec3> ids(mesh.triangles.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, ids.size(), kGrain), [&](const auto& range) {
        for (size_t f = range.begin(); f != range.end(); ++f)
            for (int k = 0; k < 3; ++k) ids[f][k] = corner_id(mesh, vf, fan_start, corner_fan.get(), uint32_t(f), k);
    });
    std::vector<glm::vec3> normals(fan_start[n]);
    fan_normals(mesh, vf, fn, fan_start, corner_fan.get(), summed, weighting, normals);
    mesh.shading_normals = std::move(normals);
    mesh.shading_normal_ids = std::move(ids);
}

}  // namespace inkshade::geometry
