#include "geometry/rtsc_depth_buffer.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/depth_reference.hpp"
#include "geometry/image_point_grid.hpp"

namespace inkshade::test {

namespace {

// GL's r for a 24-bit depth buffer: the smallest resolvable difference (glPolygonOffset units).
constexpr double kDepthUnit = 1.0 / 16777216.0;
constexpr double kOffsetFactor = 5.0, kOffsetUnits = 30.0;  // rtsc's glPolygonOffset(5, 30)

// Is the face front-facing (towards the eye; orthographic: against the view direction)?
bool front_facing(const Camera& camera, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const glm::dvec3 towards =
        camera.orthographic ? glm::dvec3(camera.eye - camera.target) : glm::dvec3(camera.eye) - a;
    return glm::dot(n, towards) > 0.0;
}

}  // namespace

RtscDepthBuffer::RtscDepthBuffer(const Mesh& mesh, const Camera& camera, int width, int height)
    : view_(camera, width, height), width_(width), height_(height), depth_(size_t(width) * size_t(height), 1.0) {
    for (const glm::uvec3& t : mesh.triangles) {
        const glm::vec3 p[3] = {mesh.positions[t.x], mesh.positions[t.y], mesh.positions[t.z]};
        if (view_.clipped(p[0]) || view_.clipped(p[1]) || view_.clipped(p[2])) continue;
        if (!front_facing(camera, p[0], p[1], p[2])) continue;  // glCullFace(GL_BACK)
        glm::dvec3 s[3];
        for (int k = 0; k < 3; ++k) s[k] = view_.project(p[k]);  // (x, y, window depth): affine in x, y
        const glm::dvec2 e1(s[1] - s[0]), e2(s[2] - s[0]);
        const double det = e1.x * e2.y - e1.y * e2.x;
        if (!(std::abs(det) > 1e-12)) continue;
        const double dz1 = s[1].z - s[0].z, dz2 = s[2].z - s[0].z;
        const double gx = (dz1 * e2.y - dz2 * e1.y) / det, gy = (dz2 * e1.x - dz1 * e2.x) / det;
        const double offset = kOffsetFactor * std::max(std::abs(gx), std::abs(gy)) + kOffsetUnits * kDepthUnit;
        const int i0 = std::max(0, int(std::floor(std::min({s[0].x, s[1].x, s[2].x}))));
        const int i1 = std::min(width_ - 1, int(std::ceil(std::max({s[0].x, s[1].x, s[2].x}))));
        const int j0 = std::max(0, int(std::floor(std::min({s[0].y, s[1].y, s[2].y}))));
        const int j1 = std::min(height_ - 1, int(std::ceil(std::max({s[0].y, s[1].y, s[2].y}))));
        for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i) {
                const glm::dvec2 q(i + 0.5 - s[0].x, j + 0.5 - s[0].y);
                const double u = (q.x * e2.y - q.y * e2.x) / det, v = (e1.x * q.y - e1.y * q.x) / det;
                if (u < 0.0 || v < 0.0 || u + v > 1.0) continue;
                double& d = depth_[size_t(j) * size_t(width_) + size_t(i)];
                d = std::min(d, std::clamp(s[0].z + u * dz1 + v * dz2 + offset, 0.0, 1.0));
            }
    }
}

bool RtscDepthBuffer::passes(glm::dvec2 p, double window_depth) const {
    const int i = int(std::floor(p.x)), j = int(std::floor(p.y));
    if (i < 0 || j < 0 || i >= width_ || j >= height_) return false;
    return window_depth <= depth_[size_t(j) * size_t(width_) + size_t(i)];  // GL_LEQUAL
}

RtscAgreement& RtscAgreement::operator+=(const RtscAgreement& o) {
    rtsc_visible += o.rtsc_visible, recalled += o.recalled, visible += o.visible, precise += o.precise;
    return *this;
}

RtscAgreement rtsc_agreement(const RtscDepthBuffer& buffer, const LineLayer& layer, double tolerance_px,
                             const LineLayer* drawn) {
    constexpr double kSpacing = 0.25;
    const LineLayer& compared = drawn ? *drawn : layer;
    ImagePointGrid ours(tolerance_px), theirs(tolerance_px);
    std::vector<std::pair<glm::dvec2, double>> rtsc_samples;
    RtscAgreement a;
    for (const auto* list : {&layer.visible, &layer.hidden})
        for_each_sample(*list, kSpacing, [&](glm::dvec2 p, double depth, double length, const LinePath&) {
            if (buffer.passes(p, depth)) theirs.add(p), rtsc_samples.emplace_back(p, length);
        });
    for_each_sample(compared.visible, kSpacing, [&](glm::dvec2 p, double, double, const LinePath&) { ours.add(p); });
    for (const auto& [p, length] : rtsc_samples) {
        a.rtsc_visible += length;
        if (ours.near(p, tolerance_px)) a.recalled += length;
    }
    for_each_sample(compared.visible, kSpacing, [&](glm::dvec2 p, double, double length, const LinePath&) {
        a.visible += length;
        if (theirs.near(p, tolerance_px)) a.precise += length;
    });
    return a;
}

}  // namespace inkshade::test
