// split_by_visibility and contour_surroundings (visibility.hpp): the sampling of chains and
// segments and the bisection of each change of occlusion level. The rays are RayScene's
// (ray_scene.cpp, occlusion_levels.cpp); the fold walks' edge table EdgeNeighbours'
// (edge_neighbours.cpp); the camera mapping ImageProjection's (image_projection.cpp).
#include "geometry/visibility.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "geometry/chaining.hpp"
#include "geometry/triangle_vertices.hpp"
#include "inkshade/lines.hpp"

namespace inkshade::geometry {

namespace {

constexpr uint8_t kClipped = 0xff;  // a sample outside the near/far range (not a level)
// An unsplit segment's level while it is unknown, and a split one's (its pieces have theirs).
constexpr uint8_t kSplit = 0xfe;  // not a level (levels ≤ kMaxOcclusionLevel) nor kClipped
static_assert(kMaxOcclusionLevel < kSplit && kSplit < kClipped);

bool is_vertex_key(uint64_t key) { return uint32_t(key >> 32) == uint32_t(key); }
bool is_edge_key(uint64_t key) { return uint32_t(key >> 32) < uint32_t(key); }
bool is_pierce_key(uint64_t key) { return uint32_t(key >> 32) == 0xfffffffcu; }

// A segment along a mesh edge (crease, border, silhouette edge): vertex keys at both ends.
bool along_edge(const LineSegment& s) { return is_vertex_key(s.edge_a) && is_vertex_key(s.edge_b); }

// A face that exists and indexes only existing vertices (then its shading normals exist too).
bool valid_face(const Mesh& mesh, uint32_t f) {
    return f < mesh.triangles.size() && in_range(mesh.triangles[f], mesh.positions.size());
}

// What the points strictly inside a segment lie on.
PointOn interior_on(const Mesh& mesh, const LineSegment& s) {
    PointOn on;
    if (valid_face(mesh, s.face)) on.face = s.face;
    if (valid_face(mesh, s.face_b)) on.face_b = s.face_b;
    if (s.face_b == kNoFace && along_edge(s)) {
        on.kind = PointOn::Edge;
        on.u = uint32_t(s.edge_a), on.v = uint32_t(s.edge_b);
    }
    return on;
}

// What a segment end with node key `key` lies on (key kinds: contours.hpp).
PointOn end_on(const Mesh& mesh, const LineSegment& s, uint64_t key) {
    PointOn on = interior_on(mesh, s);
    if (is_vertex_key(key)) {
        on.kind = PointOn::Vertex;
        on.u = uint32_t(key), on.v = kNoFace;
    } else if (is_edge_key(key)) {
        uint32_t a = uint32_t(key >> 32), b = uint32_t(key);
        if (on.face != kNoFace && on.face_b == kNoFace) {
            // An isoline's end on an edge of its face: the key names the edge by vertices, or on
            // a mesh with hard edges by the corners' shading normals (hard_edge_contours.hpp).
            const glm::uvec3 t = mesh.triangles[on.face];
            if (!(has_vertex(t, a) && has_vertex(t, b)) && mesh.has_hard_edges()) {
                const glm::uvec3 n(mesh.shading_normal_id(on.face, 0), mesh.shading_normal_id(on.face, 1),
                                   mesh.shading_normal_id(on.face, 2));
                uint32_t found[2], k_found = 0;
                for (int k = 0; k < 3; ++k)
                    if ((n[k] == a || n[k] == b) && k_found < 2) found[k_found++] = t[k];
                if (k_found == 2) a = found[0], b = found[1];
            }
            if (has_vertex(t, a) && has_vertex(t, b) && a != b) on.kind = PointOn::Edge, on.u = a, on.v = b;
        } else if (on.face == kNoFace && a < mesh.positions.size() && b < mesh.positions.size()) {
            on.kind = PointOn::Edge, on.u = a, on.v = b;
        }
        // A hard edge's piece (face and face_b: the edge's two faces) keeps its two faces.
    } else if (is_pierce_key(key)) {
        on.kind = PointOn::FaceNeighbours;
    }
    return on;
}

// The interpolated unit normal at p in face f (vertex normals, or the corners' shading normals
// on a mesh with hard edges, as the contour itself takes them); zero when undefined.
glm::vec3 interpolated_normal(const Mesh& mesh, uint32_t f, const glm::vec3& point) {
    const glm::uvec3 t = mesh.triangles[f];
    glm::dvec3 n[3];
    for (int k = 0; k < 3; ++k)
        n[k] = glm::dvec3(mesh.has_hard_edges() ? mesh.shading_normal(f, k) : mesh.normals[t[k]]);
    const glm::dvec3 P0(mesh.positions[t.x]), e1 = glm::dvec3(mesh.positions[t.y]) - P0,
                                              e2 = glm::dvec3(mesh.positions[t.z]) - P0;
    // Barycentric coordinates from the Gram matrix of (e1, e2).
    const double g11 = glm::dot(e1, e1), g12 = glm::dot(e1, e2), g22 = glm::dot(e2, e2);
    const double det = g11 * g22 - g12 * g12;
    if (!(std::abs(det) > 0.0)) return glm::vec3(0.0f);
    const glm::dvec3 x = glm::dvec3(point) - P0;
    const double r1 = glm::dot(x, e1), r2 = glm::dot(x, e2);
    const double b1 = (g22 * r1 - g12 * r2) / det, b2 = (g11 * r2 - g12 * r1) / det;
    const glm::dvec3 ni = (1.0 - b1 - b2) * n[0] + b1 * n[1] + b2 * n[2];
    const double len = glm::length(ni);
    return len > 0.0 ? glm::vec3(ni / len) : glm::vec3(0.0f);
}

// What a sample's ray leaves out, in pixels at the sample (VisibilityOptions).
struct Allowance {
    float fold_px;  // contour samples: the fold band, else 0
    float own_depth_px, own_radius_px;
    float slope_px;  // contour and own_slope samples: OcclusionQuery::slope_depth in pixels
};

OcclusionQuery query_at(const Mesh& mesh, const ImageProjection& view, const glm::vec3& p, const PointOn& on,
                        const Allowance& allow) {
    OcclusionQuery q;
    q.point = p;
    q.on = on;
    const double pixel = view.pixel_size(p);
    q.own_depth = float(allow.own_depth_px * pixel);
    // At least the depth: a held hit then lies on a face within the radius (occlusion_levels.cpp).
    q.own_radius = float(std::max(allow.own_radius_px, allow.own_depth_px) * pixel);
    if (allow.fold_px > 0.0f && on.face != kNoFace && on.face_b == kNoFace && on.kind != PointOn::Vertex) {
        q.normal = interpolated_normal(mesh, on.face, p);
        if (q.normal != glm::vec3(0.0f)) {
            q.fold_band = float(allow.fold_px * pixel);
            // An interpolated contour only: a hard edge's contour is the polygon outline itself.
            q.slope_depth = float(allow.slope_px * pixel);
        }
    } else if (allow.fold_px == 0.0f && on.face != kNoFace) {
        q.slope_depth = float(allow.slope_px * pixel);  // VisibilityOptions::own_slope
    }
    return q;
}

struct Piece {
    double t0, t1;
    uint8_t level;
};

glm::vec3 lerp(const LineSegment& s, double t) {
    return glm::vec3(glm::dvec3(s.a) + t * (glm::dvec3(s.b) - glm::dvec3(s.a)));
}

double pixel_distance(const ImageProjection& view, const glm::vec3& a, const glm::vec3& b) {
    const glm::dvec3 pa = view.project(a), pb = view.project(b);
    return std::hypot(pa.x - pb.x, pa.y - pb.y);
}

// Key of a split point: high word 0xfffffffd, low word a counter below it — no edge key
// (high < low), vertex key (high == low), face_interior_key (high ≥ 0xfffffffe) or pierce key
// (0xfffffffc) has it.
constexpr uint64_t split_key(uint32_t counter) { return (uint64_t(0xfffffffdu) << 32) | counter; }

// A point to test and what it lies on.
struct Sample {
    glm::vec3 point;
    PointOn on;
};

struct Tester {
    const RayScene& scene;
    const Mesh& mesh;
    const ImageProjection& view;
    const EdgeNeighbours* around;
    int cap;
    Allowance allow;

