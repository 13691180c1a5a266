#include "geometry/view_depth_range.hpp"

#include <algorithm>
#include <cmath>

namespace inkshade::geometry {

ViewDepthRange ViewDepthRange::of_sphere(const Camera& camera, glm::vec3 centre, float radius) {
    ViewDepthRange r;
    r.orthographic = camera.orthographic;
    r.near_plane = camera.near_plane;
    r.far_plane = camera.far_plane;
    glm::dvec3 forward = glm::dvec3(camera.target) - glm::dvec3(camera.eye);
    const double len = glm::length(forward);
    forward = len > 0.0 ? forward / len : glm::dvec3(0.0, 0.0, -1.0);
    const double d = glm::dot(glm::dvec3(centre) - glm::dvec3(camera.eye), forward);
    r.nearest = d - double(radius);
    r.farthest = d + double(radius);
    return r;
}

double ViewDepthRange::view_depth(float window_depth) const {
    const double n = near_plane, f = far_plane, w = window_depth;
    if (orthographic) return n + w * (f - n);
    // glm::perspective (OpenGL clip space): z_ndc = (f + n) / (f - n) - 2 f n / ((f - n) z).
    const double ndc = 2.0 * w - 1.0;
    return 2.0 * f * n / ((f + n) - ndc * (f - n));
}

float ViewDepthRange::fraction(float window_depth) const {
    const double span = farthest - nearest;
    if (!(span > 0.0) || !std::isfinite(window_depth)) return 0.0f;
    return float(std::clamp((view_depth(window_depth) - nearest) / span, 0.0, 1.0));
}

}  // namespace inkshade::geometry
