// Suggestive contours: per-vertex κr sin²θ, D_w κr and n·v for the view, then one pass over
// faces in fixed-size blocks (TBB), each block writing its own list, joined in block order.
#include "geometry/suggestive_contours.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "geometry/face_segments.hpp"

namespace inkshade::geometry {
namespace {

constexpr size_t kGrain = 16384;  // faces (or vertices) per TBB task, as in contours.cpp

// Per-vertex values of one view; all zero where an input is not finite.
struct ViewCurvature {
    float kr = 0.0f, dwkr = 0.0f, ndotv = 0.0f;
};

ViewCurvature view_curvature(const glm::vec3& normal, const glm::dvec3& v, const Curvature& c, size_t i) {
    const double u = glm::dot(v, glm::dvec3(c.pdir1[i]));  // |w| cos φ
    const double s = glm::dot(v, glm::dvec3(c.pdir2[i]));  // |w| sin φ
    const double u2 = u * u, s2 = s * s, sin2 = u2 + s2;
    const double k1 = c.k1[i], k2 = c.k2[i];
    const glm::dvec4 C(c.dcurv[i]);
    ViewCurvature out;
    const double ndotv = glm::dot(glm::dvec3(normal), v);
    const double krs = k1 * u2 + k2 * s2;  // κr sin²θ
    double kr = 0.0, dwkr = 0.0;
    if (sin2 > 1e-12) {
        kr = krs / sin2;
        // C(w,w,w)/|w|² = |w| C(ŵ,ŵ,ŵ), the cubic form of the derivative tensor (Rusinkiewicz
        // 2004; rtsc's sctest_num), then the term from the turning of w along itself (DeCarlo
        // 2004): −2 (n·v) τr², τr = (k2 − k1) cos φ sin φ.
        const double cubic = (u2 * (u * C.x + 3.0 * s * C.y) + s2 * (3.0 * u * C.z + s * C.w)) / sin2;
        const double tau = (k2 - k1) * u * s / sin2;
        dwkr = cubic - 2.0 * ndotv * tau * tau;
    }
    if (!std::isfinite(krs) || !std::isfinite(kr) || !std::isfinite(dwkr) || !std::isfinite(ndotv))
        return {};  // a NaN normal or curvature: no line through this vertex
    out.kr = float(kr);
    out.dwkr = float(dwkr);
    out.ndotv = float(ndotv);
    return out;
}

void check_sizes(const Mesh& mesh, const std::vector<glm::vec3>& normals, const Curvature& c) {
    const size_t n = mesh.positions.size();
    if (normals.size() != n || c.k1.size() != n || c.k2.size() != n || c.pdir1.size() != n || c.pdir2.size() != n ||
        c.dcurv.size() != n)
        throw std::invalid_argument("suggestive contours: need normals and curvature per vertex");
}

// A point on the line with the trim test's numerator (D_w κr − threshold·n·v) and denominator
// (n·v) there; the point passes where both are positive (rtsc's sctest_num / sctest_den).
struct TestPoint {
    glm::vec3 p{0.0f};
    double num = 0.0, den = 0.0;
};

// rtsc's fade: num / (den·fade + num), the strength rising from 0 at the trim point.
float strength(double num, double den, double fade) {
    if (fade <= 0.0) return 1.0f;
    const double s = num / (den * fade + num);
    return std::isfinite(s) ? float(std::clamp(s, 0.0, 1.0)) : 0.0f;
}

}  // namespace

RadialCurvature radial_curvature(const Mesh& mesh, const std::vector<glm::vec3>& normals, const Curvature& curvature,
                                 const Camera& camera) {
    check_sizes(mesh, normals, curvature);
    const ViewVector view(camera);
    const size_t n = mesh.positions.size();
    RadialCurvature out;
    out.kr.resize(n);
    out.dw_kr.resize(n);
    out.ndotv.resize(n);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, kGrain), [&](const auto& range) {
        for (size_t i = range.begin(); i != range.end(); ++i) {
            const ViewCurvature vc = view_curvature(normals[i], view.at(mesh.positions[i]), curvature, i);
            out.kr[i] = vc.kr;
            out.dw_kr[i] = vc.dwkr;
            out.ndotv[i] = vc.ndotv;
        }
    });
    return out;
}

