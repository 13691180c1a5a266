// Intersection lines. Two parts:
//
// 1. Candidate pairs. A bounding volume hierarchy over the triangles' boxes: the faces sorted
//    by the Morton code of their box centre (30 bits; ties by face index), then a complete
//    binary tree over that order, four faces a leaf, node boxes merged bottom-up (a linear BVH
//    with the tree shape fixed by the sort: no split search, each level one parallel loop;
//    the sort gives the spatial locality). Each leaf queries the tree with its box, skipping
//    the subtrees of earlier leaves, so every overlapping pair of faces is tested once (a
//    query per leaf rather than per face: a quarter of the traversals). Leaves in blocks on
//    TBB tasks; the few crossing pairs are then sorted by (f, g), so the output does not
//    depend on the thread count. All pairs would be O(n²); this is about O(n log n).
//
// 2. The pair test, after Möller 1997 ("A fast triangle-triangle intersection test", Journal
//    of Graphics Tools 2(2)): reject unless each triangle has vertices on both sides of the
//    other's plane; the crossing is then the overlap of the two triangles' cuts by the other's
//    plane, and its two ends are where an edge of one triangle pierces the other. Unlike
//    Möller's interval comparison along the common line, whether an edge pierces a face is
//    decided from that (edge, face) pair alone, with the edge taken from its lower to its
//    higher vertex index: the plane sides of its two ends, then the orientation of the edge's
//    line against the three edges of the face (the line passes through the face iff it turns
//    the same way around all three: the sign test of Plücker coordinates, each sign a 3×3
//    determinant of the four points). So the two faces on either side of an edge agree
//    whether it pierces a face and, the point being computed from the same pair in double,
//    on the point's bits: their segments join there.
//
// Exact zeros (a vertex in the other face's plane, an edge line through the other face's edge)
// are decided by fixed rules, as the contour code counts g = 0 as positive: a zero plane value
// counts as the front side, and the orientation of two edges, computed once per pair of edges
// in an order fixed by their vertex indices, counts as positive when zero. A single zero can be
// moved either way by an arbitrarily small perturbation of the points, so whichever sign the
// rule picks is a configuration that exists, and every pair still gets zero or two pierce
// points (an edge crossing an edge exactly is then given to one of the two faces beside it,
// and the other face's edge pierces the first surface instead). Where an edge crosses a plane
// exactly at its vertex, the pierce point is that vertex, keyed by the vertex (not the edge) so
// every face around it meets at one node. Faces with a vertex each at the same point (separate
// parts tessellated alike, e.g. mirror images) are handled apart: their crossing runs from that
// point. A pair whose ends do not come out as exactly two distinct pierce points (rounding in
// nearly degenerate configurations, or several zeros at once) gives no segment.
#include "geometry/intersection_lines.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

namespace inkshade::geometry {

namespace {

using glm::dvec3;

constexpr size_t kLeafSize = 4;       // faces per BVH leaf
constexpr size_t kQueryGrain = 4096;  // faces per TBB task in the build
constexpr size_t kLeafGrain = 256;    // leaves per TBB task in the pair search

struct Box {
    glm::vec3 lo{std::numeric_limits<float>::infinity()};
    glm::vec3 hi{-std::numeric_limits<float>::infinity()};

