// The second test runs only on the candidates of the first, once per edge (by its lower face),
// so a mesh with few sharp edges pays for few. The first test itself runs only on the faces
// that may have a hard edge (faces_to_test below), once per edge at its lower vertex, and the
// second walks the faces around an edge without gathering them and stops as soon as a bound on
// its result decides it. Every loop writes only its own face's (or vertex's) entry, or sets
// bits with an atomic or, so the result does not depend on the thread count.
#include "geometry/hard_edges.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <utility>

namespace inkshade::geometry {
namespace {

constexpr size_t kGrain = 16384;  // faces or vertices per TBB task
// Bit k: hard; bit k + 3: passed the first test; bit 6: the first test sees the face (cleared
// at the end: the flags' own bytes, so no array of their own).
constexpr uint8_t kHard = 0x07, kCandidate = 0x38, kSeen = 0x40;

template <class Body>
void for_each_index(size_t count, Body&& body) {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, count, kGrain), [&](const auto& range) {
        for (size_t i = range.begin(); i != range.end(); ++i) body(i);
    });
}

glm::vec3 centroid(const Mesh& mesh, uint32_t f) {
    const glm::uvec3 t = mesh.triangles[f];
    return (mesh.positions[t.x] + mesh.positions[t.y] + mesh.positions[t.z]) / 3.0f;
}

// Calls visit(g) for each face with a corner at one of faces a's and b's corners, once each,
// in ascending order (a merge of the corners' stars, which are in face order), a and b left
// out. Ascending, as a sort would give: the sides' sums below add in the same order.
template <class Visit>
void for_each_face_around(const Mesh& mesh, const VertexFaces& vf, uint32_t a, uint32_t b, Visit&& visit) {
    const glm::uvec3 ta = mesh.triangles[a], tb = mesh.triangles[b];
    const uint32_t corners[6] = {ta.x, ta.y, ta.z, tb.x, tb.y, tb.z};
    uint32_t distinct[6];
    const uint32_t *at[6], *end[6];
    int m = 0;
    for (uint32_t c : corners) {
        if (std::find(distinct, distinct + m, c) != distinct + m) continue;
        distinct[m] = c;
        at[m] = vf.begin(c);
        end[m++] = vf.end(c);
    }
    for (uint32_t last = ~0u;;) {
        int low = -1;
        for (int i = 0; i < m; ++i)
            if (at[i] != end[i] && (low < 0 || *at[i] < *at[low])) low = i;
        if (low < 0) return;
        const uint32_t g = *at[low]++;
        if (g == last) continue;
        last = g;
        if (g != a && g != b) visit(g);
    }
}

// Which side of the edge face g counts on (0: a's, 1: b's, 2: neither), and its area
// (sides_stand_apart).
struct SideOf {
    const Mesh& mesh;
    const std::vector<glm::vec3>& fn;
    glm::vec3 na, nb, mid, across;
    float cos_limit, cos_double;

    std::pair<int, float> operator()(uint32_t g) const {
        const glm::uvec3 t = mesh.triangles[g];
        const glm::vec3 &p = mesh.positions[t.x], &q = mesh.positions[t.y], &r = mesh.positions[t.z];
        int side = glm::dot((p + q + r) / 3.0f - mid, across) >= 0.0f ? 0 : 1;
        const float own = glm::dot(fn[g], side == 0 ? na : nb), other = glm::dot(fn[g], side == 0 ? nb : na);
        // Far from both faces: a third side meeting at a corner. Far from its side's face and
        // turned like the other one: the other side's orientation reached round a thin part.
        if ((own < cos_limit && other < cos_limit) || (own < cos_double && other >= cos_limit)) side = 2;
        return {side, 0.5f * glm::length(glm::cross(q - p, r - p))};
    }
};

// The sides' scatter summed: each side's area-weighted mean angle of its faces from its mean
// `mean[s]`; with `bound`, each angle φ replaced by √(2 − 2 cos φ), which is at most φ.
float scatter_of(const Mesh& mesh, const VertexFaces& vf, uint32_t a, uint32_t b, const SideOf& side_of,
                 const glm::vec3 mean[2], bool bound) {
    float scatter[2] = {0.0f, 0.0f}, weight[2] = {0.0f, 0.0f};
    for_each_face_around(mesh, vf, a, b, [&](uint32_t g) {
        const auto [side, area] = side_of(g);
        if (side == 2) return;
        const float c = std::clamp(glm::dot(side_of.fn[g], mean[side]), -1.0f, 1.0f);
        scatter[side] += area * (bound ? std::sqrt(2.0f - 2.0f * c) : std::acos(c));
        weight[side] += area;
    });
    float spread = 0.0f;
    for (int s = 0; s < 2; ++s)
        if (weight[s] > 0.0f && std::isfinite(weight[s])) spread += scatter[s] / weight[s];
    return spread;
}

