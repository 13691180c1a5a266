#include "core/tight_framing.hpp"

#include <algorithm>
#include <cmath>

namespace inkshade::framing {

namespace {

// Along image axis `axis` (0: x, 1: y), for the bound t: max_i (a_i - t z_i) and
// max_i (-a_i - t z_i), a the points' coordinate on that axis. The eye's offset e and depth ez
// satisfy every constraint |a_i - e| <= t (z_i - ez) exactly when e - t ez >= the first and
// -e - t ez >= the second.
std::pair<float, float> sides(std::span<const glm::vec3> points, int axis, float t) {
    float plus = -INFINITY, minus = -INFINITY;
    for (const glm::vec3& p : points) {
        plus = std::max(plus, p[axis] - t * p.z);
        minus = std::max(minus, -p[axis] - t * p.z);
    }
    return {plus, minus};
}

// The greatest eye depth from which the points fit the bound t on `axis` once centred (the two
// conditions of sides() summed).
float fitting_depth(std::span<const glm::vec3> points, int axis, float t) {
    const auto [plus, minus] = sides(points, axis, t);
    return -(plus + minus) / (2.0f * t);
}

// With the eye at depth ez, the offset along `axis` that centres the points' projection: their
// tangents then span [-t, t] with the least t, t = max over pairs (a_i - a_j) / (z_i + z_j - 2 ez),
// found by Dinkelbach's iteration (each step takes the ratio of the pair that is extreme for the
// current t; t rises to the maximum in a few steps), and e = (plus - minus) / 2 at that t.
float centring_offset(std::span<const glm::vec3> points, int axis, float ez) {
    float t = 0.0f;
    for (int step = 0; step < 64; ++step) {
        size_t hi = 0, lo = 0;
        float best_hi = -INFINITY, best_lo = -INFINITY;
        for (size_t i = 0; i < points.size(); ++i) {
            const float depth = points[i].z - ez, a = points[i][axis];
            if (a - t * depth > best_hi) best_hi = a - t * depth, hi = i;
            if (-a - t * depth > best_lo) best_lo = -a - t * depth, lo = i;
        }
        const float ratio = (points[hi][axis] - points[lo][axis]) / (points[hi].z + points[lo].z - 2.0f * ez);
        if (!(ratio > t)) break;
        t = ratio;
    }
    const auto [plus, minus] = sides(points, axis, t);
    return 0.5f * (plus - minus);
}

float nearest(std::span<const glm::vec3> points) {
    float z = INFINITY;
    for (const glm::vec3& p : points) z = std::min(z, p.z);
    return z;
}

}  // namespace

glm::vec3 centred_eye(std::span<const glm::vec3> points, glm::vec2 reach, float clearance) {
    // The limiting axis gives the shallower depth; the eye never comes closer than clearance.
    const float ez =
        std::min({fitting_depth(points, 0, reach.x), fitting_depth(points, 1, reach.y), nearest(points) - clearance});
    return {centring_offset(points, 0, ez), centring_offset(points, 1, ez), ez};
}

float distance_on_axis(std::span<const glm::vec3> points, glm::vec2 reach, float clearance) {
    float d = clearance - nearest(points);
    for (const glm::vec3& p : points) d = std::max({d, std::abs(p.x) / reach.x - p.z, std::abs(p.y) / reach.y - p.z});
    return d;
}

std::pair<glm::vec2, glm::vec2> extent(std::span<const glm::vec3> points) {
    glm::vec2 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec3& p : points) {
        lo = glm::min(lo, glm::vec2(p));
        hi = glm::max(hi, glm::vec2(p));
    }
    return {lo, hi};
}

}  // namespace inkshade::framing
