// The per-point attributes of a LinePath (points, depth, strength, width, color, u, world,
// surface), as one list: every operation that copies, reverses, splits, opens, rotates or resamples a path
// visits them with for_each_point_attribute, so a new attribute is added here and carried by all
// of them (tests/geometry/path_attributes_test.cpp fails until it is).
#pragma once
#include <algorithm>
#include <vector>

#include "inkshade/line_drawing.hpp"

namespace inkshade::geometry {

// Calls f once per per-point attribute with that attribute's vector of each of `paths`:
// f(a.points, b.points, ...), f(a.depth, b.depth, ...), ... (as std::visit takes the visitor
// first). Every attribute but `points` may be empty: not set on that path.
template <class F, class... Paths>
void for_each_point_attribute(F&& f, Paths&... paths) {
    f(paths.points...);
    f(paths.depth...);
    f(paths.strength...);
    f(paths.width...);
    f(paths.color...);
    f(paths.u...);
    f(paths.world...);
    f(paths.surface...);
}

// An attribute between two consecutive points a and b of a path, at the fraction f of the way
// in the image: linear for the image's own attributes.
template <class T>
T interpolated(const T& a, const T& b, float f) {
    return f == 0.0f ? a : a + (b - a) * f;
}

// The surface point under the image point at f: perspective-correct (attributes over w are
// linear in the image), on a's face, which is the face of the piece from a to b
// (SurfacePoint::face). The barycentric weights are left to surface_barycentrics.
inline SurfacePoint interpolated(const SurfacePoint& a, const SurfacePoint& b, float f) {
    if (f == 0.0f) return a;
    const float t = f * a.w / ((1.0f - f) * b.w + f * a.w);
    SurfacePoint out = a;
    out.world = a.world + (b.world - a.world) * t;
    out.w = a.w + (b.w - a.w) * t;
    out.barycentric = glm::vec3(0.0f);
    return out;
}

// An attribute reversed with its path (a closed path keeps its first point first).
template <class T>
void reverse_attribute(std::vector<T>& v, bool closed) {
    if (v.size() < 2) return;
    std::reverse(v.begin() + (closed ? 1 : 0), v.end());
}

// Surface points reversed: each face moves to the point the piece now starts from, so that it
// stays the face of the piece to the next point.
inline void reverse_attribute(std::vector<SurfacePoint>& v, bool closed) {
    const size_t n = v.size();
    if (n < 2) return;
    std::vector<int32_t> piece(n);  // piece[i]: the face from old point i to old point i + 1
    for (size_t i = 0; i < n; ++i) piece[i] = v[i].face;
    std::reverse(v.begin() + (closed ? 1 : 0), v.end());
    // New point k is old point r(k); the piece from it to new point k + 1 is the old piece that
    // ends at r(k), which starts at r(k) - 1: face piece[r(k) - 1], the last one for old point 0.
    for (size_t k = 0; k < n; ++k) {
        const size_t old = closed ? (n - k) % n : n - 1 - k;
        if (old > 0)
            v[k].face = piece[old - 1];
        else if (closed)
            v[k].face = piece[n - 1];
        else
            v[k].face = piece[0];  // the new last point: on the piece that ends there
    }
}

// Whether every per-point attribute is either empty or of the points' size.
inline bool attributes_consistent(const LinePath& path) {
    bool ok = true;
    for_each_point_attribute([&](const auto& v) { ok = ok && (v.empty() || v.size() == path.points.size()); }, path);
    return ok;
}

}  // namespace inkshade::geometry