// The second test for the candidate edge (v, w) between faces a and b (hard_edges.hpp). The
// faces around are walked again for the scatter rather than kept: most candidates are decided
// by the gap alone.
bool sides_stand_apart(const Mesh& mesh, const VertexFaces& vf, const std::vector<glm::vec3>& fn, uint32_t a,
                       uint32_t b, uint32_t v, uint32_t w, float cos_limit) {
    const glm::vec3 na = fn[a], nb = fn[b];
    const glm::vec3 mid = 0.5f * (mesh.positions[v] + mesh.positions[w]);
    glm::vec3 across = glm::cross(mesh.positions[w] - mesh.positions[v], na + nb);  // normal of the bisecting plane
    if (glm::dot(centroid(mesh, a) - mid, across) < 0.0f) across = -across;         // towards a
    const float cos_double = cos_limit > 0.0f ? 2.0f * cos_limit * cos_limit - 1.0f : -1.0f;  // cos 2θ, θ < 90°
    const SideOf side_of{mesh, fn, na, nb, mid, across, cos_limit, cos_double};
    // Each side's mean normal, its faces weighted by area.
    glm::vec3 sum[2] = {glm::vec3(0.0f), glm::vec3(0.0f)};
    for_each_face_around(mesh, vf, a, b, [&](uint32_t g) {
        const auto [side, area] = side_of(g);
        if (side < 2) sum[side] += area * fn[g];
    });
    // A side with no neighbour of its own (a tetrahedron's face) is its face.
    glm::vec3 mean[2];
    for (int s = 0; s < 2; ++s) {
        const float len = glm::length(sum[s]);
        mean[s] = len > 0.0f && std::isfinite(len) ? sum[s] / len : (s == 0 ? na : nb);
    }
    // The sides must stand apart by more than the angle plus their scatter (below): noise that
    // tilts faces by some degrees blurs a crease by as much. The scatter is not negative, so a
    // gap within the angle decides at once (most of a scan's candidates).
    const float gap = std::acos(std::clamp(glm::dot(mean[0], mean[1]), -1.0f, 1.0f));
    const float limit = std::acos(std::clamp(cos_limit + 1e-6f, -1.0f, 1.0f));
    if (!(gap > limit)) return false;
    // Then a lower bound of the scatter without acos (2 sin(φ/2) = √(2 − 2 cos φ) ≤ φ), with a
    // margin far above float rounding; only what it leaves open pays for the exact one.
    if (gap - scatter_of(mesh, vf, a, b, side_of, mean, true) <= limit - 1e-4f) return false;
    return gap - scatter_of(mesh, vf, a, b, side_of, mean, false) > limit;
}

