// The second test runs only on the candidates of the first, once per edge (by its lower face),
// so a mesh with few sharp edges pays for few. The first test itself runs only on the faces
// that may have a hard edge (quiet_faces below), and the second stops as soon as a bound on its
// result decides it. Every loop writes only its own face's (or vertex's) entry, so the result
// does not depend on the thread count.
#include "geometry/hard_edges.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>

namespace inkshade::geometry {
namespace {

constexpr size_t kGrain = 16384;                    // faces or vertices per TBB task
constexpr uint8_t kHard = 0x07, kCandidate = 0x38;  // bit k: hard; bit k + 3: passed the first test

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

struct SecondTestScratch {  // per-task buffers of sides_stand_apart
    std::vector<uint32_t> around;
    std::vector<std::pair<int, float>> sides;  // per face of `around`: side, area
};

// The sides' scatter summed: each side's area-weighted mean angle of its faces from its mean
// `mean[s]`; with `bound`, each angle φ replaced by √(2 − 2 cos φ), which is at most φ.
float scatter_of(const std::vector<uint32_t>& around, const std::vector<std::pair<int, float>>& sides,
                 const std::vector<glm::vec3>& fn, const glm::vec3 mean[2], bool bound) {
    float scatter[2] = {0.0f, 0.0f}, weight[2] = {0.0f, 0.0f};
    for (size_t i = 0; i < around.size(); ++i) {
        const auto [side, area] = sides[i];
        if (side == 2) continue;
        const float c = std::clamp(glm::dot(fn[around[i]], mean[side]), -1.0f, 1.0f);
        scatter[side] += area * (bound ? std::sqrt(2.0f - 2.0f * c) : std::acos(c));
        weight[side] += area;
    }
    float spread = 0.0f;
    for (int s = 0; s < 2; ++s)
        if (weight[s] > 0.0f && std::isfinite(weight[s])) spread += scatter[s] / weight[s];
    return spread;
}

// The second test for the candidate edge (v, w) between faces a and b (hard_edges.hpp).
bool sides_stand_apart(const Mesh& mesh, const VertexFaces& vf, const std::vector<glm::vec3>& fn, uint32_t a,
                       uint32_t b, uint32_t v, uint32_t w, float cos_limit, SecondTestScratch& scratch) {
    std::vector<uint32_t>& around = scratch.around;
    std::vector<std::pair<int, float>>& sides = scratch.sides;
    const glm::vec3 na = fn[a], nb = fn[b];
    const glm::vec3 mid = 0.5f * (mesh.positions[v] + mesh.positions[w]);
    glm::vec3 across = glm::cross(mesh.positions[w] - mesh.positions[v], na + nb);  // normal of the bisecting plane
    if (glm::dot(centroid(mesh, a) - mid, across) < 0.0f) across = -across;         // towards a
    const float cos_double = cos_limit > 0.0f ? 2.0f * cos_limit * cos_limit - 1.0f : -1.0f;  // cos 2θ, θ < 90°
    const glm::uvec3 ta = mesh.triangles[a], tb = mesh.triangles[b];
    const uint32_t corners[6] = {ta.x, ta.y, ta.z, tb.x, tb.y, tb.z};
    around.clear();
    for (uint32_t c : corners) around.insert(around.end(), vf.begin(c), vf.end(c));
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
    // Each face's side (0, 1; 2 when left out) and area, then each side's mean normal.
    glm::vec3 sum[2] = {glm::vec3(0.0f), glm::vec3(0.0f)};
    sides.clear();
    for (uint32_t g : around) {
        int side = glm::dot(centroid(mesh, g) - mid, across) >= 0.0f ? 0 : 1;
        const float own = glm::dot(fn[g], side == 0 ? na : nb), other = glm::dot(fn[g], side == 0 ? nb : na);
        // Far from both faces: a third side meeting at a corner. Far from its side's face and
        // turned like the other one: the other side's orientation reached round a thin part.
        if (g == a || g == b || (own < cos_limit && other < cos_limit) || (own < cos_double && other >= cos_limit))
            side = 2;
        const glm::uvec3 t = mesh.triangles[g];
        const glm::vec3 &p = mesh.positions[t.x], &q = mesh.positions[t.y], &r = mesh.positions[t.z];
        const float area = 0.5f * glm::length(glm::cross(q - p, r - p));
        sides.push_back({side, area});
        if (side < 2) sum[side] += area * fn[g];
    }
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
    if (gap - scatter_of(around, sides, fn, mean, true) <= limit - 1e-4f) return false;
    return gap - scatter_of(around, sides, fn, mean, false) > limit;
}

// A vertex index scrambled (splitmix64's finaliser), so that sums of them cancel only when the
// same indices come in and go out.
uint64_t mix(uint64_t x) {
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

// Which faces the first test must see (1) and which not (0). Two faces that share a vertex
// and whose normals each lie within half the angle of its normal meet at no more than the
// angle (the triangle inequality of angles), so an edge between two such "calm" faces is no
// candidate: only edges at a corner of a face that is not calm may be. Edges of three or more
// faces: around a vertex where every edge has two faces, wound alike, each neighbour is once the
// next corner and once the previous one of the faces there, so a hash sum of next minus
// previous corners vanishes; at a border, a non-manifold edge or a winding flip it does not
// (short of a hash collision, or an edge of four faces two each way among calm faces). Faces
// at such vertices are seen too. Without one unit normal per vertex every face is seen.
std::vector<uint8_t> faces_to_test(const Mesh& mesh, const VertexFaces& vf, const std::vector<glm::vec3>& fn,
                                   float cos_limit) {
    const size_t faces = mesh.triangles.size(), n = mesh.positions.size();
    const float half = 0.5f * std::acos(std::clamp(cos_limit, -1.0f, 1.0f)) - 1e-3f;  // margin for rounding
    if (mesh.normals.size() != n || !(half > 0.0f)) return std::vector<uint8_t>(faces, 1);
    const float cos_half = std::cos(half);
    std::vector<uint8_t> restless(faces);  // not calm
    for_each_index(faces, [&](size_t f) {
        const glm::uvec3 t = mesh.triangles[f];
        bool calm = fn[f] != glm::vec3(0.0f);
        for (int k = 0; k < 3 && calm; ++k) {
            const glm::vec3 nv = mesh.normals[t[k]];
            calm = glm::dot(fn[f], nv) >= cos_half * glm::length(nv);
        }
        restless[f] = !calm;
    });
    std::vector<uint8_t> busy(n);
    for_each_index(n, [&](size_t v) {
        uint64_t turn = 0;  // Σ h(next) − h(previous), wrapping
        bool restless_star = false;
        for (const uint32_t* g = vf.begin(uint32_t(v)); g != vf.end(uint32_t(v)); ++g) {
            const glm::uvec3 t = mesh.triangles[*g];
            const int k = t.x == v ? 0 : (t.y == v ? 1 : 2);
            turn += mix(t[(k + 1) % 3]) - mix(t[(k + 2) % 3]);
            restless_star |= restless[*g] != 0;
        }
        busy[v] = restless_star || turn != 0;
    });
    for_each_index(faces, [&](size_t f) {
        const glm::uvec3 t = mesh.triangles[f];
        restless[f] = busy[t.x] | busy[t.y] | busy[t.z];
    });
    return restless;
}

// First test per face edge: hard bits for edges of three or more faces, candidate bits for
// edges of two non-degenerate faces that meet at more than the angle. Returns whether any
// edge is a candidate.
bool first_test(const Mesh& mesh, const VertexFaces& vf, const std::vector<glm::vec3>& fn, float cos_limit,
                std::vector<uint8_t>& flags) {
    const std::vector<uint8_t> seen = faces_to_test(mesh, vf, fn, cos_limit);
    std::atomic<bool> any{false};
    for_each_index(mesh.triangles.size(), [&](size_t f) {
        if (!seen[f]) return;  // flags[f] stays 0
        const glm::uvec3 t = mesh.triangles[f];
        uint8_t bits = 0;
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = t[k], w = t[(k + 1) % 3];
            if (v == w) continue;
            const EdgeMate mate = edge_mate(mesh, vf, uint32_t(f), v, w);
            if (mate.count >= 2) {
                bits |= uint8_t(1u << k);
            } else if (mate.count == 1 && fn[f] != glm::vec3(0.0f) && fn[mate.face] != glm::vec3(0.0f) &&
                       glm::dot(fn[f], fn[mate.face]) < cos_limit) {
                bits |= uint8_t(8u << k);
            }
        }
        flags[f] = bits;
        if (bits & kCandidate) any.store(true, std::memory_order_relaxed);
    });
    return any.load();
}

// Second test: a candidate edge is hard when its two sides stand apart by more than the angle
// plus their scatter. Decided once per edge, by its lower face; clears the candidate bits.
void second_test(const Mesh& mesh, const VertexFaces& vf, const std::vector<glm::vec3>& fn, float cos_limit,
                 std::vector<uint8_t>& flags) {
    const size_t faces = mesh.triangles.size();
    std::vector<uint8_t> decided(faces, 0);  // bit k: hard, for edges whose lower face is f
    tbb::enumerable_thread_specific<SecondTestScratch> scratch;
    for_each_index(faces, [&](size_t f) {
        if (!(flags[f] & kCandidate)) return;
        const glm::uvec3 t = mesh.triangles[f];
        SecondTestScratch& local = scratch.local();
        for (int k = 0; k < 3; ++k) {
            if (!(flags[f] & (8u << k))) continue;
            const EdgeMate mate = edge_mate(mesh, vf, uint32_t(f), t[k], t[(k + 1) % 3]);
            if (f < mate.face &&
                sides_stand_apart(mesh, vf, fn, uint32_t(f), mate.face, t[k], t[(k + 1) % 3], cos_limit, local))
                decided[f] |= uint8_t(1u << k);
        }
    });
    for_each_index(faces, [&](size_t f) {
        if (!(flags[f] & kCandidate)) return;
        const glm::uvec3 t = mesh.triangles[f];
        uint8_t bits = flags[f] & kHard;
        for (int k = 0; k < 3; ++k) {
            if (!(flags[f] & (8u << k))) continue;
            const uint32_t v = t[k], w = t[(k + 1) % 3];
            const EdgeMate mate = edge_mate(mesh, vf, uint32_t(f), v, w);
            if (f < mate.face) {
                bits |= decided[f] & (1u << k);
                continue;
            }
            const glm::uvec3 u = mesh.triangles[mate.face];
            for (int j = 0; j < 3; ++j)
                if ((u[j] == w && u[(j + 1) % 3] == v) || (u[j] == v && u[(j + 1) % 3] == w))
                    bits |= uint8_t(((decided[mate.face] >> j) & 1u) << k);
        }
        flags[f] = bits;
    });
}

}  // namespace

std::vector<uint8_t> hard_edge_flags(const Mesh& mesh, const VertexFaces& vf, const std::vector<glm::vec3>& fn,
                                     float cos_limit) {
    std::vector<uint8_t> flags(mesh.triangles.size(), 0);
    if (first_test(mesh, vf, fn, cos_limit, flags)) second_test(mesh, vf, fn, cos_limit, flags);
    return flags;
}

}  // namespace inkshade::geometry
