// Hatching strokes: a smoothed cross field, streamlines traced face to face, spacing kept with
// a hash grid of the accepted strokes' points (one grid per family and level; point_grid.hpp).
// The two families are traced as two tasks; the result does not depend on the thread count.
#include "geometry/hatching.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <iterator>
#include <optional>
#include <random>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_for.h>

#include "geometry/point_grid.hpp"

namespace inkshade::geometry {
namespace {

constexpr uint32_t kNone = 0xffffffffu;

// Faces across each of a face's three edges (edge k runs from corner k to corner k + 1);
// kNone on borders, non-manifold edges and degenerate faces.
std::vector<glm::uvec3> face_neighbours(const Mesh& mesh, const EdgeAdjacency& adj) {
    const auto& tris = mesh.triangles;
    std::vector<glm::uvec3> out(tris.size(), glm::uvec3(kNone));
    auto slot = [&](uint32_t f, uint32_t a, uint32_t b) -> int {
        const glm::uvec3 t = tris[f];
        for (int k = 0; k < 3; ++k) {
            const uint32_t u = t[k], v = t[(k + 1) % 3];
            if ((u == a && v == b) || (u == b && v == a)) return k;
        }
        return -1;
    };
    for (size_t e = 0; e < adj.edge_count(); ++e) {
        if (adj.face_count(e) != 2) continue;
        const uint32_t f = adj.face(e, 0), g = adj.face(e, 1);
        if (f >= tris.size() || g >= tris.size()) continue;
        const int kf = slot(f, adj.edges[e].x, adj.edges[e].y), kg = slot(g, adj.edges[e].x, adj.edges[e].y);
        if (kf < 0 || kg < 0) continue;
        out[f][kf] = g;
        out[g][kg] = f;
    }
    return out;
}

// The member of the cross {±d, ±(n × d)} closest to `ref`.
glm::dvec3 matched(const glm::dvec3& d, const glm::dvec3& n, const glm::dvec3& ref) {
    const glm::dvec3 c = glm::cross(n, d);
    const double a = glm::dot(d, ref), b = glm::dot(c, ref);
    if (std::abs(a) >= std::abs(b)) return a >= 0.0 ? d : -d;
    return b >= 0.0 ? c : -c;
}

glm::dvec3 unit_or_zero(const glm::dvec3& v) {
    const double len = glm::length(v);
    return len > 1e-300 && std::isfinite(len) ? v / len : glm::dvec3(0.0);
}

// Faces with three distinct in-range corners and a nonzero normal.
struct FaceFrames {
    std::vector<glm::dvec3> normal;  // zero for unusable faces
    explicit FaceFrames(const Mesh& mesh) : normal(mesh.triangles.size(), glm::dvec3(0.0)) {
        const size_t n = mesh.positions.size();
        for (size_t f = 0; f < mesh.triangles.size(); ++f) {
            const glm::uvec3 t = mesh.triangles[f];
            if (t.x >= n || t.y >= n || t.z >= n || t.x == t.y || t.y == t.z || t.z == t.x) continue;
            const glm::dvec3 a(mesh.positions[t.x]), b(mesh.positions[t.y]), c(mesh.positions[t.z]);
            normal[f] = unit_or_zero(glm::cross(b - a, c - a));
        }
    }
    bool usable(uint32_t f) const { return f < normal.size() && normal[f] != glm::dvec3(0.0); }
};

// A point on the surface: inside or on the boundary of `face`.
struct SurfacePoint {
    uint32_t face = kNone;
    glm::dvec3 p{0.0};
};

class Tracer {
public:
    Tracer(const Mesh& mesh, const std::vector<glm::vec3>& field, const EdgeAdjacency& adj)
        : mesh_(mesh), field_(field), frames_(mesh), nbr_(face_neighbours(mesh, adj)) {}

    const FaceFrames& frames() const { return frames_; }