// A vertex index scrambled (splitmix64's finaliser), so that sums of them cancel only when the
// same indices come in and go out.
uint64_t mix(uint64_t x) {
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

// Which faces the first test must see: marked kSeen in `flags`; returns the vertices of those
// faces (1), whose stars it reads. Two faces that share a vertex and whose normals each lie
// within half the angle of its normal meet at no more than the angle (the triangle inequality
// of angles), so an edge between two such "calm" faces is no candidate: only edges at a corner
// of a face that is not calm may be. Edges of three or more faces: around a vertex where every
// edge has two faces, wound alike, each neighbour is once the next corner and once the previous
// one of the faces there, so a hash sum of next minus previous corners vanishes; at a border, a
// non-manifold edge or a winding flip it does not (short of a hash collision, or an edge of four
// faces two each way among calm faces). Faces at such vertices are seen too. Without one unit
// normal per vertex every face is seen. The sums are scattered face by face (no star table
// yet; for_vertex_ranges): a face with a repeated index adds, at each corner there, what its
// first corner there adds, as a walk of the star would. One array per vertex serves first for
// the vertices near a restless face and then for the answer, so its pages are touched once.
std::vector<uint8_t> faces_to_test(const Mesh& mesh, const std::vector<glm::vec3>& fn, float cos_limit,
                                   std::vector<uint8_t>& flags) {
    const size_t faces = mesh.triangles.size(), n = mesh.positions.size();
    const float half = 0.5f * std::acos(std::clamp(cos_limit, -1.0f, 1.0f)) - 1e-3f;  // margin for rounding
    std::vector<uint8_t> busy(n, 0);  // restless star, then or turn ≠ 0; then the answer
    const bool all = mesh.normals.size() != n || !(half > 0.0f);
    if (!all) {
        const float cos_half = std::cos(half);
        for_each_index(faces, [&](size_t f) {  // kSeen here: not calm
            const glm::uvec3 t = mesh.triangles[f];
            bool calm = fn[f] != glm::vec3(0.0f);
            for (int k = 0; k < 3 && calm; ++k) {
                const glm::vec3 nv = mesh.normals[t[k]];
                calm = glm::dot(fn[f], nv) >= cos_half * glm::length(nv);
            }
            flags[f] = calm ? 0 : kSeen;
        });
        std::vector<uint64_t> turn(n, 0);  // Σ h(next) − h(previous), wrapping
        for_vertex_ranges(n, [&](size_t lo, size_t hi) {
            for (size_t f = 0; f < faces; ++f) {
                const glm::uvec3 t = mesh.triangles[f];
                for (int c = 0; c < 3; ++c) {
                    const uint32_t v = t[c];
                    if (v < lo || v >= hi) continue;
                    const int k = t.x == v ? 0 : (t.y == v ? 1 : 2);
                    turn[v] += mix(t[(k + 1) % 3]) - mix(t[(k + 2) % 3]);
                    busy[v] |= flags[f];
                }
            }
            for (size_t v = lo; v < hi; ++v) busy[v] |= uint8_t(turn[v] != 0);
        });
    }
    for_each_index(faces, [&](size_t f) {
        const glm::uvec3 t = mesh.triangles[f];
        flags[f] = all || (busy[t.x] | busy[t.y] | busy[t.z]) ? kSeen : 0;
    });
    std::fill(busy.begin(), busy.end(), uint8_t(0));
    for_each_index(faces, [&](size_t f) {
        if (!flags[f]) return;
        for (int k = 0; k < 3; ++k)
            std::atomic_ref<uint8_t>(busy[mesh.triangles[f][k]]).store(1, std::memory_order_relaxed);
    });
    return busy;
}

// The first test of the edges from vertex v to higher vertices u, each once: its faces (those
// of v's star that have u, as edge_mate finds them) are found at the first of them, and every
// edge {v, u} of each seen one gets its bit. The star's faces are read once. Bits are set
// with an atomic or (a face's edges are decided at up to three vertices); returns whether any
// is a candidate.
bool first_test_at(uint32_t v, const Mesh& mesh, const VertexFaces& vf, const std::vector<glm::vec3>& fn,
                   float cos_limit, std::vector<uint8_t>& flags) {
    constexpr size_t kMax = 32;  // the faces of a larger star (a fan's centre) are read as needed
    const uint32_t* star = vf.begin(v);
    const size_t k = size_t(vf.end(v) - star);
    glm::uvec3 cached[kMax];
    if (k <= kMax)
        for (size_t i = 0; i < k; ++i) cached[i] = mesh.triangles[star[i]];
    const auto tri = [&](size_t i) { return k <= kMax ? cached[i] : mesh.triangles[star[i]]; };
    const auto has = [](const glm::uvec3& t, uint32_t u) { return t.x == u || t.y == u || t.z == u; };
    bool any = false;
    for (size_t i = 0; i < k; ++i) {
        if (i > 0 && star[i - 1] == star[i]) continue;  // a face listed twice (repeated index)
        const glm::uvec3 t = tri(i);
        for (int c = 0; c < 3; ++c) {
            const uint32_t u = t[c];
            if (u <= v || (c > 0 && t[c - 1] == u) || (c == 2 && t[0] == u)) continue;
            bool first = true;  // the edge's faces are handled at their first
            for (size_t j = 0; j < i && first; ++j) first = !has(tri(j), u);
            if (!first) continue;
            uint32_t members[kMax], count = 0, mate = 0;
            for (size_t j = i; j < k; ++j) {
                if ((j > i && star[j - 1] == star[j]) || !has(tri(j), u)) continue;
                if (count < kMax) members[count] = uint32_t(j);
                if (count++ == 1) mate = star[j];
            }
            uint8_t bit = 0;  // per edge of a member: 1 hard, 8 candidate
            if (count >= 3)
                bit = 1;
            else if (count == 2 && fn[star[i]] != glm::vec3(0.0f) && fn[mate] != glm::vec3(0.0f) &&
                     glm::dot(fn[star[i]], fn[mate]) < cos_limit)
                bit = 8;
            if (!bit) continue;
            for (uint32_t m = 0; m < std::min<uint32_t>(count, kMax); ++m) {
                const uint32_t g = star[members[m]];
                if (!(std::atomic_ref<uint8_t>(flags[g]).load(std::memory_order_relaxed) & kSeen)) continue;
                const glm::uvec3 s = tri(members[m]);
                uint8_t bits = 0;
                for (int e = 0; e < 3; ++e) {
                    const uint32_t p = s[e], q = s[(e + 1) % 3];
                    if ((p == v && q == u) || (p == u && q == v)) bits |= uint8_t(bit << e);
                }
                std::atomic_ref<uint8_t>(flags[g]).fetch_or(bits, std::memory_order_relaxed);
            }
            any |= bit == 8;
        }
    }
    return any;
}

// First test per face edge: hard bits for edges of three or more faces, candidate bits for
// edges of two non-degenerate faces that meet at more than the angle; only on the faces
// faces_to_test picks, edge by edge at its lower vertex (first_test_at). Returns whether any
// edge is a candidate.
bool first_test(const Mesh& mesh, const std::vector<glm::vec3>& fn, float cos_limit, HardEdgeFlags& out) {
    const std::vector<uint8_t> listed = faces_to_test(mesh, fn, cos_limit, out.flags);
    out.stars = vertex_faces(mesh, listed);
    std::atomic<bool> any{false};
    for_each_index(mesh.positions.size(), [&](size_t v) {
        if (listed[v] && first_test_at(uint32_t(v), mesh, out.stars, fn, cos_limit, out.flags))
            any.store(true, std::memory_order_relaxed);
    });
    return any.load();
}

// Second test: a candidate edge is hard when its two sides stand apart by more than the angle
// plus their scatter. Decided once per edge, by its lower face, which sets the hard bit of both
// faces with an atomic or (the candidate bits it reads do not change meanwhile).
void second_test(const Mesh& mesh, const VertexFaces& vf, const std::vector<glm::vec3>& fn, float cos_limit,
                 std::vector<uint8_t>& flags) {
    for_each_index(mesh.triangles.size(), [&](size_t f) {
        const uint8_t bits = std::atomic_ref<uint8_t>(flags[f]).load(std::memory_order_relaxed);
        if (!(bits & kCandidate)) return;
        const glm::uvec3 t = mesh.triangles[f];
        for (int k = 0; k < 3; ++k) {
            if (!(bits & (8u << k))) continue;
            const uint32_t v = t[k], w = t[(k + 1) % 3];
            const EdgeMate mate = edge_mate(mesh, vf, uint32_t(f), v, w);
            if (f > mate.face || !sides_stand_apart(mesh, vf, fn, uint32_t(f), mate.face, v, w, cos_limit)) continue;
            std::atomic_ref<uint8_t>(flags[f]).fetch_or(uint8_t(1u << k), std::memory_order_relaxed);
            const glm::uvec3 u = mesh.triangles[mate.face];
            for (int j = 0; j < 3; ++j)
                if ((u[j] == w && u[(j + 1) % 3] == v) || (u[j] == v && u[(j + 1) % 3] == w))
                    std::atomic_ref<uint8_t>(flags[mate.face]).fetch_or(uint8_t(1u << j), std::memory_order_relaxed);
        }
    });
}

}  // namespace

HardEdgeFlags hard_edge_flags(const Mesh& mesh, const std::vector<glm::vec3>& fn, float cos_limit) {
    HardEdgeFlags out;
    out.flags.assign(mesh.triangles.size(), 0);
    if (first_test(mesh, fn, cos_limit, out)) second_test(mesh, out.stars, fn, cos_limit, out.flags);
    for_each_index(out.flags.size(), [&](size_t f) { out.flags[f] &= kHard; });
    return out;
}

}  // namespace inkshade::geometry
