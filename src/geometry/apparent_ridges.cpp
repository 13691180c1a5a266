// Apparent ridges: per vertex q1 and t1 from the curvature tensor (parallel), D_t1 q1 from the
// one-ring (each face's three corners in parallel, summed per vertex in face order), then one
// pass over faces (TBB blocks joined in order).
#include "geometry/apparent_ridges.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>

#include "geometry/face_segments.hpp"
#include "geometry/feature_size.hpp"

namespace inkshade::geometry {
namespace {

constexpr size_t kGrain = 16384;       // vertices per TBB task, as in contours.cpp
constexpr double kMinCosTheta = 1e-4;  // |n·v| floor: q1 ~ 1/|n·v| stays finite on the contour

void check_sizes(const Mesh& mesh, const std::vector<glm::vec3>& normals, const Curvature& c) {
    const size_t n = mesh.positions.size();
    if (normals.size() != n || c.k1.size() != n || c.k2.size() != n || c.pdir1.size() != n || c.pdir2.size() != n)
        throw std::invalid_argument("apparent ridges: need normals and curvature per vertex");
}

struct VertexQ {
    double q1 = 0.0;
    glm::dvec3 t1{0.0}, screen{0.0};
};

// q1 and t1 at one vertex. In the frame (pdir1, pdir2) S = diag(k1, k2) and, with ŵ the unit
// projected view vector, P⁻¹ = I + (1/cos θ − 1) ŵŵᵀ (the image plane identified with the tangent
// plane by the rotation about ŵ⊥, under which P stretches nothing across ŵ). q1² is the largest
// eigenvalue of QᵀQ, t1 (image) its eigenvector; the tangent direction that projects onto it is
// P⁻¹ t1.
VertexQ vertex_q(const glm::dvec3& v, const glm::dvec3& n, const glm::dvec3& e1, const glm::dvec3& e2, double k1,
                 double k2) {
    const double u = glm::dot(v, e1), s = glm::dot(v, e2), sin2 = u * u + s * s;
    const double cos_theta = std::max(std::abs(glm::dot(v, n)), kMinCosTheta);
    double wu = 1.0, ws = 0.0, m = 0.0;  // ŵ and 1/cos θ − 1 (0: view along the normal, P = I)
    if (sin2 > 1e-20) {
        const double len = std::sqrt(sin2);
        wu = u / len;
        ws = s / len;
        m = 1.0 / cos_theta - 1.0;
    }
    const double q11 = k1 * (1.0 + m * wu * wu), q12 = k1 * m * wu * ws;
    const double q21 = k2 * m * wu * ws, q22 = k2 * (1.0 + m * ws * ws);
    const double a = q11 * q11 + q21 * q21, b = q11 * q12 + q21 * q22, c = q12 * q12 + q22 * q22;
    const double lambda = 0.5 * (a + c) + std::sqrt(0.25 * (a - c) * (a - c) + b * b);
    // The better conditioned of the two forms of the eigenvector; (1, 0) where QᵀQ is isotropic.
    glm::dvec2 t(b, lambda - a);
    const glm::dvec2 t_other(lambda - c, b);
    if (glm::dot(t_other, t_other) > glm::dot(t, t)) t = t_other;
    const double tl = glm::length(t);
    t = tl > 1e-12 * (lambda + 1e-300) ? t / tl : glm::dvec2(1.0, 0.0);
    // P⁻¹ t: the component along ŵ stretched by 1/cos θ.
    const double along = t.x * wu + t.y * ws;
    const glm::dvec2 T = t + m * along * glm::dvec2(wu, ws);
    VertexQ out;
    out.q1 = std::sqrt(std::max(lambda, 0.0));
    out.t1 = glm::normalize(T.x * e1 + T.y * e2);
    const glm::dvec3 screen = out.t1 - glm::dot(out.t1, v) * v;
    const double sl = glm::length(screen);
    out.screen = sl > 0.0 ? screen / sl : glm::dvec3(0.0);
    return out;
}

bool finite(const glm::dvec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

}  // namespace

ViewDependentCurvature view_dependent_curvature(const Mesh& mesh, const std::vector<glm::vec3>& normals,
                                                const Curvature& curvature, const Camera& camera) {
    check_sizes(mesh, normals, curvature);
    const ViewVector view(camera);
    const size_t n = mesh.positions.size();
    ViewDependentCurvature out;
    out.q1.assign(n, 0.0f);
    out.t1.assign(n, glm::vec3(0.0f));
    out.screen_t1.assign(n, glm::vec3(0.0f));
    out.dt1_q1.assign(n, 0.0f);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, kGrain), [&](const auto& range) {
        for (size_t i = range.begin(); i != range.end(); ++i) {
            const VertexQ q =
                vertex_q(view.at(mesh.positions[i]), glm::dvec3(normals[i]), glm::dvec3(curvature.pdir1[i]),
                         glm::dvec3(curvature.pdir2[i]), double(curvature.k1[i]), double(curvature.k2[i]));
            if (!std::isfinite(q.q1) || !finite(q.t1) || !finite(q.screen)) continue;  // no line here
            out.q1[i] = float(q.q1);
            out.t1[i] = glm::vec3(q.t1);
            out.screen_t1[i] = glm::vec3(q.screen);
        }
    });