    // The field's direction in face f closest to `ref` (in the face's plane), or zero.
    glm::dvec3 field_in(uint32_t f, const glm::dvec3& ref) const {
        const glm::uvec3 t = mesh_.triangles[f];
        const glm::dvec3 n = frames_.normal[f];
        glm::dvec3 sum(0.0);
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3 d(field_[t[k]]);
            if (d == glm::dvec3(0.0)) continue;
            // Each corner's cross, brought into the face's plane, then matched.
            const glm::dvec3 dp = unit_or_zero(d - glm::dot(d, n) * n);
            if (dp == glm::dvec3(0.0)) continue;
            sum += matched(dp, n, ref);
        }
        return unit_or_zero(sum - glm::dot(sum, n) * n);
    }

    // Where the ray p + s·d (in f's plane) leaves face f, not through edge `skip`: the edge's
    // index k and the parameter along it (from corner k to k + 1), and s. False if it does not.
    bool exit_of(uint32_t f, const glm::dvec3& p, const glm::dvec3& d, int skip, int& edge, double& along,
                 double& s) const {
        const glm::uvec3 t = mesh_.triangles[f];
        const glm::dvec3 n = frames_.normal[f];
        double best = HUGE_VAL;
        edge = -1;
        for (int k = 0; k < 3; ++k) {
            if (k == skip) continue;
            const glm::dvec3 a(mesh_.positions[t[k]]), b(mesh_.positions[t[(k + 1) % 3]]);
            // Solve p + s d = a + u (b − a) in the plane: 2×2 system via the normal.
            const glm::dvec3 e = b - a;
            const double den = glm::dot(glm::cross(d, e), n);
            if (!(std::abs(den) > 1e-300)) continue;
            const glm::dvec3 ap = a - p;
            const double si = glm::dot(glm::cross(ap, e), n) / den;
            const double ui = glm::dot(glm::cross(ap, d), n) / den;
            if (!(si > -1e-12) || ui < -1e-9 || ui > 1.0 + 1e-9) continue;
            if (si < best) best = si, edge = k, along = std::clamp(ui, 0.0, 1.0);
        }
        if (edge < 0) return false;
        s = std::max(best, 0.0);
        return true;
    }

    // Carries direction d from face f across its edge k into the neighbour g, unfolding the
    // two faces about the edge; the result points into g.
    glm::dvec3 unfold(uint32_t f, int k, uint32_t g, const glm::dvec3& d) const {
        const glm::uvec3 t = mesh_.triangles[f];
        const glm::dvec3 a(mesh_.positions[t[k]]), b(mesh_.positions[t[(k + 1) % 3]]);
        const glm::dvec3 e = unit_or_zero(b - a);
        const glm::dvec3 mf = glm::cross(frames_.normal[f], e), mg0 = glm::cross(frames_.normal[g], e);
        // mg must point into g: away from the edge towards g's far corner.
        const glm::uvec3 tg = mesh_.triangles[g];
        glm::dvec3 far(0.0);
        for (int j = 0; j < 3; ++j)
            if (tg[j] != t[k] && tg[j] != t[(k + 1) % 3]) far = glm::dvec3(mesh_.positions[tg[j]]);
        const glm::dvec3 mg = glm::dot(far - a, mg0) >= 0.0 ? mg0 : -mg0;
        // d leaves f, so its part across the edge goes into g.
        return unit_or_zero(glm::dot(d, e) * e + std::abs(glm::dot(d, mf)) * mg);
    }

    // Walks `distance` along the surface from `from` in direction d (straight across each
    // face, unfolded over edges). Nothing when a border or an unusable face comes first.
    bool walk(SurfacePoint from, glm::dvec3 d, double distance, SurfacePoint& to) const {
        int skip = -1;
        for (int steps = 0; steps < 4096; ++steps) {
            int k;
            double along = 0.0, s = 0.0;
            if (!exit_of(from.face, from.p, d, skip, k, along, s)) return false;
            if (s >= distance) {
                to = {from.face, from.p + d * distance};
                return true;
            }
            distance -= s;
            const uint32_t g = nbr_[from.face][k];
            if (g == kNone || !frames_.usable(g)) return false;
            const glm::uvec3 t = mesh_.triangles[from.face];
            const glm::dvec3 a(mesh_.positions[t[k]]), b(mesh_.positions[t[(k + 1) % 3]]);
            d = unfold(from.face, k, g, d);
            if (d == glm::dvec3(0.0)) return false;
            skip = edge_index(g, t[k], t[(k + 1) % 3]);
            from = {g, a + along * (b - a)};
        }
        return false;
    }

