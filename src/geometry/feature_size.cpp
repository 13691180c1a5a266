#include "geometry/feature_size.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace inkshade::geometry {

BoundingSphere bounding_sphere(const Mesh& mesh) {
    const auto& p = mesh.positions;
    auto first = std::find_if(p.begin(), p.end(), is_finite);
    if (first == p.end()) return {};
    // Ritter: from any point the farthest x, from x the farthest y; the sphere on xy grows to
    // take in every point left outside it.
    auto farthest = [&](const glm::dvec3& from) {
        glm::dvec3 best = from;
        double best_d = -1.0;
        for (const glm::vec3& q : p)
            if (is_finite(q)) {
                const double d = glm::dot(glm::dvec3(q) - from, glm::dvec3(q) - from);
                if (d > best_d) best_d = d, best = glm::dvec3(q);
            }
        return best;
    };
    const glm::dvec3 x = farthest(glm::dvec3(*first)), y = farthest(x);
    glm::dvec3 center = 0.5 * (x + y);
    double radius = 0.5 * glm::length(y - x);
    for (const glm::vec3& q : p) {
        if (!is_finite(q)) continue;
        const double d = glm::length(glm::dvec3(q) - center);
        if (d <= radius) continue;
        const double grown = 0.5 * (radius + d);
        center += (grown - radius) / d * (glm::dvec3(q) - center);
        radius = grown;
    }
    return {glm::vec3(center), float(radius)};
}

float line_feature_size(const Mesh& mesh, const Curvature& curvature) {
    const double cap = 0.05 * double(bounding_sphere_radius(mesh));
    if (!(cap > 0.0) || !std::isfinite(cap)) return 1.0f;
    const size_t n = std::min({mesh.positions.size(), curvature.k1.size(), curvature.k2.size()});
    std::vector<float> samples;
    const size_t count = std::min<size_t>(n, 500);
    samples.reserve(2 * count);
    uint32_t random = 0;
    for (size_t i = 0; i < count; ++i) {
        random = 1664525u * random + 1013904223u;  // Numerical Recipes' generator, as rtsc
        const size_t v = random % n;
        for (float k : {curvature.k1[v], curvature.k2[v]})
            if (std::isfinite(k)) samples.push_back(std::abs(k));
    }
    if (samples.empty()) return float(cap);
    const auto tenth = samples.begin() + ptrdiff_t(0.1 * double(samples.size()));
    std::nth_element(samples.begin(), tenth, samples.end());
    const double size = 0.01 / double(*tenth);  // +inf where the percentile is 0: the cap
    return float(std::min(size, cap));
}

}  // namespace inkshade::geometry