    void add(const Box& b) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
};

// Closed boxes: faces that only touch are still tested (an empty box overlaps nothing).
bool overlaps(const Box& a, const Box& b) {
    return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y && a.lo.z <= b.hi.z &&
           b.lo.z <= a.hi.z;
}

Box face_box(const Mesh& mesh, const glm::uvec3& t) {
    const glm::vec3 &a = mesh.positions[t.x], &b = mesh.positions[t.y], &c = mesh.positions[t.z];
    return {glm::min(glm::min(a, b), c), glm::max(glm::max(a, b), c)};
}

// In-range, distinct indices, finite positions and a nonzero normal.
bool usable(const Mesh& mesh, const glm::uvec3& t) {
    const size_t nv = mesh.positions.size();
    if (t.x >= nv || t.y >= nv || t.z >= nv || t.x == t.y || t.y == t.z || t.x == t.z) return false;
    const glm::vec3 &a = mesh.positions[t.x], &b = mesh.positions[t.y], &c = mesh.positions[t.z];
    if (!is_finite(a) || !is_finite(b) || !is_finite(c)) return false;
    return glm::cross(dvec3(b) - dvec3(a), dvec3(c) - dvec3(a)) != dvec3(0.0);
}

// 10 bits of x spread to every third bit.
uint32_t spread_bits(uint32_t x) {
    x &= 0x3ffu;
    x = (x | (x << 16)) & 0x030000ffu;
    x = (x | (x << 8)) & 0x0300f00fu;
    x = (x | (x << 4)) & 0x030c30c3u;
    x = (x | (x << 2)) & 0x09249249u;
    return x;
}

// The usable faces in a linear BVH (file comment).
class FaceBvh {
public:
    explicit FaceBvh(const Mesh& mesh) {
        const size_t nf = mesh.triangles.size();
        std::vector<uint8_t> ok(nf);
        // Box of the usable faces' box centres, in double (a sum of large floats may overflow).
        struct Bounds {
            dvec3 lo{std::numeric_limits<double>::infinity()}, hi{-std::numeric_limits<double>::infinity()};
        };
        const auto centre = [&](size_t f) {
            const Box b = face_box(mesh, mesh.triangles[f]);
            return 0.5 * (dvec3(b.lo) + dvec3(b.hi));
        };
        const Bounds bounds = tbb::parallel_reduce(
            tbb::blocked_range<size_t>(0, nf, kQueryGrain), Bounds{},
            [&](const tbb::blocked_range<size_t>& r, Bounds acc) {
            for (size_t f = r.begin(); f != r.end(); ++f) {
                ok[f] = usable(mesh, mesh.triangles[f]);
                if (!ok[f]) continue;
                const dvec3 c = centre(f);
                acc.lo = glm::min(acc.lo, c);
                acc.hi = glm::max(acc.hi, c);
            }
            return acc;
            },
            [](Bounds a, const Bounds& b) {
            a.lo = glm::min(a.lo, b.lo);
            a.hi = glm::max(a.hi, b.hi);
            return a;
        });
        // Key: Morton code in the high word, face index in the low one; unusable faces last.
        std::vector<uint64_t> keys(nf);
        const dvec3 extent = bounds.hi - bounds.lo;
        const double largest = std::max({extent.x, extent.y, extent.z});
        const double scale = largest > 0.0 ? 1023.0 / largest : 0.0;
        tbb::parallel_for(tbb::blocked_range<size_t>(0, nf, kQueryGrain), [&](const tbb::blocked_range<size_t>& r) {
            for (size_t f = r.begin(); f != r.end(); ++f) {
                if (!ok[f]) {
                    keys[f] = ~uint64_t(0);
                    continue;
                }
                const dvec3 q = glm::clamp((centre(f) - bounds.lo) * scale, 0.0, 1023.0);
                const uint32_t code =
                    (spread_bits(uint32_t(q.x)) << 2) | (spread_bits(uint32_t(q.y)) << 1) | spread_bits(uint32_t(q.z));
                keys[f] = (uint64_t(code) << 32) | f;
            }
        });
        tbb::parallel_sort(keys.begin(), keys.end());
        const size_t n = size_t(std::count(ok.begin(), ok.end(), uint8_t(1)));
        faces_.resize(n);
        boxes_.resize(n);
        tbb::parallel_for(tbb::blocked_range<size_t>(0, n, kQueryGrain), [&](const tbb::blocked_range<size_t>& r) {
            for (size_t s = r.begin(); s != r.end(); ++s) {
                faces_[s] = uint32_t(keys[s]);
                boxes_[s] = face_box(mesh, mesh.triangles[faces_[s]]);
            }
        });
        if (n == 0) return;

        // A complete binary tree: node i has children 2i + 1 and 2i + 2; the leaves (a power
        // of two of them, the ones past the faces empty) start at leaf_base_.
        const size_t leaves = (n + kLeafSize - 1) / kLeafSize;
        size_t width = 1;
        while (width < leaves) width *= 2;
        leaf_base_ = width - 1;
        nodes_.assign(2 * width - 1, Box{});
        tbb::parallel_for(tbb::blocked_range<size_t>(0, leaves, kQueryGrain), [&](const tbb::blocked_range<size_t>& r) {
            for (size_t k = r.begin(); k != r.end(); ++k)
                for (size_t s = k * kLeafSize; s < std::min(n, (k + 1) * kLeafSize); ++s)
                    nodes_[leaf_base_ + k].add(boxes_[s]);
        });
        for (size_t first = leaf_base_; first > 0;) {
            const size_t parent_first = (first - 1) / 2;
            tbb::parallel_for(tbb::blocked_range<size_t>(parent_first, first, kQueryGrain),
                              [&](const tbb::blocked_range<size_t>& r) {
                for (size_t p = r.begin(); p != r.end(); ++p) {
                    nodes_[p] = nodes_[2 * p + 1];
                    nodes_[p].add(nodes_[2 * p + 2]);
                }
            });
            first = parent_first;
        }
    }