    int edge_index(uint32_t f, uint32_t u, uint32_t v) const {
        const glm::uvec3 t = mesh_.triangles[f];
        for (int k = 0; k < 3; ++k)
            if ((t[k] == u && t[(k + 1) % 3] == v) || (t[k] == v && t[(k + 1) % 3] == u)) return k;
        return -1;
    }

    struct Node {
        glm::dvec3 p;
        uint32_t u, v;  // the edge's corners, as in the face
        double along;   // from u to v
        uint32_t face;  // the face the piece ending here crossed
    };

    // Traces from `seed` (direction `d`, in the field) until a border, an unusable face, a
    // sharp turn of the field, a face this stroke crossed already, or a point nearer than
    // `stop` to `grid`'s points. Returns the nodes (edge points) in order; `looped` when the
    // trace came back into the seed's face. `visit` holds per face the stamp of the last trace
    // that crossed it (the caller's own, so that traces may run on several threads).
    std::vector<Node> trace(const SurfacePoint& seed, glm::dvec3 d, const PointGrid& grid, double stop, uint32_t stamp,
                            uint32_t seed_stamp, std::vector<uint32_t>& visit_, bool& looped) const {
        std::vector<Node> nodes;
        looped = false;
        SurfacePoint at = seed;
        int skip = -1;
        for (int steps = 0; steps < 1 << 20; ++steps) {
            int k;
            double along = 0.0, s = 0.0;
            if (!exit_of(at.face, at.p, d, skip, k, along, s)) break;
            const glm::uvec3 t = mesh_.triangles[at.face];
            const glm::dvec3 a(mesh_.positions[t[k]]), b(mesh_.positions[t[(k + 1) % 3]]);
            const glm::dvec3 q = a + along * (b - a);
            if (grid.any_within(q, stop)) break;
            nodes.push_back({q, t[k], t[(k + 1) % 3], along, at.face});
            const uint32_t g = nbr_[at.face][k];
            if (g == kNone || !frames_.usable(g)) break;
            if (visit_[g] == seed_stamp) {
                looped = true;
                break;
            }
            if (visit_[g] == stamp) break;
            visit_[g] = stamp;
            const glm::dvec3 carried = unfold(at.face, k, g, d);
            const glm::dvec3 next = field_in(g, carried);
            // A turn sharper than 45° is a singularity of the field: the stroke ends there.
            if (next == glm::dvec3(0.0) || glm::dot(next, carried) < 0.7071) break;
            d = next;
            skip = edge_index(g, t[k], t[(k + 1) % 3]);
            at = {g, q};
        }
        return nodes;
    }

private:
    const Mesh& mesh_;
    const std::vector<glm::vec3>& field_;
    FaceFrames frames_;
    std::vector<glm::uvec3> nbr_;
};

// f(v) for every vertex, in parallel (each v writes only its own entries).
template <class F>
void parallel_vertices(size_t n, const F& f) {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 4096), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t v = r.begin(); v != r.end(); ++v) f(v);
    });
}

// |(x, y)| as glibc's hypotf computes it for finite values (squares summed in double, one
// square root), inline: the library call was a tenth of the hatching setup.
float hypot_float(float x, float y) { return float(std::sqrt(double(x) * double(x) + double(y) * double(y))); }

double bounding_diagonal(const Mesh& mesh) {
    if (mesh.positions.empty()) return 0.0;
    glm::dvec3 lo(HUGE_VAL), hi(-HUGE_VAL);
    for (const glm::vec3& p : mesh.positions)
        if (is_finite(p)) lo = glm::min(lo, glm::dvec3(p)), hi = glm::max(hi, glm::dvec3(p));
    return hi.x >= lo.x ? glm::length(hi - lo) : 0.0;
}

}  // namespace

