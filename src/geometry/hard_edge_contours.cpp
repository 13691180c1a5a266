#include "geometry/hard_edge_contours.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <tuple>

#include "geometry/face_segments.hpp"

namespace inkshade::geometry {
namespace {

// A corner as the view reads it: its vertex, shading normal id (Mesh::shading_normal_id), and
// where its n·v lies in the view's array (view_dot_normals).
struct Corner {
    uint32_t vertex, normal, at;
};

// Where n·v vanishes on the edge (a, b) of one face: computed from the ends ordered by shading
// normal id, so the face on the other side of a smooth edge, and the hard-edge piece that ends
// there, get the same bits.
glm::vec3 crossing(const Mesh& mesh, const std::vector<float>& g, Corner a, Corner b) {
    if (b.normal < a.normal) std::swap(a, b);
    const double ga = g[a.at], gb = g[b.at];
    const double t = ga / (ga - gb);
    const glm::dvec3 pa(mesh.positions[a.vertex]), pb(mesh.positions[b.vertex]);
    return glm::vec3(pa + t * (pb - pa));
}

bool face_is_valid(const Mesh& mesh, size_t f) {
    const glm::uvec3 t = mesh.triangles[f];
    const size_t n = mesh.positions.size();
    return t.x < n && t.y < n && t.z < n;
}

bool is_split(const ShadingSplits& s, uint32_t v) { return (s.split[v / 64] >> (v % 64)) & 1u; }

// Where face f's n·v at split vertex v lies in the view's array: after the vertices', at its
// fan's normal (out of line: few corners need it).
[[gnu::noinline]] uint32_t split_at(const Mesh& mesh, uint32_t v, uint32_t f) {
    const ShadingSplits& s = mesh.shading_splits;
    const uint32_t slot = s.slot(v);
    return uint32_t(mesh.positions.size()) + s.extra[slot] + slot + s.fan(slot, f);
}

Corner corner_at(const Mesh& mesh, uint32_t f, uint32_t v) {
    return {v, mesh.shading_splits.id(v, f), is_split(mesh.shading_splits, v) ? split_at(mesh, v, f) : v};
}

// n·v of each vertex's smooth normal, then of each fan normal of the split vertices, after
// them (ShadingSplits::normals): a corner off a split vertex reads its vertex's entry, as the
// smooth contour does, so a view costs what it costs without hard edges. A split vertex's own
// entry is NaN (n·v is finite elsewhere): one test of a face's three values finds its corners
// at split vertices.
std::vector<float> view_dot_normals(const Mesh& mesh, const Camera& camera) {
    const ViewVector view(camera);
    const ShadingSplits& s = mesh.shading_splits;
    const size_t n = mesh.positions.size();
    std::vector<float> g(n + s.normals.size());
    auto dot = [&](const glm::vec3& normal, size_t v) {
        const double d = glm::dot(glm::dvec3(normal), view.at(mesh.positions[v]));
        return std::isfinite(d) ? float(d) : 0.0f;
    };
    tbb::parallel_for(tbb::blocked_range<size_t>(0, s.split.size(), kFaceGrain / 64), [&](const auto& range) {
        for (size_t word = range.begin(); word != range.end(); ++word) {
            for (size_t v = word * 64; v < std::min(n, word * 64 + 64); ++v) g[v] = dot(mesh.normals[v], v);
            uint32_t slot = s.rank[word];
            for (uint64_t bits = s.split[word]; bits != 0; bits &= bits - 1, ++slot) {
                const size_t v = word * 64 + size_t(std::countr_zero(bits));
                g[v] = std::numeric_limits<float>::quiet_NaN();
                for (uint32_t i = s.extra[slot] + slot; i < s.extra[slot + 1] + slot + 1; ++i)
                    g[n + i] = dot(s.normals[i], v);
            }
        }
    });
    return g;
}

std::vector<LineSegment> face_crossings(const Mesh& mesh, const std::vector<float>& g) {
    const ShadingSplits& s = mesh.shading_splits;
    return collect_face_segments(mesh.triangles.size(), [&](size_t f, std::vector<LineSegment>& out) {
        if (!face_is_valid(mesh, f)) return;
        const glm::uvec3 t = mesh.triangles[f];
        uint32_t at[3] = {t.x, t.y, t.z};
        float value[3] = {g[t.x], g[t.y], g[t.z]};
        if (std::isnan(value[0] + value[1] + value[2]))  // a corner at a split vertex
            for (int k = 0; k < 3; ++k)
                if (std::isnan(value[k])) value[k] = g[at[k] = split_at(mesh, t[k], uint32_t(f))];
        const bool pos[3] = {value[0] >= 0.0f, value[1] >= 0.0f, value[2] >= 0.0f};
        if (pos[0] == pos[1] && pos[1] == pos[2]) return;
        const int k = pos[1] == pos[2] ? 0 : (pos[0] == pos[2] ? 1 : 2);  // the odd one out
        auto c = [&](int i) { return Corner{t[i % 3], s.id(t[i % 3], uint32_t(f)), at[i % 3]}; };
        const Corner ck = c(k), cnext = c(k + 1), cprev = c(k + 2);
        if (ck.vertex == cnext.vertex || ck.vertex == cprev.vertex) return;  // repeated index
        LineSegment seg;
        seg.face = uint32_t(f);
        seg.edge_a = edge_key(ck.normal, cnext.normal);
        seg.edge_b = edge_key(cprev.normal, ck.normal);
        seg.a = crossing(mesh, g, ck, cnext);
        seg.b = crossing(mesh, g, cprev, ck);
        if (!pos[k]) {  // keep n·v ≥ 0 on the left of a → b
            std::swap(seg.a, seg.b);
            std::swap(seg.edge_a, seg.edge_b);
        }
        out.push_back(seg);
    });
}

using HalfEdge = HardEdgeSide;

// The pieces of one hard edge where faces A and B disagree about facing. The edge runs from
// vertex i to vertex j (i < j); each face's n·v is linear along it.
void hard_edge_pieces(const Mesh& mesh, const std::vector<float>& g, const HalfEdge& A, const HalfEdge& B,
                      std::vector<LineSegment>& out) {
    const uint32_t i = std::min(A.from.vertex, A.to.vertex), j = std::max(A.from.vertex, A.to.vertex);
    // Each face's corners at i and j.
    auto end = [&](const HalfEdge& h, uint32_t v) { return corner_at(mesh, h.face, v); };
    const Corner ai = end(A, i), aj = end(A, j), bi = end(B, i), bj = end(B, j);
    if (ai.normal == bi.normal && aj.normal == bj.normal) return;  // smooth: face crossings cover it
    const double gai = g[ai.at], gaj = g[aj.at], gbi = g[bi.at], gbj = g[bj.at];

    struct Stop {
        double t;
        glm::vec3 p;
        uint64_t key;
    };
    std::vector<Stop> stops{{0.0, mesh.positions[i], vertex_key(i)}};
    auto add_crossing = [&](double gi, double gj, Corner ci, Corner cj) {
        if ((gi >= 0.0) == (gj >= 0.0)) return;
        stops.push_back({gi / (gi - gj), crossing(mesh, g, ci, cj), edge_key(ci.normal, cj.normal)});
    };
    add_crossing(gai, gaj, ai, aj);
    add_crossing(gbi, gbj, bi, bj);
    stops.push_back({1.0, mesh.positions[j], vertex_key(j)});
    std::sort(stops.begin() + 1, stops.end() - 1, [](const Stop& x, const Stop& y) { return x.t < y.t; });

    for (size_t s = 0; s + 1 < stops.size(); ++s) {
        const Stop &lo = stops[s], &hi = stops[s + 1];
        if (!(hi.t > lo.t) || lo.p == hi.p) continue;
        const double m = 0.5 * (lo.t + hi.t);
        const bool a_front = (1.0 - m) * gai + m * gaj >= 0.0, b_front = (1.0 - m) * gbi + m * gbj >= 0.0;
        if (a_front == b_front) continue;
        // The front face on the left: it walks the edge from i to j, or the piece is reversed.
        const HalfEdge& front = a_front ? A : B;
        const bool forward = front.from.vertex == i;
        LineSegment seg;
        seg.face = std::min(A.face, B.face);
        seg.face_b = std::max(A.face, B.face);  // it lies on both (visibility: PointOn)
        seg.a = forward ? lo.p : hi.p;
        seg.b = forward ? hi.p : lo.p;
        seg.edge_a = forward ? lo.key : hi.key;
        seg.edge_b = forward ? hi.key : lo.key;
        out.push_back(seg);
    }
}

}  // namespace

HardEdgeTable hard_edge_table(const Mesh& mesh) {
    // A hard edge has a split vertex (one of several shading normals) at an end at least: the
    // faces at split vertices are listed in ShadingSplits::corner_face.
    HardEdgeTable table;
    const ShadingSplits& s = mesh.shading_splits;
    std::vector<HalfEdge> half;
    std::vector<uint32_t> faces = s.corner_face;
    tbb::parallel_sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    for (uint32_t f : faces) {
        if (f >= mesh.triangles.size() || !face_is_valid(mesh, f)) continue;
        const glm::uvec3 t = mesh.triangles[f];
        for (int k = 0; k < 3; ++k) {
            const ShadingCorner from{t[k], mesh.shading_normal_id(f, k)},
                to{t[(k + 1) % 3], mesh.shading_normal_id(f, (k + 1) % 3)};
            if (from.vertex != to.vertex && (is_split(s, from.vertex) || is_split(s, to.vertex)))
                half.push_back({edge_key(from.vertex, to.vertex), f, from, to});
        }
    }
    tbb::parallel_sort(half.begin(), half.end(), [](const HalfEdge& x, const HalfEdge& y) {
        return std::tie(x.key, x.face) < std::tie(y.key, y.face);
    });
    auto normal_at = [](const HalfEdge& h, uint32_t v) { return h.from.vertex == v ? h.from.normal : h.to.normal; };
    for (size_t i = 0; i < half.size();) {
        size_t j = i;
        while (j < half.size() && half[j].key == half[i].key) ++j;
        // Borders (one face) are their own line type; non-manifold edges (three or more) have no
        // one pair of sides to compare; an edge whose faces share both ends' normals is smooth.
        if (j - i == 2 && half[i].face != half[i + 1].face) {
            const HalfEdge &a = half[i], &b = half[i + 1];
            const uint32_t u = a.from.vertex, w = a.to.vertex;
            if (normal_at(a, u) != normal_at(b, u) || normal_at(a, w) != normal_at(b, w)) table.edges.push_back({a, b});
        }
        i = j;
    }
    return table;
}

std::vector<LineSegment> extract_hard_edge_contours(const Mesh& mesh, const HardEdgeTable& table,
                                                    const Camera& camera) {
    const std::vector<float> g = view_dot_normals(mesh, camera);
    std::vector<LineSegment> out = face_crossings(mesh, g);
    const std::vector<LineSegment> edges =
        collect_per_face<LineSegment>(table.edges.size(), [&](size_t e, std::vector<LineSegment>& found) {
            hard_edge_pieces(mesh, g, table.edges[e][0], table.edges[e][1], found);
        });
    out.insert(out.end(), edges.begin(), edges.end());
    return out;
}

std::vector<LineSegment> extract_hard_edge_contours(const Mesh& mesh, const Camera& camera) {
    return extract_hard_edge_contours(mesh, hard_edge_table(mesh), camera);
}

}  // namespace inkshade::geometry