    size_t leaf_count() const { return (faces_.size() + kLeafSize - 1) / kLeafSize; }

    // Calls visit(a, b) for each face a of leaf k and face b of leaf k or a later one (after a
    // in leaf k) whose boxes overlap: over all leaves, every overlapping pair once. One
    // traversal per leaf, not per face, and subtrees of earlier leaves are skipped whole.
    template <class Visit>
    void pairs_of_leaf(size_t k, Visit&& visit) const {
        const Box& box = nodes_[leaf_base_ + k];
        const size_t first = k * kLeafSize, last = std::min(first + kLeafSize, faces_.size());
        size_t stack[64];  // depth ≤ 32: at most one pending sibling per level
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const size_t i = stack[--top];
            const int depth = int(std::bit_width(i + 1)) - 1;  // node i covers leaves [lo, lo + span)
            const size_t span = (leaf_base_ + 1) >> depth, lo = (i + 1 - (size_t(1) << depth)) * span;
            if (lo + span <= k || !overlaps(nodes_[i], box)) continue;
            if (i < leaf_base_) {
                stack[top++] = 2 * i + 2;
                stack[top++] = 2 * i + 1;
                continue;
            }
            const size_t other = (i - leaf_base_) * kLeafSize, other_last = std::min(other + kLeafSize, faces_.size());
            for (size_t s = first; s < last; ++s)
                for (size_t t = std::max(other, s + 1); t < other_last; ++t)
                    if (overlaps(boxes_[s], boxes_[t])) visit(faces_[s], faces_[t]);
        }
    }

private:
    std::vector<uint32_t> faces_;  // usable faces in Morton order
    std::vector<Box> boxes_;       // box of faces_[s]
    std::vector<Box> nodes_;
    size_t leaf_base_ = 0;
};

// A face's vertex indices, positions and (unnormalised, counter-clockwise) normal, always
// computed the same way, so a plane value has the same bits in every pair it is used in.
struct FaceGeometry {
    glm::uvec3 v;
    dvec3 p[3];
    dvec3 n;
};

FaceGeometry geometry_of(const Mesh& mesh, uint32_t f) {
    FaceGeometry g;
    g.v = mesh.triangles[f];
    for (int k = 0; k < 3; ++k) g.p[k] = dvec3(mesh.positions[g.v[k]]);
    g.n = glm::cross(g.p[1] - g.p[0], g.p[2] - g.p[0]);
    return g;
}

// Signed distance of p from the face's plane, times the normal's length.
double plane_value(const FaceGeometry& g, const dvec3& p) { return glm::dot(p - g.p[0], g.n); }

// Zero counts as positive (the fixed rule for exact zeros).
int sign_of(double x) { return x < 0.0 ? -1 : 1; }

double orientation(const dvec3& a, const dvec3& b, const dvec3& c, const dvec3& d) {
    return glm::dot(d - a, glm::cross(b - a, c - a));
}

// Sign of the orientation of the lines through edges (i, j) and (k, l), i < j and k < l, the
// four indices distinct: computed with the edge of the lower first index first, so both faces
// and both pairs that ask for it get the same value (swapping the two edges is an even
// permutation of the four points, so the sign is that of either order).
int edge_orientation(uint32_t i, const dvec3& pi, const dvec3& pj, uint32_t k, const dvec3& pk, const dvec3& pl) {
    return sign_of(i < k ? orientation(pi, pj, pk, pl) : orientation(pk, pl, pi, pj));
}

// Whether the line of edge (i, j), i < j (pi, pj its ends), passes through face g: it turns the same way around
// each of g's directed edges.
bool line_through_face(uint32_t i, const dvec3& pi, const dvec3& pj, const FaceGeometry& g) {
    int first = 0;
    for (int k = 0; k < 3; ++k) {
        const int k1 = (k + 1) % 3;
        const uint32_t x = g.v[k], y = g.v[k1];
        const int s =
            x < y ? edge_orientation(i, pi, pj, x, g.p[k], g.p[k1]) : -edge_orientation(i, pi, pj, y, g.p[k1], g.p[k]);
        if (k == 0)
            first = s;
        else if (s != first)
            return false;
    }
    return true;
}

// Whether point p, in g's plane, lies inside g: on the inner side of each directed edge, the
// side computed along the edge from its lower to its higher index (a zero counts as inside
// the face that runs the edge that way, so a point on a shared edge is in exactly one face).
bool point_in_face(const dvec3& p, const FaceGeometry& g) {
    for (int k = 0; k < 3; ++k) {
        const int k1 = (k + 1) % 3;
        const bool forward = g.v[k] < g.v[k1];
        const dvec3& lo = forward ? g.p[k] : g.p[k1];
        const dvec3& hi = forward ? g.p[k1] : g.p[k];
        const int s = sign_of(glm::dot(glm::cross(hi - lo, p - lo), g.n));
        if ((forward ? s : -s) < 0) return false;
    }
    return true;
}

// Where an edge or a vertex of one face pierces another face.
struct Pierce {
    uint64_t feature = 0;  // edge_key(i, j), or vertex_key(v) where the crossing is at vertex v
    uint32_t face = 0;     // the pierced face
    glm::vec3 p{0.0f};

