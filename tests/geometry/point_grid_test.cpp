// PointGrid::any_within against a scan of every point, with the same float arithmetic: points
// along strokes and scattered, queries anywhere (cell corners and faces included), radii up
// to the cell size, near the origin and far from it.
#include "geometry/point_grid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace inkshade::geometry {
namespace {

bool any_within_by_scan(const std::vector<glm::vec3>& points, const glm::dvec3& p, double r) {
    const glm::vec3 pf(p);
    const float r2 = float(r * r);
    for (const glm::vec3& q : points) {
        const glm::vec3 d = q - pf;
        if (glm::dot(d, d) < r2) return true;
    }
    return false;
}

void expect_matches_scan(const glm::dvec3& origin, double cell) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    PointGrid grid(cell);
    std::vector<glm::vec3> points;
    auto add = [&](const glm::dvec3& p) {
        grid.add(p);
        points.push_back(glm::vec3(p));
    };
    const double extent = 12.0 * cell;
    auto random_point = [&] { return origin + extent * glm::dvec3(unit(rng), unit(rng), unit(rng)); };
    for (int i = 0; i < 300; ++i) add(random_point());
    // Points exactly on cell planes, where a float rounding can move a point into the next cell.
    for (int i = 0; i < 200; ++i) {
        glm::dvec3 p = random_point();
        p.x = std::floor(p.x / cell) * cell;
        if (i % 2) p.y = std::floor(p.y / cell) * cell;
        add(p);
    }
    for (int i = 0; i < 20; ++i) {
        const glm::dvec3 a = random_point(), b = random_point();
        grid.add_segment(a, b, 0.25 * cell);
        const int n = std::max(1, int(std::ceil(glm::length(b - a) / (0.25 * cell))));
        for (int k = 0; k <= n; ++k) points.push_back(glm::vec3(a + (b - a) * (double(k) / n)));
    }
    EXPECT_EQ(grid.size(), points.size());
    int hits = 0, misses = 0;
    for (int i = 0; i < 20000; ++i) {
        glm::dvec3 p = origin + glm::dvec3(-cell) + (extent + 2.0 * cell) * glm::dvec3(unit(rng), unit(rng), unit(rng));
        if (i % 4 == 1) p.z = std::round(p.z / cell) * cell;  // on a cell plane
        if (i % 4 == 2) p = glm::dvec3(points[size_t(i) % points.size()]) + glm::dvec3(0.3 * cell, 0.0, 0.0);
        const double r = cell * (i % 3 == 0 ? 1.0 : i % 3 == 1 ? 0.5 : 0.9);
        const bool expected = any_within_by_scan(points, p, r);
        ASSERT_EQ(grid.any_within(p, r), expected) << "query " << i << " at " << p.x << ", " << p.y << ", " << p.z;
        (expected ? hits : misses)++;
    }
    // Both answers occur often, so the comparison means something.
    EXPECT_GT(hits, 2000);
    EXPECT_GT(misses, 2000);
}

TEST(PointGrid, AnyWithinMatchesAScanOfEveryPoint) { expect_matches_scan(glm::dvec3(0.0), 0.1); }

TEST(PointGrid, AnyWithinMatchesAScanFarFromTheOriginAndBelowIt) {
    expect_matches_scan(glm::dvec3(-1234.5, 987.25, -3.0), 0.37);
}

TEST(PointGrid, EmptyGridHasNothingNear) {
    const PointGrid grid(1.0);
    EXPECT_FALSE(grid.any_within(glm::dvec3(0.0), 1.0));
}

}  // namespace
}  // namespace inkshade::geometry
