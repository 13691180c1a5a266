// The per-point attributes of a LinePath (points, depth, strength, width, color, u, world), as
// one list: every operation that copies, reverses, splits, opens, rotates or resamples a path
// visits them with for_each_point_attribute, so a new attribute is added here and carried by all
// of them (tests/geometry/path_attributes_test.cpp fails until it is).
#pragma once
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
}

// Whether every per-point attribute is either empty or of the points' size.
inline bool attributes_consistent(const LinePath& path) {
    bool ok = true;
    for_each_point_attribute([&](const auto& v) { ok = ok && (v.empty() || v.size() == path.points.size()); }, path);
    return ok;
}

}  // namespace inkshade::geometry
