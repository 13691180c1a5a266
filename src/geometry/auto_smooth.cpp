// Hard edges come from hard_edge_flags (hard_edges.hpp). Fans are then found vertex by vertex
// over the vertex's own faces (a few, typically six), only at the ends of hard edges: no
// mesh-wide edge table, union-find over 3F corners or per-corner array, and those vertices run
// in parallel. Fans are numbered within a vertex in order of each fan's lowest face, so the
// result does not depend on the thread count.
#include "geometry/auto_smooth.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cmath>
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

// The ends of the hard edges, ascending: the only vertices that may have several fans. Read
// from the flags face by face; a mesh with few hard edges lists few.
std::vector<uint32_t> hard_edge_ends(const Mesh& mesh, const std::vector<uint8_t>& hard) {
    tbb::enumerable_thread_specific<std::vector<uint32_t>> found;
    tbb::parallel_for(tbb::blocked_range<size_t>(0, hard.size(), kGrain * 4), [&](const auto& range) {
        std::vector<uint32_t>& out = found.local();
        for (size_t f = range.begin(); f != range.end(); ++f) {
            if (!hard[f]) continue;
            const glm::uvec3 t = mesh.triangles[f];
            for (int k = 0; k < 3; ++k)
                if ((hard[f] >> k) & 1u) {
                    out.push_back(t[k]);
                    out.push_back(t[(k + 1) % 3]);
                }
        }
    });
    std::vector<uint32_t> ends;
    for (const std::vector<uint32_t>& part : found) ends.insert(ends.end(), part.begin(), part.end());
    std::sort(ends.begin(), ends.end());
    ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
    return ends;
}

// Each fan's unit normal at split vertex v: its faces' weighted normals summed; a fan of
// degenerate faces has no direction of its own and takes the smooth normal. `fan` is the fan
// of each face of v's star (fans_at).
void fan_normals(const Mesh& mesh, const VertexFaces& vf, const std::vector<glm::vec3>& fn, uint32_t v,
                 const uint32_t* fan, NormalWeighting weighting, glm::vec3* out, size_t fans) {
    std::fill_n(out, fans, glm::vec3(0.0f));
    int c = -1;
    for (uint32_t i = vf.offsets[v]; i < vf.offsets[v + 1]; ++i) {
        const uint32_t f = vf.faces[i];
        const glm::uvec3 t = mesh.triangles[f];
        // The face's next corner at v: a face with a repeated index is listed once per corner,
        // consecutively, and its second listing shares the first one's fan.
        const bool again = i > vf.offsets[v] && vf.faces[i - 1] == f;
        c = again ? c + 1 : 0;
        while (t[c] != v) ++c;
        out[fan[(again ? i - 1 : i) - vf.offsets[v]]] += corner_weight(mesh, f, c, weighting) * fn[f];
    }
    for (size_t j = 0; j < fans; ++j) {
        const float len = glm::length(out[j]);
        out[j] = len > 0.0f && std::isfinite(len) ? out[j] / len : mesh.normals[v];
    }
}

// The split vertices among the hard edges' ends (those of several fans) and their slots: sets
// their bits and ranks, and per slot the fan count and star size as prefix sums.
void number_splits(const Mesh& mesh, const VertexFaces& vf, const std::vector<uint32_t>& ends,
                   const std::vector<uint32_t>& fans, ShadingSplits& s) {
    s.split.assign(mesh.positions.size() / 64 + 1, 0);
    for (size_t i = 0; i < ends.size(); ++i)
        if (fans[i] > 1) s.split[ends[i] / 64] |= uint64_t(1) << (ends[i] % 64);
    s.rank.resize(s.split.size());
    uint32_t count = 0;
    for (size_t word = 0; word < s.split.size(); ++word) {
        s.rank[word] = count;
        count += uint32_t(std::popcount(s.split[word]));
    }
    s.extra.assign(count + 1, 0);
    s.corner_start.assign(count + 1, 0);
    for (size_t i = 0, slot = 0; i < ends.size(); ++i) {
        if (fans[i] < 2) continue;
        s.extra[slot + 1] = s.extra[slot] + fans[i] - 1;
        s.corner_start[slot + 1] = s.corner_start[slot] + (vf.offsets[ends[i] + 1] - vf.offsets[ends[i]]);
        ++slot;
    }
}

}  // namespace