    // The levels of many samples (kClipped outside the near/far range) as ray streams
    // (rtcOccluded1M, one ray at a time: occlusion_levels.cpp), in fixed blocks on TBB tasks:
    // the same blocks whatever the thread count, so the results do not depend on it.
    void levels(const std::vector<Sample>& samples, std::vector<uint8_t>& out) const {
        constexpr size_t kBlock = 64;
        out.resize(samples.size());
        tbb::parallel_for(size_t(0), (samples.size() + kBlock - 1) / kBlock, [&](size_t block) {
            OcclusionQuery queries[kBlock];
            uint8_t found[kBlock];
            size_t where[kBlock];
            size_t m = 0;
            const size_t end = std::min(samples.size(), (block + 1) * kBlock);
            for (size_t i = block * kBlock; i < end; ++i) {
                if (view.clipped(samples[i].point)) {
                    out[i] = kClipped;
                    continue;
                }
                queries[m] = query_at(mesh, view, samples[i].point, samples[i].on, allow);
                where[m++] = i;
            }
            scene.occlusion_levels(view, queries, m, found, cap, around);
            for (size_t k = 0; k < m; ++k) out[where[k]] = found[k];
        });
    }
};

// A segment whose ends differ in level, or longer than the sample spacing: sampled inside at
// `steps` equal parts, each change of level then bisected.
struct SegmentTask {
    uint32_t segment;
    uint8_t level_a, level_b;
    uint32_t steps;
    size_t first;  // its steps − 1 interior samples' index in the task list's sample array
};

// Samples parts of a segment when it is longer than `spacing` in the image (1 part when an end
// is clipped or the camera degenerate).
uint32_t segment_steps(const ImageProjection& view, const LineSegment& s, double spacing) {
    if (view.clipped(s.a) || view.clipped(s.b)) return 1;
    const double px = pixel_distance(view, s.a, s.b);
    // NaN (a degenerate camera) keeps one step instead of an undefined conversion.
    return std::isfinite(px) ? uint32_t(std::clamp(std::ceil(px / spacing), 1.0, 16384.0)) : 1;
}

// A change of level inside a task's segment, between parameters lo (level `level_lo`) and hi.
struct Bracket {
    uint32_t task;
    double lo, hi;
    uint8_t level_lo;
};

// Each task's pieces (into `pieces`, or `whole` when its samples agree): interior samples in
// one stream, then every change bisected in rounds of one stream each until its bracket is
// `precision` pixels long.
void resolve_segments(const Tester& tester, const std::vector<LineSegment>& segments,
                      const std::vector<SegmentTask>& tasks, double precision, std::vector<uint8_t>& whole,
                      std::vector<std::vector<Piece>>& pieces) {
    const ImageProjection& view = tester.view;
    const size_t interior = tasks.empty() ? 0 : tasks.back().first + tasks.back().steps - 1;
    std::vector<Sample> samples(interior);
    tbb::parallel_for(size_t(0), tasks.size(), [&](size_t i) {
        const SegmentTask& t = tasks[i];
        const LineSegment& s = segments[t.segment];
        const PointOn inside = interior_on(tester.mesh, s);
        for (uint32_t k = 1; k < t.steps; ++k) samples[t.first + k - 1] = {lerp(s, double(k) / t.steps), inside};
    });
    std::vector<uint8_t> levels;
    tester.levels(samples, levels);
    auto level_at = [&](const SegmentTask& t, uint32_t k) {
        return k == 0 ? t.level_a : k == t.steps ? t.level_b : levels[t.first + k - 1];
    };

    std::vector<Bracket> brackets;
    for (uint32_t i = 0; i < tasks.size(); ++i) {
        const SegmentTask& t = tasks[i];
        for (uint32_t k = 0; k < t.steps; ++k)
            if (level_at(t, k) != level_at(t, k + 1))
                brackets.push_back({i, double(k) / t.steps, double(k + 1) / t.steps, level_at(t, k)});
    }
    std::vector<uint32_t> active(brackets.size());
    for (uint32_t b = 0; b < active.size(); ++b) active[b] = b;
    std::vector<char> done;
    std::vector<uint8_t> found;
    for (int iter = 0; iter < 60 && !active.empty(); ++iter) {
        samples.resize(active.size());
        done.assign(active.size(), 0);
        tbb::parallel_for(size_t(0), active.size(), [&](size_t i) {
            const Bracket& b = brackets[active[i]];
            const LineSegment& s = segments[tasks[b.task].segment];
            const glm::vec3 plo = lerp(s, b.lo), phi = lerp(s, b.hi);
            const bool measurable = !view.clipped(plo) && !view.clipped(phi);
            done[i] = measurable ? pixel_distance(view, plo, phi) <= precision : b.hi - b.lo < 1e-7;
            samples[i] = {lerp(s, 0.5 * (b.lo + b.hi)), interior_on(tester.mesh, s)};
        });
        size_t kept = 0;
        for (size_t i = 0; i < active.size(); ++i)
            if (!done[i]) samples[kept] = samples[i], active[kept++] = active[i];
        samples.resize(kept);
        active.resize(kept);
        tester.levels(samples, found);
        for (size_t i = 0; i < kept; ++i) {
            Bracket& b = brackets[active[i]];
            (found[i] == b.level_lo ? b.lo : b.hi) = 0.5 * (b.lo + b.hi);
        }
    }

    // Runs of equal level, split at the middle of each change's bracket.
    size_t next = 0;
    for (uint32_t i = 0; i < tasks.size(); ++i) {
        const SegmentTask& t = tasks[i];
        if (next == brackets.size() || brackets[next].task != i) {
            whole[t.segment] = t.level_a;  // every sample agrees
            continue;
        }
        std::vector<Piece>& out = pieces[t.segment];
        double start = 0.0;
        for (; next < brackets.size() && brackets[next].task == i; ++next) {
            const Bracket& b = brackets[next];
            const double at = 0.5 * (b.lo + b.hi);
            out.push_back({start, at, b.level_lo});
            start = at;
        }
        out.push_back({start, 1.0, t.level_b});
    }
}

// One node of a chain (chaining.hpp): node i is where segment i starts in walking order, node
// k (k segments) where the last one ends. Its point and what it lies on come from the segment
// end there.
struct ChainNode {
    const LineSegment* segment;
    bool at_b;  // the node is the segment's b end
};

ChainNode chain_node(const std::vector<LineSegment>& segments, const Chain& chain, size_t i) {
    const size_t k = chain.segments.size();
    if (i < k) return {&segments[chain.segments[i]], chain.reversed[i] != 0};
    return {&segments[chain.segments[k - 1]], chain.reversed[k - 1] == 0};
}

glm::vec3 node_point(const ChainNode& n) { return n.at_b ? n.segment->b : n.segment->a; }

PointOn node_on(const Mesh& mesh, const ChainNode& n) {
    return end_on(mesh, *n.segment, n.at_b ? n.segment->edge_b : n.segment->edge_a);
}

Sample node_sample(const Mesh& mesh, const ChainNode& n) { return {node_point(n), node_on(mesh, n)}; }

// The chains of `segments` (chain_order), and each segment left out of them (both ends one
// key) as a chain of its own.
std::vector<Chain> sampling_chains(const std::vector<LineSegment>& segments) {
    const size_t n = segments.size();
    std::vector<Chain> chains = chain_order(segments);
    std::vector<char> chained(n, 0);
    for (const Chain& c : chains)
        for (uint32_t s : c.segments) chained[s] = 1;
    for (uint32_t s = 0; s < n; ++s)  // left out of chains (both ends one key): alone
        if (!chained[s]) chains.push_back({{s}, {0}, false});
    return chains;
}

// The nodes of a chain to sample, no more than `spacing` apart in the image (and both nodes of
// a segment with a clipped end); none when the whole chain is shorter than `min_length_px`
// and nothing can join it to more.
std::vector<uint32_t> sampled_nodes(const ImageProjection& view, const std::vector<LineSegment>& segments,
                                    const Chain& chain, double spacing, float min_length_px) {
    const size_t k = chain.segments.size();
    // Image length of each segment; infinite where an end is clipped (or the camera is
    // degenerate), which makes both its nodes samples.
    std::vector<double> step(k, std::numeric_limits<double>::infinity());
    const glm::vec3 p0 = node_point(chain_node(segments, chain, 0));
    bool prev_ok = !view.clipped(p0);
    glm::dvec3 prev = prev_ok ? view.project(p0) : glm::dvec3(0.0);
    for (size_t i = 0; i < k; ++i) {
        const glm::vec3 p = node_point(chain_node(segments, chain, i + 1));
        const bool ok = !view.clipped(p);
        const glm::dvec3 q = ok ? view.project(p) : glm::dvec3(0.0);
        const double d = std::hypot(q.x - prev.x, q.y - prev.y);
        if (ok && prev_ok && std::isfinite(d)) step[i] = d;
        prev = q, prev_ok = ok;
    }
    // A whole chain shorter than the caller keeps: every part of it would be shorter too.
    if (chain.component && min_length_px > 0.0f &&
        std::accumulate(step.begin(), step.end(), 0.0) + 1e-3 < double(min_length_px))
        return {};  // no samples: its segments are left out of the result
    // Greedy: from each sample, the farthest node within `spacing`, or the next node.
    std::vector<uint32_t> out;
    out.push_back(0);
    for (size_t i = 0; i < k;) {
        size_t j = i + 1;
        double length = step[i];
        while (j < k && length + step[j] <= spacing) length += step[j++];
        out.push_back(uint32_t(j));
        i = j;
    }
    return out;
}

// The levels of chosen nodes of every chain (`nodes[c]`), in one stream: chain c's are at
// first[c] onwards in `levels`.
void levels_of_nodes(const Tester& tester, const std::vector<LineSegment>& segments, const std::vector<Chain>& chains,
                     const std::vector<std::vector<uint32_t>>& nodes, std::vector<size_t>& first,
                     std::vector<uint8_t>& levels) {
    first.assign(chains.size() + 1, 0);
    for (size_t c = 0; c < chains.size(); ++c) first[c + 1] = first[c] + nodes[c].size();
    std::vector<Sample> samples(first.back());
    tbb::parallel_for(size_t(0), chains.size(), [&](size_t c) {
        for (size_t k = 0; k < nodes[c].size(); ++k)
            samples[first[c] + k] = node_sample(tester.mesh, chain_node(segments, chains[c], nodes[c][k]));
    });
    tester.levels(samples, levels);
}

// Per chain, the nodes between two sampled nodes (`sampled`, their levels from first[c] on in
// `levels`) of different levels.
std::vector<std::vector<uint32_t>> nodes_in_changes(const std::vector<std::vector<uint32_t>>& sampled,
                                                    const std::vector<size_t>& first,
                                                    const std::vector<uint8_t>& levels) {
    std::vector<std::vector<uint32_t>> inner(sampled.size());
    tbb::parallel_for(size_t(0), sampled.size(), [&](size_t c) {
        const std::vector<uint32_t>& nodes = sampled[c];
        for (size_t m = 0; m + 1 < nodes.size(); ++m)
            if (levels[first[c] + m] != levels[first[c] + m + 1])
                for (uint32_t i = nodes[m] + 1; i < nodes[m + 1]; ++i) inner[c].push_back(i);
    });
    return inner;
}

// A chain's segments from the levels of its sampled nodes (`node_level`, one a node of
// `nodes`) and of the nodes in between that changed (`inner_level`, in order): a segment
// between two samples of one level takes it (`whole`); one whose ends differ, or that is
// longer than `spacing`, becomes a task for resolve_segments.
std::vector<SegmentTask> chain_segment_tasks(const ImageProjection& view, const std::vector<LineSegment>& segments,
                                             const Chain& chain, const std::vector<uint32_t>& nodes,
                                             const uint8_t* node_level, const uint8_t* inner_level, double spacing,
                                             std::vector<uint8_t>& whole) {
    std::vector<SegmentTask> tasks;
    // Levels at a segment's start and end in walking order, to its a and b ends.
    auto set_segment = [&](size_t i, uint8_t level_start, uint8_t level_end) {
        const uint32_t s = chain.segments[i];
        const bool rev = chain.reversed[i] != 0;
        const uint8_t la = rev ? level_end : level_start, lb = rev ? level_start : level_end;
        const uint32_t steps = segment_steps(view, segments[s], spacing);
        if (la == lb && steps == 1)
            whole[s] = la;
        else
            tasks.push_back({s, la, lb, steps, 0});
    };
    for (size_t m = 0; m + 1 < nodes.size(); ++m) {
        const size_t lo = nodes[m], end = nodes[m + 1];
        const uint8_t level_lo = node_level[m], level_end = node_level[m + 1];
        if (level_lo == level_end && end - lo > 1) {
            for (size_t i = lo; i < end; ++i) whole[chain.segments[i]] = level_lo;
            continue;
        }
        uint8_t level = level_lo;
        for (size_t i = lo; i < end; ++i) {
            const uint8_t next = i + 1 == end ? level_end : *inner_level++;
            set_segment(i, level, next);
            level = next;
        }
    }
    return tasks;
}

// The parts of every segment, gathered serially in input order so that split keys and output
// order are deterministic: an unsplit segment (`whole`: its level) as it is, a split one cut
// at its pieces' ends; clipped parts left out.
VisibilitySplit gather_parts(const std::vector<LineSegment>& segments, const std::vector<uint8_t>& whole,
                             const std::vector<std::vector<Piece>>& pieces) {
    VisibilitySplit result;
    auto emit = [&](const LineSegment& part, uint8_t level) {
        if (level == kClipped) return;
        if (level == 0) {
            result.visible.push_back(part);
        } else {
            result.hidden.push_back(part);
            result.hidden_levels.push_back(level);
        }
    };
    uint32_t counter = 0;
    for (size_t i = 0; i < segments.size(); ++i) {
        const LineSegment& s = segments[i];
        if (whole[i] != kSplit) {
            emit(s, whole[i]);
            continue;
        }
        for (const Piece& p : pieces[i]) {
            if (p.level == kClipped) continue;
            LineSegment part = s;
            if (p.t0 > 0.0) {
                part.a = lerp(s, p.t0);
                part.edge_a = split_key(counter++);
                part.strength_a = float(s.strength_a + p.t0 * (s.strength_b - s.strength_a));
            }
            if (p.t1 < 1.0) {
                part.b = lerp(s, p.t1);
                part.edge_b = split_key(counter++);
                part.strength_b = float(s.strength_a + p.t1 * (s.strength_b - s.strength_a));
            }
            emit(part, p.level);
        }
    }
    return result;
}

}  // namespace

EdgeNeighbours contour_surroundings(const Mesh& mesh, const std::vector<const std::vector<LineSegment>*>& contours) {
    std::vector<uint32_t> vertices;
    for (const std::vector<LineSegment>* list : contours)
        for (const LineSegment& s : *list)
            for (uint32_t f : {s.face, s.face_b})
                if (valid_face(mesh, f))
                    for (int k = 0; k < 3; ++k) vertices.push_back(mesh.triangles[f][k]);
    return EdgeNeighbours(mesh, vertices);
}

VisibilitySplit split_by_visibility(const RayScene& scene, const Mesh& mesh, const ImageProjection& view,
                                    const std::vector<LineSegment>& segments, const VisibilityOptions& options,
                                    const EdgeNeighbours* around) {
    const size_t n = segments.size();
    const double spacing = std::max(double(options.sample_spacing_px), 1e-3);
    const double precision = std::max(double(options.transition_precision_px), 1e-4);
    EdgeNeighbours own;
    if (!around && options.contour) {
        own = contour_surroundings(mesh, {&segments});
        around = &own;
    }
    // The slope allowance: contours, and the types that lie on the surface beside them.
    const float slope_px = options.contour || options.own_slope ? std::max(options.contour_slope_px, 0.0f) : 0.0f;
    const Tester tester{scene,
                        mesh,
                        view,
                        around,
                        std::clamp(options.count_levels_to, 1, kMaxOcclusionLevel),
                        {options.contour ? std::max(options.contour_fold_px, 0.0f) : 0.0f,
                         std::max(options.own_depth_px, 0.0f), std::max(options.own_radius_px, 0.0f), slope_px}};
    std::vector<uint8_t> whole(n, kSplit);      // level of an unsplit segment, else kSplit
    std::vector<std::vector<Piece>> pieces(n);  // pieces of split segments only

    // Samples go along chains, not segments: on a fine mesh a segment is a fraction of a pixel,
    // and testing each node would cost several rays a pixel. A chain is sampled at nodes no
    // more than `spacing` apart in the image (and inside segments longer than that); between
    // two samples of one level the segments take it, between two of different levels the
    // nodes in between are searched for the change, then the segment with it is bisected.
    const std::vector<Chain> chains = sampling_chains(segments);
    std::vector<std::vector<uint32_t>> sampled(chains.size());  // chosen in parallel
    tbb::parallel_for(size_t(0), chains.size(), [&](size_t c) {
        sampled[c] = sampled_nodes(view, segments, chains[c], spacing, options.min_length_px);
    });
    std::vector<size_t> first;
    std::vector<uint8_t> node_levels;
    levels_of_nodes(tester, segments, chains, sampled, first, node_levels);

    // Between two samples of one level, every segment takes it. Between samples of different
    // levels, every node in between is tested as well (one stream for all), then each segment
    // whose ends differ, or that is longer than `spacing`, is resolved (resolve_segments).
    const std::vector<std::vector<uint32_t>> inner = nodes_in_changes(sampled, first, node_levels);
    std::vector<size_t> inner_first;
    std::vector<uint8_t> inner_levels;
    levels_of_nodes(tester, segments, chains, inner, inner_first, inner_levels);

    std::vector<std::vector<SegmentTask>> chain_tasks(chains.size());
    tbb::parallel_for(size_t(0), chains.size(), [&](size_t c) {
        chain_tasks[c] = chain_segment_tasks(view, segments, chains[c], sampled[c], node_levels.data() + first[c],
                                             inner_levels.data() + inner_first[c], spacing, whole);
    });
    std::vector<SegmentTask> tasks;
    for (std::vector<SegmentTask>& list : chain_tasks)
        for (SegmentTask& t : list) {
            t.first = tasks.empty() ? 0 : tasks.back().first + tasks.back().steps - 1;
            tasks.push_back(t);
        }
    resolve_segments(tester, segments, tasks, precision, whole, pieces);
    return gather_parts(segments, whole, pieces);
}

}  // namespace inkshade::geometry
