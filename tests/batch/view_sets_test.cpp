// View sets on the sphere (parse_views: fibonacci, ico, random; orbit:AxE) against their
// formulas: the Fibonacci lattice's latitudes and golden-angle azimuths, the icosahedron's
// 12 vertices and its subdivisions' 10 * 4^L + 2, a seeded random set's determinism and
// uniformity.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "batch/sphere_directions.hpp"
#include "batch/view_roll.hpp"
#include "inkshade/batch.hpp"
#include "inkshade/error.hpp"

namespace inkshade {
namespace {

// The view's direction from the model centre towards the eye, as frame_camera places an
// orbit view (azimuth about +y from +z, elevation towards +y).
glm::dvec3 direction(const BatchView& v) {
    const double az = glm::radians(double(*v.camera.azimuth_degrees));
    const double el = glm::radians(double(*v.camera.elevation_degrees));
    return {std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)};
}

TEST(ViewSets, FibonacciFollowsTheLatticeFormula) {
    const int n = 50;
    const auto views = parse_views("fibonacci:50");
    ASSERT_EQ(views.size(), size_t(n));
    const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));  // radians
    for (int i = 0; i < n; ++i) {
        const double y = 1.0 - (2.0 * i + 1.0) / n, r = std::sqrt(1.0 - y * y);
        const glm::dvec3 expected(r * std::sin(golden * i), y, r * std::cos(golden * i));
        EXPECT_NEAR(glm::length(direction(views[size_t(i)]) - expected), 0.0, 1e-6) << i;
        EXPECT_FALSE(views[size_t(i)].camera.distance.has_value());  // auto-framed
    }
    EXPECT_EQ(views[0].name, "fib50_000");
    EXPECT_EQ(views[49].name, "fib50_049");
    EXPECT_EQ(parse_views("fibonacci:1001")[7].name, "fib1001_0007");
}

TEST(ViewSets, IcoLevelsHaveTheIcosahedronsVertices) {
    for (auto [level, count] : {std::pair{0, 12}, {1, 42}, {2, 162}, {3, 642}})
        EXPECT_EQ(parse_views("ico:" + std::to_string(level)).size(), size_t(count)) << level;
    // Level 0: unit vectors, each with exactly five nearest neighbours at the icosahedron's
    // central angle acos(1 / sqrt 5) = 63.435 degrees, and none nearer.
    const std::vector<glm::dvec3> v = batch::icosphere_directions(0);
    const double edge = std::acos(1.0 / std::sqrt(5.0));
    for (size_t i = 0; i < v.size(); ++i) {
        EXPECT_NEAR(glm::length(v[i]), 1.0, 1e-12);
        int neighbours = 0;
        for (size_t j = 0; j < v.size(); ++j) {
            if (i == j) continue;
            const double angle = std::acos(std::clamp(glm::dot(v[i], v[j]), -1.0, 1.0));
            EXPECT_GE(angle, edge - 1e-9);
            neighbours += std::abs(angle - edge) < 1e-9;
        }
        EXPECT_EQ(neighbours, 5) << i;
    }
    const auto views = parse_views("ico:0");
    EXPECT_NEAR(*views[0].camera.elevation_degrees, 90.0f, 1e-4f);
    EXPECT_NEAR(*views[11].camera.elevation_degrees, -90.0f, 1e-4f);
    EXPECT_NEAR(*views[1].camera.elevation_degrees, float(glm::degrees(std::atan(0.5))), 1e-4f);
    EXPECT_EQ(views[11].name, "ico0_011");
    // Level 1 adds the 30 edge midpoints: the first new one halves the edge (top, ring vertex 0).
    const std::vector<glm::dvec3> l1 = batch::icosphere_directions(1);
    EXPECT_NEAR(glm::length(l1[12] - glm::normalize(v[0] + v[1])), 0.0, 1e-12);
}

TEST(ViewSets, OrbitWithAColonIsTheOrbitSet) {
    const auto a = parse_views("orbit:8x3"), b = parse_views("orbit8x3");
    ASSERT_EQ(a.size(), 24u);
    for (size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].name, b[i].name);
        EXPECT_EQ(a[i].camera.azimuth_degrees, b[i].camera.azimuth_degrees);
        EXPECT_EQ(a[i].camera.elevation_degrees, b[i].camera.elevation_degrees);
    }
}

TEST(ViewSets, SplitMix64IsTheReferenceSequence) {
    // The first outputs for seed 1234567 of Vigna's splitmix64.c (prng.di.unimi.it).
    batch::SplitMix64 r(1234567);
    EXPECT_EQ(r.next(), 6457827717110365317ull);
    EXPECT_EQ(r.next(), 3203168211198807973ull);
    EXPECT_EQ(r.next(), 9817491932198370423ull);
}