void auto_smooth(Mesh& mesh, float angle_degrees, NormalWeighting weighting) {
    if (!(angle_degrees < 180.0f) || mesh.triangles.empty()) {
        mesh.shading_splits = ShadingSplits();
        return;
    }
    auto_smooth(mesh, angle_degrees, weighting, face_normals(mesh));
}

void auto_smooth(Mesh& mesh, float angle_degrees, NormalWeighting weighting, const std::vector<glm::vec3>& fn) {
    mesh.shading_splits = ShadingSplits();
    const size_t n = mesh.positions.size();
    if (!(angle_degrees < 180.0f) || mesh.triangles.empty() || fn.size() != mesh.triangles.size() ||
        mesh.normals.size() != n)
        return;
    for (const glm::uvec3& t : mesh.triangles)
        if (t.x >= n || t.y >= n || t.z >= n) return;  // load_mesh validates first; nothing to split here
    // Compared as a dot product of unit normals; the small slack keeps exactly-at-limit edges
    // (a 30° split of a 12-gon prism) on the smooth side whatever the rounding.
    const float cos_limit = std::cos(glm::radians(std::max(angle_degrees, 0.0f))) - 1e-6f;
    HardEdgeFlags flags = hard_edge_flags(mesh, fn, cos_limit);
    drop_small_hard_edge_groups(mesh, flags.flags);
    const std::vector<uint8_t>& hard = flags.flags;
    const VertexFaces& vf = flags.stars;  // empty at vertices far from a hard edge

    // Pass 1: the fan count at each end of a hard edge. Pass 2, at those of several fans after
    // the prefix sums: their faces' fans (found again) and the fans' normals.
    const std::vector<uint32_t> ends = hard_edge_ends(mesh, hard);
    std::vector<uint32_t> fans(ends.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, ends.size(), 64), [&](const auto& range) {
        Scratch scratch;
        for (size_t i = range.begin(); i != range.end(); ++i)
            fans[i] = fans_at(ends[i], mesh, fn, hard, vf.begin(ends[i]), vf.end(ends[i]) - vf.begin(ends[i]), scratch);
    });
    if (std::all_of(fans.begin(), fans.end(), [](uint32_t c) { return c < 2; })) return;
    ShadingSplits s;
    s.triangle_count = mesh.triangles.size();
    number_splits(mesh, vf, ends, fans, s);
    const size_t count = s.extra.size() - 1;
    s.corner_face.resize(s.corner_start.back());
    s.corner_fan.resize(s.corner_start.back());
    s.normals.resize(s.extra.back() + count);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, ends.size(), 64), [&](const auto& range) {
        Scratch scratch;
        for (size_t i = range.begin(); i != range.end(); ++i) {
            if (fans[i] < 2) continue;
            const uint32_t v = ends[i], slot = s.slot(v);
            const size_t k = vf.end(v) - vf.begin(v);
            fans_at(v, mesh, fn, hard, vf.begin(v), k, scratch);
            std::copy(vf.begin(v), vf.end(v), s.corner_face.begin() + s.corner_start[slot]);
            std::copy(scratch.fan.begin(), scratch.fan.end(), s.corner_fan.begin() + s.corner_start[slot]);
            fan_normals(mesh, vf, fn, v, scratch.fan.data(), weighting, s.normals.data() + s.extra[slot] + slot,
                        fans[i]);
        }
    });
    mesh.shading_splits = std::move(s);
}

}  // namespace inkshade::geometry
