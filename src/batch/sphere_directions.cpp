// View directions on the sphere (batch/sphere_directions.hpp).
#include "batch/sphere_directions.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

namespace inkshade::batch {

namespace {

// A direction of the camera math's frame from its up coordinate and azimuth (radians).
glm::dvec3 from_up_and_azimuth(double y, double azimuth) {
    const double r = std::sqrt(std::max(0.0, 1.0 - y * y));
    return {r * std::sin(azimuth), y, r * std::cos(azimuth)};
}

using Face = std::array<int, 3>;

// The level-0 icosahedron: poles, two rings of five, and its 20 faces.
void icosahedron(std::vector<glm::dvec3>& points, std::vector<Face>& faces) {
    const double ring = std::atan(0.5), step = 2.0 * std::numbers::pi / 5.0;
    points.push_back({0.0, 1.0, 0.0});
    for (int k = 0; k < 5; ++k) points.push_back(from_up_and_azimuth(std::sin(ring), step * k));           // 1..5
    for (int k = 0; k < 5; ++k) points.push_back(from_up_and_azimuth(-std::sin(ring), step * (k + 0.5)));  // 6..10
    points.push_back({0.0, -1.0, 0.0});
    for (int k = 0; k < 5; ++k) {
        const int u = 1 + k, u1 = 1 + (k + 1) % 5, l = 6 + k, l1 = 6 + (k + 1) % 5;
        faces.push_back({0, u, u1});
        faces.push_back({u, l, u1});
        faces.push_back({u1, l, l1});
        faces.push_back({11, l1, l});
    }
}

}  // namespace

std::vector<glm::dvec3> fibonacci_directions(int n) {
    const double golden_angle = std::numbers::pi * (3.0 - std::sqrt(5.0));
    std::vector<glm::dvec3> out;
    out.reserve(size_t(std::max(n, 0)));
    for (int i = 0; i < n; ++i)
        out.push_back(
            from_up_and_azimuth(1.0 - (2.0 * i + 1.0) / n, std::fmod(golden_angle * i, 2.0 * std::numbers::pi)));
    return out;
}

std::vector<glm::dvec3> icosphere_directions(int level) {
    std::vector<glm::dvec3> points;
    std::vector<Face> faces;
    icosahedron(points, faces);
    for (int l = 0; l < level; ++l) {
        std::map<std::pair<int, int>, int> midpoints;  // edge (low, high) -> its new vertex
        auto midpoint = [&](int a, int b) {
            const auto key = std::minmax(a, b);
            const auto [it, fresh] = midpoints.emplace(key, int(points.size()));
            if (fresh) points.push_back(glm::normalize(points[size_t(a)] + points[size_t(b)]));
            return it->second;
        };
        std::vector<Face> next;
        next.reserve(faces.size() * 4);
        for (const Face& f : faces) {
            const int ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
            next.push_back({f[0], ab, ca});
            next.push_back({ab, f[1], bc});
            next.push_back({ca, bc, f[2]});
            next.push_back({ab, bc, ca});
        }
        faces = std::move(next);
    }
    return points;
}

uint64_t SplitMix64::next() {
    uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

glm::dvec3 uniform_direction(SplitMix64& random) {
    const double y = 1.0 - 2.0 * random.uniform();
    return from_up_and_azimuth(y, 2.0 * std::numbers::pi * random.uniform());
}

glm::dvec2 azimuth_elevation(const glm::dvec3& d) {
    double azimuth = std::atan2(d.x, d.z) * 180.0 / std::numbers::pi;
    if (azimuth < 0.0) azimuth += 360.0;
    if (azimuth >= 360.0) azimuth = 0.0;
    return {azimuth, std::asin(std::clamp(d.y, -1.0, 1.0)) * 180.0 / std::numbers::pi};
}

}  // namespace inkshade::batch
