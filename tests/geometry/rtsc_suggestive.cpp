#include "geometry/rtsc_suggestive.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "geometry/curvature.hpp"
#include "geometry/image_point_grid.hpp"
#include "geometry/visibility.hpp"

namespace inkshade::test {

namespace {

// trimesh2's need_normals: each face's cross product a × b (twice its area along its normal)
// added to a corner with weight 1 / (|e1|² |e2|²), e1 and e2 the corner's two edges (Max 1999).
std::vector<glm::vec3> max_weighted_normals(const Mesh& mesh) {
    std::vector<glm::dvec3> sum(mesh.positions.size(), glm::dvec3(0.0));
    for (const glm::uvec3& t : mesh.triangles) {
        const glm::dvec3 p0(mesh.positions[t.x]), p1(mesh.positions[t.y]), p2(mesh.positions[t.z]);
        const glm::dvec3 a = p0 - p1, b = p1 - p2, c = p2 - p0;
        const double la = glm::dot(a, a), lb = glm::dot(b, b), lc = glm::dot(c, c);
        if (!(la > 0.0 && lb > 0.0 && lc > 0.0)) continue;
        const glm::dvec3 n = glm::cross(a, b);
        sum[t.x] += n * (1.0 / (la * lc));
        sum[t.y] += n * (1.0 / (lb * la));
        sum[t.z] += n * (1.0 / (lc * lb));
    }
    std::vector<glm::vec3> out(sum.size());
    for (size_t i = 0; i < sum.size(); ++i) {
        const double l = glm::length(sum[i]);
        out[i] = l > 0.0 ? glm::vec3(sum[i] / l) : glm::vec3(0.0f);
    }
    return out;
}

// Radius of a bounding sphere about the bounding box's centre (trimesh2's bsphere is tighter;
// the radius only caps the feature size at 5 % of it).
double bounding_radius(const Mesh& mesh) {
    const BoundingBox box = mesh.bounds();
    const glm::dvec3 centre = 0.5 * (glm::dvec3(box.min) + glm::dvec3(box.max));
    double r = 0.0;
    for (const glm::vec3& p : mesh.positions) r = std::max(r, glm::length(glm::dvec3(p) - centre));
    return r;
}

// rtsc's compute_feature_size: 1 % of the reciprocal of the 10th percentile of |k1|, |k2| over
// 500 vertices drawn with its linear congruential generator, at most 5 % of the bounding radius.
float rtsc_feature_size(const std::vector<float>& k1, const std::vector<float>& k2, double radius) {
    const size_t nv = k1.size();
    if (nv == 0) return 1.0f;
    std::vector<float> samples;
    unsigned randq = 0;
    for (size_t i = 0; i < std::min<size_t>(nv, 500); ++i) {
        randq = unsigned(1664525) * randq + unsigned(1013904223);
        const size_t ind = randq % nv;
        samples.push_back(std::fabs(k1[ind]));
        samples.push_back(std::fabs(k2[ind]));
    }
    const size_t which = size_t(0.1f * float(samples.size()));
    std::nth_element(samples.begin(), samples.begin() + ptrdiff_t(which), samples.end());
    return std::min(0.01f / samples[which], 0.05f * float(radius));
}

// rtsc's per-vertex quantities for one view (compute_perview).
struct PerView {
    std::vector<float> ndotv, kr, num, den;
};

// A line vertex as rtsc emits it between glBegin(GL_LINES) and glEnd: position and alpha.
struct LineVertex {
    glm::vec3 p;
    float alpha;
};

float faded_alpha(float num, float den, float fade) {
    const float a = num / (den * fade + num);
    return std::isfinite(a) ? std::clamp(a, 0.0f, 1.0f) : 0.0f;  // GL clamps colours
}

// rtsc's draw_face_isoline2 with do_test and linear zero finding: val[v0] differs in sign from
// val[v1] and val[v2].
void face_isoline2(const Mesh& mesh, const PerView& pv, uint32_t v0, uint32_t v1, uint32_t v2, float fade,
                   std::vector<LineVertex>& out) {
    const auto& val = pv.kr;
    const float w10 = val[v0] / (val[v0] - val[v1]), w01 = 1.0f - w10;
    const float w20 = val[v0] / (val[v0] - val[v2]), w02 = 1.0f - w20;
    const glm::vec3 p1 = w01 * mesh.positions[v0] + w10 * mesh.positions[v1];
    const glm::vec3 p2 = w02 * mesh.positions[v0] + w20 * mesh.positions[v2];
    const float num1 = w01 * pv.num[v0] + w10 * pv.num[v1], num2 = w02 * pv.num[v0] + w20 * pv.num[v2];
    const float den1 = w01 * pv.den[v0] + w10 * pv.den[v1], den2 = w02 * pv.den[v0] + w20 * pv.den[v2];
    const bool valid1 = (num1 >= 0.0f) == (den1 >= 0.0f);
    float z1 = 0.0f, z2 = 0.0f;
    if ((num1 >= 0.0f) != (num2 >= 0.0f)) z1 = num1 / (num1 - num2);
    if ((den1 >= 0.0f) != (den2 >= 0.0f)) z2 = den1 / (den1 - den2);
    if (z1 == 0.0f)
        z1 = z2, z2 = 0.0f;
    else if (z2 < z1)
        std::swap(z1, z2);
    if (!valid1 && !z1 && !z2) return;
    int npts = 0;
    auto emit_at = [&](float z) {
        const float num = (1.0f - z) * num1 + z * num2, den = (1.0f - z) * den1 + z * den2;
        out.push_back({(1.0f - z) * p1 + z * p2, faded_alpha(num, den, fade)});
        ++npts;
    };
    if (valid1) out.push_back({p1, faded_alpha(num1, den1, fade)}), ++npts;
    if (z1 != 0.0f) emit_at(z1);
    if (z2 != 0.0f) emit_at(z2);
    if (npts != 2) out.push_back({p2, faded_alpha(num2, den2, fade)});
}

// rtsc's draw_face_isoline for suggestive contours: back-face culling, the quick reject, then
// the vertex whose kr differs in sign.
void face_isoline(const Mesh& mesh, const PerView& pv, uint32_t v0, uint32_t v1, uint32_t v2, float fade,
                  std::vector<LineVertex>& out) {
    const auto &nv = pv.ndotv, &val = pv.kr, &num = pv.num, &den = pv.den;
    if (nv[v0] <= 0.0f && nv[v1] <= 0.0f && nv[v2] <= 0.0f) return;
    if (num[v0] <= 0.0f && den[v0] >= 0.0f && num[v1] <= 0.0f && den[v1] >= 0.0f && num[v2] <= 0.0f && den[v2] >= 0.0f)
        return;
    if (num[v0] >= 0.0f && den[v0] <= 0.0f && num[v1] >= 0.0f && den[v1] <= 0.0f && num[v2] >= 0.0f && den[v2] <= 0.0f)
        return;
    auto odd = [&](uint32_t a, uint32_t b, uint32_t c) {
        return (val[a] < 0.0f && val[b] >= 0.0f && val[c] >= 0.0f) ||
               (val[a] > 0.0f && val[b] <= 0.0f && val[c] <= 0.0f);
    };
    if (odd(v0, v1, v2))
        face_isoline2(mesh, pv, v0, v1, v2, fade, out);
    else if (odd(v1, v2, v0))
        face_isoline2(mesh, pv, v1, v2, v0, fade, out);
    else if (odd(v2, v0, v1))
        face_isoline2(mesh, pv, v2, v0, v1, fade, out);
}

}  // namespace

RtscSuggestive::RtscSuggestive(const Mesh& mesh) : mesh_(mesh), normals_(max_weighted_normals(mesh)) {
    const geometry::Curvature c = geometry::compute_curvature(mesh, normals_);
    pdir1_ = c.pdir1, pdir2_ = c.pdir2, k1_ = c.k1, k2_ = c.k2, dcurv_ = c.dcurv;
    feature_size_ = rtsc_feature_size(k1_, k2_, bounding_radius(mesh));
}

std::vector<RtscLineSample> RtscSuggestive::drawn(const Camera& camera, int width, int height) const {
    // compute_perview with sug_thresh 0.01: sctest_num = D_w κr (the cubic form of dcurv in w
    // over |w|², minus 2 (n·v) τr²) − threshold · n·v, sctest_den = n·v.
    const size_t n = mesh_.positions.size();
    const float fs2 = feature_size_ * feature_size_, scthresh = 0.01f / fs2, fade = 0.03f / fs2;
    PerView pv{std::vector<float>(n), std::vector<float>(n), std::vector<float>(n), std::vector<float>(n)};
    const glm::vec3 viewpos = camera.eye;
    for (size_t i = 0; i < n; ++i) {
        const glm::vec3 viewdir = glm::normalize(viewpos - mesh_.positions[i]);
        pv.ndotv[i] = glm::dot(viewdir, normals_[i]);
        const float u = glm::dot(viewdir, pdir1_[i]), u2 = u * u;
        const float v = glm::dot(viewdir, pdir2_[i]), v2 = v * v;
        pv.kr[i] = k1_[i] * u2 + k2_[i] * v2;  // κr sin²θ
        const glm::vec4& C = dcurv_[i];
        float num = u2 * (u * C[0] + 3.0f * v * C[1]) + v2 * (3.0f * u * C[2] + v * C[3]);
        const float csc2theta = 1.0f / (u2 + v2);
        num *= csc2theta;
        const float tr = (k2_[i] - k1_[i]) * u * v * csc2theta;
        num -= 2.0f * pv.ndotv[i] * tr * tr;
        pv.den[i] = pv.ndotv[i];
        pv.num[i] = num - scthresh * pv.den[i];
    }
    // draw_isolines: faces with kr of both signs.
    std::vector<LineVertex> lines;
    for (const glm::uvec3& t : mesh_.triangles) {
        const float a = pv.kr[t.x], b = pv.kr[t.y], c = pv.kr[t.z];
        if ((a > 0.0f || b > 0.0f || c > 0.0f) && (a < 0.0f || b < 0.0f || c < 0.0f))
            face_isoline(mesh_, pv, t.x, t.y, t.z, fade, lines);
    }
    // Half-pixel samples through the depth test (GL_LEQUAL against the offset mesh).
    const RtscDepthBuffer buffer(mesh_, camera, width, height);
    const geometry::ImageProjection view(camera, width, height);
    std::vector<RtscLineSample> out;
    for (size_t i = 0; i + 1 < lines.size(); i += 2) {
        const LineVertex &a = lines[i], &b = lines[i + 1];
        if (view.clipped(a.p) || view.clipped(b.p)) continue;
        const glm::dvec3 sa = view.project(a.p), sb = view.project(b.p);
        const double length = glm::length(glm::dvec2(sb) - glm::dvec2(sa));
        const int steps = std::max(1, int(std::ceil(length / 0.5)));
        for (int k = 0; k < steps; ++k) {
            const double s = (k + 0.5) / steps;
            const glm::dvec3 q = sa + s * (sb - sa);
            if (!buffer.passes(glm::dvec2(q), q.z)) continue;
            out.push_back({glm::dvec2(q), double(a.alpha) + s * double(b.alpha - a.alpha), length / steps});
        }
    }
    return out;
}

namespace {

// Samples every `spacing` px along the paths with their strength (1 where a path has none).
template <typename F>
void for_each_strength_sample(const std::vector<LinePath>& paths, double spacing, F&& f) {
    for (const LinePath& path : paths) {
        const size_t n = path.points.size();
        auto strength = [&](size_t i) { return path.strength.size() == n ? double(path.strength[i]) : 1.0; };
        const size_t segments = n < 2 ? 0 : (path.closed ? n : n - 1);
        for (size_t i = 0; i < segments; ++i) {
            const size_t j = (i + 1) % n;
            const glm::dvec2 a(path.points[i]), b(path.points[j]);
            const double length = glm::length(b - a);
            const int steps = std::max(1, int(std::ceil(length / spacing)));
            for (int k = 0; k < steps; ++k) {
                const double s = (k + 0.5) / steps;
                f(a + s * (b - a), strength(i) + s * (strength(j) - strength(i)), length / steps);
            }
        }
    }
}

}  // namespace

RtscAgreement rtsc_suggestive_agreement(const std::vector<RtscLineSample>& rtsc, const LineLayer& layer,
                                        double tolerance_px) {
    ImagePointGrid ours(tolerance_px), theirs(tolerance_px);
    for_each_strength_sample(layer.visible, 0.25, [&](glm::dvec2 p, double, double) { ours.add(p); });
    for (const RtscLineSample& s : rtsc)
        if (s.alpha > 0.0) theirs.add(s.p);
    RtscAgreement a;
    for (const RtscLineSample& s : rtsc) {
        a.rtsc_visible += s.alpha * s.length;
        if (ours.near(s.p, tolerance_px)) a.recalled += s.alpha * s.length;
    }
    for_each_strength_sample(layer.visible, 0.25, [&](glm::dvec2 p, double strength, double length) {
        a.visible += strength * length;
        if (theirs.near(p, tolerance_px)) a.precise += strength * length;
    });
    return a;
}

}  // namespace inkshade::test