    // Per face corner: where the line through the corner's vertex along its t1 leaves the face
    // through the opposite edge, (q1 there − q1 here) / image-plane distance.
    const auto& tris = mesh.triangles;
    struct Estimate {
        float value = 0.0f;
        bool valid = false;
    };
    std::vector<std::array<Estimate, 3>> corner(tris.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, tris.size(), kGrain), [&](const auto& range) {
        for (size_t f = range.begin(); f != range.end(); ++f) {
            const glm::uvec3 t = tris[f];
            if (t.x >= n || t.y >= n || t.z >= n || t.x == t.y || t.y == t.z || t.z == t.x) continue;
            for (int k = 0; k < 3; ++k) {
                const uint32_t i = t[k], j = t[(k + 1) % 3], l = t[(k + 2) % 3];
                const glm::dvec3 pi(mesh.positions[i]), pj(mesh.positions[j]), pl(mesh.positions[l]);
                const glm::dvec3 across = glm::cross(glm::dvec3(normals[i]), glm::dvec3(out.t1[i]));
                const double aj = glm::dot(pj - pi, across), al = glm::dot(pl - pi, across);
                if (!(aj != al) || (aj > 0.0) == (al > 0.0)) continue;  // the line misses the edge
                const double w = al / (al - aj);                        // weight of j
                const glm::dvec3 p = w * pj + (1.0 - w) * pl;
                const double q = w * double(out.q1[j]) + (1.0 - w) * double(out.q1[l]);
                const double dist = glm::dot(p - pi, glm::dvec3(out.screen_t1[i]));
                if (!(std::abs(dist) > 0.0)) continue;
                const double d = (q - double(out.q1[i])) / dist;
                if (std::isfinite(d)) corner[f][size_t(k)] = {float(d), true};
            }
        }
    });
    std::vector<double> sum(n, 0.0);
    std::vector<uint32_t> count(n, 0);
    for (size_t f = 0; f < tris.size(); ++f)
        for (int k = 0; k < 3; ++k)
            if (corner[f][size_t(k)].valid) {
                sum[tris[f][k]] += corner[f][size_t(k)].value;
                ++count[tris[f][k]];
            }
    for (size_t i = 0; i < n; ++i)
        if (count[i] > 0) out.dt1_q1[i] = float(sum[i] / count[i]);
    return out;
}

