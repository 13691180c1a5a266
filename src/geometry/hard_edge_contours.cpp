#include "geometry/hard_edge_contours.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "geometry/face_segments.hpp"

namespace inkshade::geometry {
namespace {

using Corner = ShadingCorner;

// Where n·v vanishes on the edge (a, b) of one face: computed from the ends ordered by shading
// normal id, so the face on the other side of a smooth edge, and the hard-edge piece that ends
// there, get the same bits.
glm::vec3 crossing(const Mesh& mesh, const std::vector<float>& g, Corner a, Corner b) {
    if (b.normal < a.normal) std::swap(a, b);
    const double ga = g[a.normal], gb = g[b.normal];
    const double t = ga / (ga - gb);
    const glm::dvec3 pa(mesh.positions[a.vertex]), pb(mesh.positions[b.vertex]);
    return glm::vec3(pa + t * (pb - pa));
}

bool face_is_valid(const Mesh& mesh, size_t f) {
    const glm::uvec3 t = mesh.triangles[f], s = mesh.shading_normal_ids[f];
    const size_t n = mesh.positions.size(), m = mesh.shading_normals.size();
    return t.x < n && t.y < n && t.z < n && s.x < m && s.y < m && s.z < m;
}

Corner corner(const Mesh& mesh, size_t f, int k) {
    return {mesh.triangles[f][k % 3], mesh.shading_normal_ids[f][k % 3]};
}

// n·v per shading normal, at the vertex it belongs to.
std::vector<float> shading_view_dot_normal(const Mesh& mesh, const HardEdgeTable& table, const Camera& camera) {
    const ViewVector view(camera);
    std::vector<float> g(table.owner.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, g.size(), kFaceGrain), [&](const auto& range) {
        for (size_t i = range.begin(); i != range.end(); ++i) {
            const double d = glm::dot(glm::dvec3(mesh.shading_normals[i]), view.at(mesh.positions[table.owner[i]]));
            g[i] = std::isfinite(d) ? float(d) : 0.0f;
        }
    });
    return g;
}

std::vector<LineSegment> face_crossings(const Mesh& mesh, const std::vector<float>& g) {
    return collect_face_segments(mesh.triangles.size(), [&](size_t f, std::vector<LineSegment>& out) {
        if (!face_is_valid(mesh, f)) return;
        const glm::uvec3 s = mesh.shading_normal_ids[f];
        const bool pos[3] = {g[s.x] >= 0.0f, g[s.y] >= 0.0f, g[s.z] >= 0.0f};
        if (pos[0] == pos[1] && pos[1] == pos[2]) return;
        const int k = pos[1] == pos[2] ? 0 : (pos[0] == pos[2] ? 1 : 2);  // the odd one out
        const Corner ck = corner(mesh, f, k), cnext = corner(mesh, f, k + 1), cprev = corner(mesh, f, k + 2);
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
    auto at = [](const HalfEdge& h, uint32_t v) { return h.from.vertex == v ? h.from : h.to; };
    const Corner ai = at(A, i), aj = at(A, j), bi = at(B, i), bj = at(B, j);
    if (ai.normal == bi.normal && aj.normal == bj.normal) return;  // smooth: face crossings cover it
    const double gai = g[ai.normal], gaj = g[aj.normal], gbi = g[bi.normal], gbj = g[bj.normal];

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

// Vertices with more than one shading normal: a hard edge has one at an end at least.
std::vector<uint8_t> split_vertices(const Mesh& mesh, HardEdgeTable& table) {
    table.owner.assign(mesh.shading_normals.size(), 0);
    std::vector<uint32_t> first(mesh.positions.size(), ~0u);
    std::vector<uint8_t> split(mesh.positions.size(), 0);
    for (size_t f = 0; f < mesh.triangles.size(); ++f) {
        if (!face_is_valid(mesh, f)) continue;
        for (int k = 0; k < 3; ++k) {
            const Corner c = corner(mesh, f, k);
            table.owner[c.normal] = c.vertex;
            if (first[c.vertex] == ~0u) first[c.vertex] = c.normal;
            split[c.vertex] |= first[c.vertex] != c.normal;
        }
    }
    return split;
}

}  // namespace

HardEdgeTable hard_edge_table(const Mesh& mesh) {
    HardEdgeTable table;
    const std::vector<uint8_t> split = split_vertices(mesh, table);
    std::vector<HalfEdge> half;
    for (size_t f = 0; f < mesh.triangles.size(); ++f) {
        if (!face_is_valid(mesh, f)) continue;
        for (int k = 0; k < 3; ++k) {
            const Corner from = corner(mesh, f, k), to = corner(mesh, f, k + 1);
            if (from.vertex != to.vertex && (split[from.vertex] || split[to.vertex]))
                half.push_back({edge_key(from.vertex, to.vertex), uint32_t(f), from, to});
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
    const std::vector<float> g = shading_view_dot_normal(mesh, table, camera);
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