    bool same_node(const Pierce& o) const { return feature == o.feature && face == o.face; }
    bool operator<(const Pierce& o) const { return feature != o.feature ? feature < o.feature : face < o.face; }
};

// Whether edge (i, j), i < j, with plane values di, dj against face g (index g_index),
// pierces it; the point from this pair alone.
bool pierce(uint32_t i, uint32_t j, const dvec3& pi, const dvec3& pj, double di, double dj, const FaceGeometry& g,
            uint32_t g_index, Pierce& out) {
    if (sign_of(di) == sign_of(dj)) return false;
    if (di == 0.0 || dj == 0.0) {  // through a vertex (not both: both zero count as one side)
        const bool at_i = di == 0.0;
        const dvec3& p = at_i ? pi : pj;
        if (!point_in_face(p, g)) return false;
        out = {vertex_key(at_i ? i : j), g_index, glm::vec3(p)};
        return true;
    }
    if (!line_through_face(i, pi, pj, g)) return false;
    const double t = di / (di - dj);
    out = {edge_key(i, j), g_index, glm::vec3(pi + t * (pj - pi))};
    return true;
}

bool straddles(const double d[3]) {
    const int s = sign_of(d[0]);
    return sign_of(d[1]) != s || sign_of(d[2]) != s;
}

// The pierce points of a's edges through b (d: plane values of a's vertices against b).
void edge_pierces(const FaceGeometry& a, const double d[3], const FaceGeometry& b, uint32_t b_index, Pierce* found,
                  int& count) {
    for (int k = 0; k < 3; ++k) {
        const int k1 = (k + 1) % 3;
        const bool forward = a.v[k] < a.v[k1];
        const int lo = forward ? k : k1, hi = forward ? k1 : k;
        Pierce p;
        if (!pierce(a.v[lo], a.v[hi], a.p[lo], a.p[hi], d[lo], d[hi], b, b_index, p)) continue;
        bool seen = false;  // two edges through the same vertex
        for (int m = 0; m < count; ++m) seen |= found[m].same_node(p);
        if (!seen) found[count++] = p;
    }
}

struct PairSegment {
    LineSegment segment;
    Pierce ends[2];
};

PairSegment segment_of(Pierce a, Pierce b, uint32_t f_index, uint32_t g_index) {
    if (b < a) std::swap(a, b);
    PairSegment out;
    out.ends[0] = a;
    out.ends[1] = b;
    out.segment = {.a = a.p, .b = b.p, .face = f_index, .face_b = g_index};
    return out;
}

// Pierce point of the edge of a opposite its corner k through b (plane values d of a's
// vertices against b).
bool opposite_edge_pierces(const FaceGeometry& a, int k, const double d[3], const FaceGeometry& b, uint32_t b_index,
                           Pierce& out) {
    int lo = (k + 1) % 3, hi = (k + 2) % 3;
    if (a.v[hi] < a.v[lo]) std::swap(lo, hi);
    return pierce(a.v[lo], a.v[hi], a.p[lo], a.p[hi], d[lo], d[hi], b, b_index, out);
}

// Faces f < g with one vertex each at the same point x (corners kf, kg; separate parts that
// meet there, e.g. mirror images tessellated alike): f ∩ g is x alone or a segment from x to
// where the edge of one opposite x pierces the other (a line through x meets the other's
// plane at x only, so the edges at x pierce nothing else). The curve through x is two such
// rays, joined at a node of their own: the two vertex indices, no face.
bool meet_at_common_point(const FaceGeometry& f, uint32_t f_index, int kf, const FaceGeometry& g, uint32_t g_index,
                          int kg, PairSegment& out) {
    double df[3], dg[3];
    for (int k = 0; k < 3; ++k) df[k] = plane_value(g, f.p[k]);
    for (int k = 0; k < 3; ++k) dg[k] = plane_value(f, g.p[k]);
    Pierce found[2];
    int count = 0;
    if (opposite_edge_pierces(f, kf, df, g, g_index, found[count])) ++count;
    if (opposite_edge_pierces(g, kg, dg, f, f_index, found[count])) ++count;
    if (count != 1) return false;  // two: the opposite edges cross each other (rounding)
    const Pierce x{edge_key(f.v[kf], g.v[kg]), kNoFace, glm::vec3(f.p[kf])};
    out = segment_of(x, found[0], f_index, g_index);
    return true;
}

// The segment of faces f < g when they cross.
bool intersect_pair(const FaceGeometry& f, uint32_t f_index, const FaceGeometry& g, uint32_t g_index,
                    PairSegment& out) {
    int common = 0, kf = 0, kg = 0;
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) {
            if (f.v[a] == g.v[b]) return false;  // a shared vertex (neighbours, as Line Art skips them)
            if (f.p[a] == g.p[b]) ++common, kf = a, kg = b;
        }
    if (common > 1) return false;  // an unwelded seam: the faces meet along an edge, or are one
    if (common == 1) return meet_at_common_point(f, f_index, kf, g, g_index, kg, out);
    double df[3], dg[3];  // f's vertices against g's plane, g's against f's
    for (int k = 0; k < 3; ++k) df[k] = plane_value(g, f.p[k]);
    if (!straddles(df)) return false;
    for (int k = 0; k < 3; ++k) dg[k] = plane_value(f, g.p[k]);
    if (!straddles(dg)) return false;
    Pierce found[6];
    int count = 0;
    edge_pierces(f, df, g, g_index, found, count);
    edge_pierces(g, dg, f, f_index, found, count);
    if (count != 2) return false;
    out = segment_of(found[0], found[1], f_index, g_index);
    return true;
}

}  // namespace