std::vector<LineSegment> extract_apparent_ridges(const Mesh& mesh, const std::vector<glm::vec3>& normals,
                                                 const Curvature& curvature, const Camera& camera,
                                                 const ApparentRidgeOptions& options) {
    check_sizes(mesh, normals, curvature);
    const double size =
        options.feature_size > 0.0f ? double(options.feature_size) : double(line_feature_size(mesh, curvature));
    const double threshold = double(options.threshold) / (size * size);  // on q1²
    const ViewDependentCurvature vdc = view_dependent_curvature(mesh, normals, curvature, camera);
    const size_t n = mesh.positions.size();

    // The field pointing up the slope of q1; its sign does not depend on the sign of t1.
    auto uphill = [&](uint32_t i) { return double(vdc.dt1_q1[i]) * glm::dvec3(vdc.t1[i]); };
    auto q1_squared = [&](uint32_t i) { return double(vdc.q1[i]) * double(vdc.q1[i]); };
    struct EdgePoint {
        glm::vec3 p{0.0f};
        double q2 = 0.0;  // q1² interpolated
    };
    // The crossing on edge (i, j), from the edge alone (ordered by index).
    auto crossing = [&](uint32_t i, uint32_t j) -> std::optional<EdgePoint> {
        if (j < i) std::swap(i, j);
        const double ei = std::abs(double(vdc.dt1_q1[i])), ej = std::abs(double(vdc.dt1_q1[j]));
        if (!(ei + ej > 0.0) || glm::dot(uphill(i), uphill(j)) > 0.0) return std::nullopt;
        const double t = ei / (ei + ej);
        const glm::dvec3 pi(mesh.positions[i]), pj(mesh.positions[j]);
        EdgePoint e;
        e.p = glm::vec3(pi + t * (pj - pi));
        e.q2 = q1_squared(i) + t * (q1_squared(j) - q1_squared(i));
        return e;
    };
    auto strength = [&](double q2) {
        if (!(threshold > 0.0)) return 1.0f;
        const double s = 1.0 - threshold / q2;  // rtsc: k / (k + thresh), k = q2 − thresh
        return std::isfinite(s) ? float(std::clamp(s, 0.0, 1.0)) : 0.0f;
    };

    return collect_face_segments(mesh.triangles.size(), [&](size_t f, std::vector<LineSegment>& out) {
        const glm::uvec3 t = mesh.triangles[f];
        if (t.x >= n || t.y >= n || t.z >= n || t.x == t.y || t.y == t.z || t.z == t.x) return;
        if (q1_squared(t.x) <= threshold && q1_squared(t.y) <= threshold && q1_squared(t.z) <= threshold) return;
        EdgePoint e[3];
        uint64_t key[3];
        int count = 0;
        for (int s = 0; s < 3; ++s)
            if (const auto c = crossing(t[s], t[(s + 1) % 3])) {
                if (count == 2) return;  // three crossings: the field turns inside the face
                e[count] = *c;
                key[count++] = edge_key(t[s], t[(s + 1) % 3]);
            }
        if (count != 2 || e[0].p == e[1].p) return;  // none, or both at a corner where D_t1 q1 = 0

        // A maximum: at every corner the uphill field points towards the segment's line.
        const glm::dvec3 a(e[0].p), b(e[1].p);
        const glm::dvec3 p0(mesh.positions[t.x]), p1(mesh.positions[t.y]), p2(mesh.positions[t.z]);
        const glm::dvec3 perp = glm::cross(glm::cross(p1 - p0, p2 - p0), b - a);
        for (int k = 0; k < 3; ++k) {
            const double side = glm::dot(glm::dvec3(mesh.positions[t[k]]) - a, perp);
            if (side == 0.0) continue;
            if (!(glm::dot(uphill(t[k]), perp) * side < 0.0)) return;
        }

        // The part of a → b where q1² (linear along it) is above the threshold.
        const double h0 = e[0].q2 - threshold, h1 = e[1].q2 - threshold;
        double lo = 0.0, hi = 1.0;
        if (!(h0 > 0.0) && !(h1 > 0.0)) return;
        if (!(h0 > 0.0)) lo = h0 / (h0 - h1);
        if (!(h1 > 0.0)) hi = h0 / (h0 - h1);
        if (!(lo < hi)) return;
        auto at = [&](double s) { return glm::vec3(a + s * (b - a)); };
        LineSegment seg;
        seg.face = uint32_t(f);
        seg.a = lo > 0.0 ? at(lo) : e[0].p;
        seg.b = hi < 1.0 ? at(hi) : e[1].p;
        seg.edge_a = lo > 0.0 ? face_interior_key(uint32_t(f), 0) : key[0];
        seg.edge_b = hi < 1.0 ? face_interior_key(uint32_t(f), 1) : key[1];
        seg.strength_a = lo > 0.0 ? 0.0f : strength(e[0].q2);
        seg.strength_b = hi < 1.0 ? 0.0f : strength(e[1].q2);
        out.push_back(seg);
    });
}

}  // namespace inkshade::geometry