TEST(ViewSets, RandomSetIsSeededAndUniform) {
    const auto a = parse_views("random:2000:7"), b = parse_views("random:2000:7"), c = parse_views("random:2000:8");
    ASSERT_EQ(a.size(), 2000u);
    size_t differ = 0;
    glm::dvec3 mean(0.0);
    int upper = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].camera.azimuth_degrees, b[i].camera.azimuth_degrees);
        EXPECT_EQ(a[i].camera.elevation_degrees, b[i].camera.elevation_degrees);
        differ += a[i].camera.azimuth_degrees != c[i].camera.azimuth_degrees;
        mean += direction(a[i]);
        upper += *a[i].camera.elevation_degrees > 0.0f;
        EXPECT_FALSE(a[i].roll_degrees.has_value());
    }
    EXPECT_EQ(differ, a.size());
    // Uniform on the sphere: each coordinate has mean 0 and variance 1/3, so the mean of 2000
    // has a standard deviation of 0.013; 0.05 is four of them. Half the views lie above.
    mean /= double(a.size());
    EXPECT_LT(glm::length(mean), 0.05);
    EXPECT_NEAR(upper, 1000, 100);
    EXPECT_EQ(a[0].name, "rnd7_0000");

    // Roll and distance draw from the same sequence without moving the directions.
    const auto d = parse_views("random:2000:7:roll=30:dist=2-3");
    for (size_t i = 0; i < d.size(); ++i) {
        EXPECT_EQ(d[i].camera.azimuth_degrees, a[i].camera.azimuth_degrees);
        EXPECT_EQ(d[i].camera.elevation_degrees, a[i].camera.elevation_degrees);
        EXPECT_LE(std::abs(*d[i].roll_degrees), 30.0f);
        EXPECT_GE(*d[i].camera.distance, 2.0f);
        EXPECT_LE(*d[i].camera.distance, 3.0f);
    }
}

// Roll turns the camera about its view axis: a point right of the centre in the unrolled
// image lies below it after a roll of +90 degrees (the camera turned counter-clockwise seen
// from behind, the image clockwise); the eye stays, and framing still holds the model.
TEST(ViewSets, RollTurnsTheImageAboutTheViewAxis) {
    const BoundingBox box{glm::vec3(-1), glm::vec3(1)};
    for (UpAxis axis : {UpAxis::PosY, UpAxis::PosZ})
        for (float elevation : {20.0f, 90.0f}) {
            CameraOptions o;
            o.azimuth_degrees = 30.0f;
            o.elevation_degrees = elevation;
            o.distance = 8.0f;
            o.up_axis = axis;
            const Camera plain = frame_camera(box, o, 1.0f);
            batch::roll_view(o, 90.0f);
            const Camera rolled = frame_camera(box, o, 1.0f);
            EXPECT_NEAR(glm::length(rolled.eye - plain.eye), 0.0f, 1e-5f);
            const glm::vec3 right = glm::normalize(glm::cross(plain.target - plain.eye, plain.up));
            const glm::vec4 a = plain.view() * glm::vec4(plain.target + right, 1);
            const glm::vec4 b = rolled.view() * glm::vec4(plain.target + right, 1);
            EXPECT_NEAR(a.x, 1.0f, 1e-5f);
            EXPECT_NEAR(b.x, 0.0f, 1e-5f);
            EXPECT_NEAR(b.y, -1.0f, 1e-5f);
            // Auto-framed, the turned view still holds every corner of the box.
            CameraOptions f;
            f.azimuth_degrees = 30.0f;
            f.elevation_degrees = elevation;
            f.up_axis = axis;
            batch::roll_view(f, 37.0f);
            const Camera framed = frame_camera(box, f, 1.5f);
            const glm::mat4 vp = framed.projection(1.5f) * framed.view();
            for (int i = 0; i < 8; ++i) {
                const glm::vec4 c = vp * glm::vec4(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1, 1);
                EXPECT_LT(std::abs(c.x / c.w), 1.0f);
                EXPECT_LT(std::abs(c.y / c.w), 1.0f);
            }
        }
}

TEST(ViewSets, BadSetsAreOneLineErrorsWithTheGrammar) {
    for (const std::string bad : {"fibonacci",
                                  "fibonacci:0",
                                  "fibonacci:3601",
                                  "fibonacci:x",
                                  "fibonacci:3:1",
                                  "ico",
                                  "ico:5",
                                  "ico:-1",
                                  "icosa:1",
                                  "random",
                                  "random:10",
                                  "random:0:1",
                                  "random:10:-1",
                                  "random:10:x",
                                  "random:10:1:roll=200",
                                  "random:10:1:dist=3-2",
                                  "random:10:1:dist=0-2",
                                  "random:10:1:zoom=2",
                                  "random:10:1:roll=1:roll=2",
                                  "orbit:8",
                                  "fibonacci:3,fibonacci:3"}) {
        try {
            parse_views(bad);
            ADD_FAILURE() << "accepted '" << bad << "'";
        } catch (const InputError& e) {
            const std::string what = e.what();
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
            EXPECT_NE(what.find("view"), std::string::npos) << what;
        }
    }
    try {
        parse_views("random:10:1:zoom=2");
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("random:N:SEED[:roll=DEG][:dist=LO-HI]"), std::string::npos);
    }
}

}  // namespace
}  // namespace inkshade