std::vector<glm::vec3> hatch_direction_field(const Mesh& mesh, const std::vector<glm::vec3>& normals,
                                             const Curvature& c, int iterations) {
    const size_t n = mesh.positions.size();
    if (normals.size() != n || c.pdir1.size() != n || c.pdir2.size() != n || c.k1.size() != n || c.k2.size() != n)
        throw std::invalid_argument("hatch_direction_field: need normals and curvature per vertex");
    // Each vertex's frame: e1 the principal direction of larger |k| in its tangent plane,
    // e2 = n × e1. A cross at angle θ from e1 is the unit complex number z = e^{4iθ} (a cross
    // looks the same turned by 90°: Hertzmann & Zorin 2000 §4.1, Ray et al. 2008's N-RoSy), so
    // crosses average as complex numbers; each starts at z = 1, its own principal direction.
    std::vector<glm::vec3> e1(n, glm::vec3(0.0f)), e2(n, glm::vec3(0.0f));
    std::vector<float> weight(n, 0.0f);
    parallel_vertices(n, [&](size_t v) {
        const glm::dvec3 nv = unit_or_zero(glm::dvec3(normals[v]));
        const double k1 = c.k1[v], k2 = c.k2[v];
        const glm::dvec3 d = std::abs(k1) >= std::abs(k2) ? glm::dvec3(c.pdir1[v]) : glm::dvec3(c.pdir2[v]);
        const glm::dvec3 t = unit_or_zero(d - glm::dot(d, nv) * nv);
        e1[v] = glm::vec3(t);
        e2[v] = glm::vec3(glm::cross(nv, t));
        const double sum = std::abs(k1) + std::abs(k2);
        // Anisotropy: strongly curved, non-umbilic vertices keep their direction; a floor lets
        // umbilic regions (all weights near 0) still average.
        weight[v] = float((std::isfinite(sum) && sum > 0.0 ? std::abs(k1 - k2) / sum : 0.0) + 1e-3);
    });
    // Each vertex's distinct neighbours through its faces, with the turn of a neighbour's frame
    // into the vertex's (its e1 laid into the vertex's tangent plane), as e^{4iφ}.
    const auto& tris = mesh.triangles;
    std::vector<uint32_t> first(n + 1, 0), around;
    for (const glm::uvec3& t : tris)
        if (t.x < n && t.y < n && t.z < n)
            for (int k = 0; k < 3; ++k) first[t[k] + 1] += 2;
    for (size_t v = 0; v < n; ++v) first[v + 1] += first[v];
    around.resize(first[n]);
    {
        std::vector<uint32_t> fill(first.begin(), first.end() - 1);
        for (const glm::uvec3& t : tris)
            if (t.x < n && t.y < n && t.z < n)
                for (int k = 0; k < 3; ++k)
                    for (int j = 1; j < 3; ++j) around[fill[t[k]]++] = t[(k + j) % 3];
    }
    std::vector<std::complex<float>> turn(around.size(), 0.0f);
    std::vector<uint32_t> count(n, 0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 4096), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t v = r.begin(); v != r.end(); ++v) {
            uint32_t* begin = around.data() + first[v];
            uint32_t* end = around.data() + first[v + 1];
            std::sort(begin, end);
            end = std::unique(begin, end);
            count[v] = uint32_t(end - begin);
            if (e1[v] == glm::vec3(0.0f)) continue;
            for (uint32_t a = first[v]; a < first[v] + count[v]; ++a) {
                const uint32_t u = around[a];
                if (e1[u] == glm::vec3(0.0f)) continue;
                const float x = glm::dot(e1[u], e1[v]), y = glm::dot(e1[u], e2[v]);
                const float len = hypot_float(x, y);
                if (!(len > 1e-6f)) continue;
                const std::complex<float> once(x / len, y / len);
                // Weighted here once (the product is the same float either way: the weight
                // multiplied the turn first in the rounds as well).
                turn[a] = weight[u] * ((once * once) * (once * once));
            }
        }
    });
    std::vector<std::complex<float>> z(n, 1.0f), next(n);
    for (size_t v = 0; v < n; ++v)
        if (e1[v] == glm::vec3(0.0f)) z[v] = 0.0f;
    // Jacobi rounds (every vertex from the previous round's crosses), so the result does not
    // depend on how the vertices are split between threads.
    for (int it = 0; it < iterations; ++it) {
        tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 4096), [&](const tbb::blocked_range<size_t>& r) {
            for (size_t v = r.begin(); v != r.end(); ++v) {
                next[v] = z[v];
                if (z[v] == 0.0f) continue;
                std::complex<float> sum = weight[v] * z[v];
                for (uint32_t a = first[v]; a < first[v] + count[v]; ++a) sum += turn[a] * z[around[a]];
                const float len = hypot_float(sum.real(), sum.imag());
                if (len > 1e-12f && std::isfinite(len)) next[v] = sum / len;
            }
        });
        std::swap(z, next);
    }
    std::vector<glm::vec3> out(n, glm::vec3(0.0f));
    parallel_vertices(n, [&](size_t v) {
        if (z[v] == 0.0f) return;
        const float theta = 0.25f * std::arg(z[v]);
        out[v] = std::cos(theta) * e1[v] + std::sin(theta) * e2[v];
    });
    return out;
}