std::vector<LineSegment> extract_suggestive_contours(const Mesh& mesh, const std::vector<glm::vec3>& normals,
                                                     const Curvature& curvature, const Camera& camera,
                                                     const SuggestiveOptions& options) {
    check_sizes(mesh, normals, curvature);
    const double size =
        options.feature_size > 0.0f ? double(options.feature_size) : double(line_feature_size(mesh, curvature));
    const double threshold = double(options.threshold) / (size * size);
    const double fade = double(options.fade) / (size * size);
    const ViewVector view(camera);
    const size_t n = mesh.positions.size();

    // Per vertex the isoline function κr sin²θ (rtsc's kr: κr's zeros, but finite where w → 0),
    // then the trim test (D_w κr and n·v, rtsc's sctest_num / sctest_den) only at the vertices
    // of faces the isoline crosses: on a scan that is a fraction of the vertices, each of which
    // the faces around it would otherwise evaluate up to a dozen times.
    std::vector<float> krs(n);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, kGrain), [&](const auto& range) {
        for (size_t i = range.begin(); i != range.end(); ++i) {
            const glm::dvec3 v = view.at(mesh.positions[i]);
            const double u = glm::dot(v, glm::dvec3(curvature.pdir1[i]));
            const double s = glm::dot(v, glm::dvec3(curvature.pdir2[i]));
            const double k = double(curvature.k1[i]) * u * u + double(curvature.k2[i]) * s * s;
            krs[i] = std::isfinite(k) ? float(k) : 0.0f;
        }
    });
    const auto& tris = mesh.triangles;
    auto crossed = [&](const glm::uvec3& t) {
        if (t.x >= n || t.y >= n || t.z >= n) return false;
        const bool a = krs[t.x] >= 0.0f, b = krs[t.y] >= 0.0f, c = krs[t.z] >= 0.0f;
        return !(a == b && b == c);
    };
    std::vector<uint8_t> needed(n, 0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, tris.size(), kGrain), [&](const auto& range) {
        for (size_t f = range.begin(); f != range.end(); ++f)
            if (crossed(tris[f]))
                for (int k = 0; k < 3; ++k)
                    std::atomic_ref<uint8_t>(needed[tris[f][k]]).store(1, std::memory_order_relaxed);
    });
    struct Trim {
        float dwkr = 0.0f, ndotv = 0.0f;
    };
    std::vector<Trim> trim(n);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, kGrain), [&](const auto& range) {
        for (size_t i = range.begin(); i != range.end(); ++i)
            if (needed[i]) {
                const ViewCurvature vc = view_curvature(normals[i], view.at(mesh.positions[i]), curvature, i);
                trim[i] = {vc.dwkr, vc.ndotv};
            }
    });
    // The trim test's numerator (±D_w κr − threshold·n·v; minus for highlights) and
    // denominator (n·v) at vertex i.
    const double sign = options.highlights ? -1.0 : 1.0;
    auto test = [&](uint32_t i) {
        return std::pair{sign * double(trim[i].dwkr) - threshold * double(trim[i].ndotv), double(trim[i].ndotv)};
    };

    // The crossing on edge (i, j) with its test values, from the edge alone (bit-identical
    // for both faces of the edge).
    auto on_edge = [&](uint32_t i, uint32_t j) {
        if (j < i) std::swap(i, j);
        const EdgeCrossing c = edge_zero_crossing(mesh, krs, i, j);
        const auto [num_i, den_i] = test(i);
        const auto [num_j, den_j] = test(j);
        TestPoint tp;
        tp.p = c.p;
        tp.num = num_i + c.t * (num_j - num_i);
        tp.den = den_i + c.t * (den_j - den_i);
        return tp;
    };

    return collect_face_segments(tris.size(), [&](size_t f, std::vector<LineSegment>& out) {
        const glm::uvec3 t = tris[f];
        if (!crossed(t)) return;
        const bool pos[3] = {krs[t.x] >= 0.0f, krs[t.y] >= 0.0f, krs[t.z] >= 0.0f};
        if (pos[0] == pos[1] && pos[1] == pos[2]) return;
        const int k = pos[1] == pos[2] ? 0 : (pos[0] == pos[2] ? 1 : 2);
        const uint32_t vk = t[k], vnext = t[(k + 1) % 3], vprev = t[(k + 2) % 3];
        uint64_t key_a = edge_key(vk, vnext), key_b = edge_key(vprev, vk);
        if (key_a == key_b) return;  // repeated index
        TestPoint a = on_edge(vk, vnext), b = on_edge(vprev, vk);
        // As in extract_contours: keep krs ≥ 0 on the left of a → b.
        if (!pos[k]) {
            std::swap(a, b);
            std::swap(key_a, key_b);
        }

        // The part of a → b where both num and den are positive, both linear along it.
        double lo = 0.0, hi = 1.0;
        for (const auto& [h0, h1] : {std::pair{a.num, b.num}, std::pair{a.den, b.den}}) {
            if (h0 > 0.0 && h1 > 0.0) continue;
            if (h0 <= 0.0 && h1 <= 0.0) {
                lo = 1.0;
                hi = 0.0;
                break;
            }
            const double s = h0 / (h0 - h1);
            if (h0 > 0.0)
                hi = std::min(hi, s);
            else
                lo = std::max(lo, s);
        }
        if (!(lo < hi)) return;

        auto at = [&](double s) {
            TestPoint tp;
            tp.p = glm::vec3(glm::dvec3(a.p) + s * (glm::dvec3(b.p) - glm::dvec3(a.p)));
            tp.num = std::max(0.0, a.num + s * (b.num - a.num));
            tp.den = std::max(0.0, a.den + s * (b.den - a.den));
            return tp;
        };
        LineSegment seg;
        seg.face = uint32_t(f);
        const TestPoint pa = lo > 0.0 ? at(lo) : a, pb = hi < 1.0 ? at(hi) : b;
        seg.a = pa.p;
        seg.b = pb.p;
        seg.edge_a = lo > 0.0 ? face_interior_key(uint32_t(f), 0) : key_a;
        seg.edge_b = hi < 1.0 ? face_interior_key(uint32_t(f), 1) : key_b;
        seg.strength_a = strength(pa.num, pa.den, fade);
        seg.strength_b = strength(pb.num, pb.den, fade);
        out.push_back(seg);
    });
}

}  // namespace inkshade::geometry