std::vector<LineSegment> extract_intersections(const Mesh& mesh) {
    const FaceBvh bvh(mesh);
    const size_t leaves = bvh.leaf_count();
    const size_t blocks = (leaves + kLeafGrain - 1) / kLeafGrain;
    std::vector<std::vector<PairSegment>> found(blocks);
    tbb::parallel_for(size_t(0), blocks, [&](size_t block) {
        for (size_t k = block * kLeafGrain; k < std::min(leaves, (block + 1) * kLeafGrain); ++k)
            bvh.pairs_of_leaf(k, [&](uint32_t a, uint32_t b) {
                const uint32_t f = std::min(a, b), g = std::max(a, b);
                const glm::uvec3 t = mesh.triangles[f], u = mesh.triangles[g];
                for (int c = 0; c < 3; ++c)
                    if (u[c] == t.x || u[c] == t.y || u[c] == t.z) return;  // neighbours: skipped at once
                PairSegment s;
                if (intersect_pair(geometry_of(mesh, f), f, geometry_of(mesh, g), g, s)) found[block].push_back(s);
            });
    });
    std::vector<PairSegment> pairs;
    for (auto& list : found) pairs.insert(pairs.end(), list.begin(), list.end());
    found = {};
    // Sorted by (face, face_b): the order does not depend on the tasks.
    tbb::parallel_sort(pairs.begin(), pairs.end(), [](const PairSegment& a, const PairSegment& b) {
        return a.segment.face != b.segment.face ? a.segment.face < b.segment.face : a.segment.face_b < b.segment.face_b;
    });

    // Number the distinct pierce points in (feature, face) order.
    std::vector<Pierce> nodes;
    nodes.reserve(2 * pairs.size());
    for (const PairSegment& s : pairs) nodes.insert(nodes.end(), {s.ends[0], s.ends[1]});
    tbb::parallel_sort(nodes.begin(), nodes.end());
    nodes.erase(
        std::unique(nodes.begin(), nodes.end(), [](const Pierce& a, const Pierce& b) { return a.same_node(b); }),
        nodes.end());
    const auto id_of = [&](const Pierce& p) {
        return pierce_key(uint32_t(std::lower_bound(nodes.begin(), nodes.end(), p) - nodes.begin()));
    };
    std::vector<LineSegment> segments(pairs.size());
    tbb::parallel_for(size_t(0), pairs.size(), [&](size_t k) {
        segments[k] = pairs[k].segment;
        segments[k].edge_a = id_of(pairs[k].ends[0]);
        segments[k].edge_b = id_of(pairs[k].ends[1]);
    });
    return segments;
}

}  // namespace inkshade::geometry