Hatching trace_hatching(const Mesh& mesh, const std::vector<glm::vec3>& normals, const Curvature& curvature,
                        const EdgeAdjacency& adjacency, const HatchOptions& options) {
    Hatching out;
    const double diagonal = bounding_diagonal(mesh);
    const double spacing =
        options.spacing > 0.0f && std::isfinite(options.spacing)
            ? double(options.spacing)
            : 0.015 * diagonal /
                  std::clamp(std::isfinite(options.density) ? double(options.density) : 1.0, 0.01, 100.0);
    out.spacing = float(spacing);
    if (!(spacing > 0.0) || mesh.triangles.empty()) return out;
    const int levels = std::clamp(options.levels, 1, 4);
    const auto& tris = mesh.triangles;
    // The cross field beside the faces' frames and the free seeds, which do not read it: the
    // seeds' serial random draws run while the field's rounds take the other threads.
    std::vector<glm::vec3> field;
    std::optional<Tracer> tracer_slot;
    std::vector<SurfacePoint> free_seeds;
    auto make_field = [&] { field = hatch_direction_field(mesh, normals, curvature, options.smoothing); };
    auto make_seeds = [&] {
        tracer_slot.emplace(mesh, field, adjacency);  // keeps a reference to `field`, read later
        const FaceFrames& frames = tracer_slot->frames();
        // Free seeds: random points of the faces, about one per (finest spacing)² of area, in
        // an order fixed by the seed.
        std::mt19937_64 rng(options.seed);
        const double finest = spacing / double(1 << (levels - 1));
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        for (uint32_t f = 0; f < tris.size(); ++f) {
            if (!frames.usable(f)) continue;
            const glm::dvec3 a(mesh.positions[tris[f].x]), b(mesh.positions[tris[f].y]), c(mesh.positions[tris[f].z]);
            const double area = 0.5 * glm::length(glm::cross(b - a, c - a));
            const double expected = area / (finest * finest);
            int count = int(expected);
            if (unit(rng) < expected - count) ++count;
            for (int i = 0; i < count; ++i) {
                double r1 = unit(rng), r2 = unit(rng);
                if (r1 + r2 > 1.0) r1 = 1.0 - r1, r2 = 1.0 - r2;
                free_seeds.push_back({f, a + r1 * (b - a) + r2 * (c - a)});
            }
        }
        std::shuffle(free_seeds.begin(), free_seeds.end(), rng);
    };
    tbb::parallel_invoke(make_field, make_seeds);
    const Tracer& tracer = *tracer_slot;
    const FaceFrames& frames = tracer.frames();

    // The two families never meet (each keeps its spacing only against its own strokes), so
    // each is traced on its own thread with its own visit stamps, and family 0's strokes come
    // first whatever the thread count.
    auto trace_family = [&](const int family) {
        std::vector<HatchStroke> strokes;
        std::vector<uint32_t> visit(tris.size(), kNone);  // per face: the last trace that crossed it
        uint32_t stamp = 0;
        for (int level = 0; level < levels; ++level) {
            const double d_sep = spacing / double(1 << level);
            const double d_test = 0.5 * d_sep;
            // The obstacles: this family's strokes so far (every coarser level).
            PointGrid grid(d_sep);
            auto add_stroke = [&](const HatchStroke& s) {
                const size_t m = s.points.size();
                for (size_t i = 0; i + 1 < m + (s.closed ? 1 : 0); ++i)
                    grid.add_segment(glm::dvec3(s.points[i]), glm::dvec3(s.points[(i + 1) % m]), d_test * 0.5, i == 0);
            };
            for (const HatchStroke& s : strokes) add_stroke(s);

            auto try_seed = [&](const SurfacePoint& seed) -> bool {
                if (!frames.usable(seed.face) || grid.any_within(seed.p, d_sep * 0.9)) return false;
                // The family's direction at the seed: the field (larger |k|) or across it.
                const glm::uvec3 t = tris[seed.face];
                glm::dvec3 ref(field[t.x]);
                const glm::dvec3 n = frames.normal[seed.face];
                ref = unit_or_zero(ref - glm::dot(ref, n) * n);
                if (ref == glm::dvec3(0.0)) return false;
                if (family == 1) ref = glm::cross(n, ref);
                const glm::dvec3 d = tracer.field_in(seed.face, ref);
                if (d == glm::dvec3(0.0)) return false;
                const uint32_t seed_stamp = ++stamp;
                visit[seed.face] = seed_stamp;
                bool looped = false, back_looped = false;
                const uint32_t trace_stamp = ++stamp;  // both halves: neither re-enters a face of the other
                const std::vector<Tracer::Node> fwd =
                    tracer.trace(seed, d, grid, d_test, trace_stamp, seed_stamp, visit, looped);
                const std::vector<Tracer::Node> back =
                    looped ? std::vector<Tracer::Node>{}
                           : tracer.trace(seed, -d, grid, d_test, trace_stamp, seed_stamp, visit, back_looped);
                HatchStroke s;
                s.family = uint8_t(family);
                s.level = uint8_t(level);
                auto push = [&](const Tracer::Node& node) {
                    s.points.push_back(glm::vec3(node.p));
                    s.edges.push_back(edge_key(node.u, node.v));
                    s.t.push_back(float(node.u < node.v ? node.along : 1.0 - node.along));
                };
                for (size_t i = back.size(); i-- > 0;) push(back[i]);
                for (const auto& node : fwd) push(node);
                // A node's face is the one its trace crossed to reach it: the piece before it
                // on the forward half, after it on the (reversed) backward half.
                for (size_t i = back.size(); i-- > 1;) s.faces.push_back(back[i].face);
                if (!back.empty() && !fwd.empty()) s.faces.push_back(seed.face);
                for (size_t i = 1; i < fwd.size(); ++i) s.faces.push_back(fwd[i].face);
                if (looped && fwd.size() >= 3) {
                    s.closed = true;
                    s.faces.push_back(seed.face);  // the last node back to the first, across the seed's face
                }
                if (s.points.size() < 2) return false;
                double length = 0.0;
                for (size_t i = 0; i + 1 < s.points.size(); ++i)
                    length += glm::length(glm::dvec3(s.points[i + 1]) - glm::dvec3(s.points[i]));
                if (length < d_sep) return false;  // a stub between two strokes
                add_stroke(s);
                strokes.push_back(std::move(s));
                return true;
            };

            // Seeds beside every stroke of the family, d_sep to either side (Jobard & Lefer),
            // the new ones included as they come; free seeds where none reached.
            size_t next_stroke = 0;
            size_t next_free = 0;
            for (;;) {
                if (next_stroke < strokes.size()) {
                    const HatchStroke s = strokes[next_stroke++];  // a copy: try_seed appends
                    const size_t pieces = s.faces.size();
                    double start = 0.0, next_at = 0.5 * d_sep;
                    for (size_t i = 0; i < pieces; ++i) {
                        const glm::dvec3 a(s.points[i]), b(s.points[(i + 1) % s.points.size()]);
                        const double len = glm::length(b - a);
                        if (len > 0.0 && frames.usable(s.faces[i])) {
                            const glm::dvec3 t = (b - a) / len, n = frames.normal[s.faces[i]];
                            for (; next_at < start + len; next_at += d_sep) {
                                const SurfacePoint from{s.faces[i], a + t * (next_at - start)};
                                for (const double side : {1.0, -1.0}) {
                                    SurfacePoint seed;
                                    if (tracer.walk(from, glm::cross(n, t) * side, d_sep, seed)) try_seed(seed);
                                }
                            }
                        }
                        start += len;
                    }
                    continue;
                }
                bool found = false;
                while (next_free < free_seeds.size() && !found) found = try_seed(free_seeds[next_free++]);
                if (!found) break;
            }
        }
        return strokes;
    };
    if (options.cross) {
        std::vector<HatchStroke> across;
        tbb::parallel_invoke([&] { out.strokes = trace_family(0); }, [&] { across = trace_family(1); });
        out.strokes.insert(out.strokes.end(), std::make_move_iterator(across.begin()),
                           std::make_move_iterator(across.end()));
    } else {
        out.strokes = trace_family(0);
    }
    return out;
}

std::vector<LineSegment> hatch_segments(const Mesh& mesh, const std::vector<glm::vec3>& normals,
                                        const Hatching& hatching, const Camera& camera, const HatchView& view) {
    std::vector<LineSegment> out;
    const ViewVector to_eye(camera);
    const size_t nv = mesh.positions.size();
    const glm::dvec3 light = unit_or_zero(glm::dvec3(view.light));
    const int levels = hatching.strokes.empty() ? 1
                                                : 1 + std::max_element(hatching.strokes.begin(), hatching.strokes.end(),
                                                                       [](const HatchStroke& a, const HatchStroke& b) {
        return a.level < b.level;
                                                      })->level;
    const double fade = std::max(double(view.fade), 1e-6);
    uint32_t node_id = 0;
    for (const HatchStroke& s : hatching.strokes) {
        const size_t m = s.points.size();
        const size_t index = size_t(s.family) * size_t(levels) + s.level;
        if (uint64_t(node_id) + m > kMaxHatchNodes) break;  // keys run out (never at real sizes)
        const uint32_t first_id = node_id;
        node_id += uint32_t(m);
        if (index >= view.thresholds.size() || m < 2) continue;
        const double threshold = view.thresholds[index];
        // Tone and facing at each node, from the interpolated vertex normal.
        std::vector<double> strength(m, 0.0);
        std::vector<bool> front(m, false);
        for (size_t i = 0; i < m; ++i) {
            const uint32_t lo = uint32_t(s.edges[i] >> 32), hi = uint32_t(s.edges[i]);
            if (lo >= nv || hi >= nv || lo >= normals.size() || hi >= normals.size()) continue;
            const glm::dvec3 n =
                unit_or_zero(glm::dvec3(normals[lo]) * (1.0 - s.t[i]) + glm::dvec3(normals[hi]) * double(s.t[i]));
            const double tone = std::clamp(glm::dot(n, light), 0.0, 1.0);
            strength[i] = std::clamp((threshold - tone) / fade, 0.0, 1.0);
            const double facing = glm::dot(n, to_eye.at(s.points[i]));
            front[i] = facing > 0.0;
            // Where the surface turns away, its strokes crowd in the image (their spacing on
            // screen shrinks by about n·v): a finer level fades out below n·v = thin·2^(k−1),
            // so towards the outline only the coarsest strokes are left.
            if (s.level > 0 && view.thin > 0.0) {
                const double at = view.thin * double(1 << (s.level - 1));
                strength[i] *= std::clamp((facing - at) / (0.5 * at), 0.0, 1.0);
            }
        }
        const size_t pieces = s.closed ? m : m - 1;
        for (size_t i = 0; i < pieces; ++i) {
            const size_t j = (i + 1) % m;
            if (strength[i] <= 0.0 && strength[j] <= 0.0) continue;
            if (!front[i] && !front[j]) continue;
            LineSegment seg;
            seg.a = s.points[i];
            seg.b = s.points[j];
            seg.edge_a = hatch_node_key(first_id + uint32_t(i));
            seg.edge_b = hatch_node_key(first_id + uint32_t(j));
            seg.face = s.faces[i];
            seg.strength_a = float(strength[i]);
            seg.strength_b = float(strength[j]);
            out.push_back(seg);
        }
    }
    return out;
}

}  // namespace inkshade::geometry
