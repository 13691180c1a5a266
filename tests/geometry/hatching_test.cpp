#include "geometry/hatching.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <tbb/global_control.h>

#include "geometry/adjacency.hpp"
#include "geometry/analytic_meshes.hpp"
#include "geometry/builtin_models.hpp"
#include "geometry/chaining.hpp"
#include "geometry/curvature.hpp"

namespace inkshade::geometry {
namespace {

struct Prepared {
    Mesh mesh;
    Curvature curvature;
    EdgeAdjacency adjacency;
};

Prepared prepare(Mesh mesh) {
    Prepared p;
    p.curvature = compute_curvature(mesh, mesh.normals);
    p.adjacency = build_edge_adjacency(mesh);
    p.mesh = std::move(mesh);
    return p;
}

Hatching hatch(const Prepared& p, const HatchOptions& options) {
    return trace_hatching(p.mesh, p.mesh.normals, p.curvature, p.adjacency, options);
}

// A cylinder's principal directions are exact: k = 1/r around it, 0 along it. Family 0 (larger
// |k|) must run round the cylinder, family 1 along it, each piece within a few degrees.
TEST(Hatching, CylinderStrokesFollowPrincipalDirections) {
    const Prepared p = prepare(test::cylinder(1.0f, 96, 61, 3.0f));
    HatchOptions o;
    o.spacing = 0.2f;
    o.levels = 1;
    const Hatching h = hatch(p, o);
    double along_axis[2] = {0.0, 0.0}, total[2] = {0.0, 0.0};
    int count[2] = {0, 0};
    for (const HatchStroke& s : h.strokes) {
        ASSERT_EQ(s.faces.size(), s.closed ? s.points.size() : s.points.size() - 1);
        ASSERT_EQ(s.edges.size(), s.points.size());
        ++count[s.family];
        for (size_t i = 0; i < s.faces.size(); ++i) {
            const glm::dvec3 d = glm::dvec3(s.points[(i + 1) % s.points.size()]) - glm::dvec3(s.points[i]);
            const double len = glm::length(d);
            total[s.family] += len;
            along_axis[s.family] += std::abs(d.z);
            // Every point on the surface.
            EXPECT_NEAR(std::hypot(s.points[i].x, s.points[i].y), 1.0, 1e-3);
        }
    }
    ASSERT_GT(count[0], 5);
    ASSERT_GT(count[1], 5);
    // Family 0: rings (|dz| small against the length); family 1: generators (|dz| ≈ length).
    EXPECT_LT(along_axis[0] / total[0], 0.02);
    EXPECT_GT(along_axis[1] / total[1], 0.98);
}

// The rings of family 0 on a cylinder close, and their heights are evenly spaced: no two
// closer than half the spacing (where tracing stops), no gap wider than twice it.
TEST(Hatching, CylinderRingsAreClosedAndEvenlySpaced) {
    const Prepared p = prepare(test::cylinder(1.0f, 128, 81, 3.0f));
    HatchOptions o;
    o.spacing = 0.25f;
    o.levels = 1;
    o.cross = false;
    const Hatching h = hatch(p, o);
    std::vector<double> heights;
    for (const HatchStroke& s : h.strokes) {
        EXPECT_EQ(s.family, 0);
        double zsum = 0.0, zmin = 1e9, zmax = -1e9;
        for (const glm::vec3& q : s.points)
            zsum += q.z, zmin = std::min(zmin, double(q.z)), zmax = std::max(zmax, double(q.z));
        EXPECT_LT(zmax - zmin, 0.05) << "a ring stays at one height";
        const double z = zsum / double(s.points.size());
        if (z > 0.1 && z < 2.9) {
            EXPECT_TRUE(s.closed) << "ring at z = " << z;
        }
        heights.push_back(z);
    }
    std::sort(heights.begin(), heights.end());
    ASSERT_GE(heights.size(), 8u);
    for (size_t i = 0; i + 1 < heights.size(); ++i) {
        EXPECT_GT(heights[i + 1] - heights[i], 0.5 * o.spacing);
        EXPECT_LT(heights[i + 1] - heights[i], 2.0 * o.spacing);
    }
    EXPECT_LT(heights.front(), 2.0 * o.spacing);
    EXPECT_GT(heights.back(), 3.0 - 2.0 * o.spacing);
}

// A finer level puts strokes between the coarser ones: on the cylinder, the level-1 rings lie
// between level-0 rings, and together they are spaced by about half the level-0 spacing.
TEST(Hatching, FinerLevelFillsBetweenCoarserStrokes) {
    const Prepared p = prepare(test::cylinder(1.0f, 128, 121, 3.0f));
    HatchOptions o;
    o.spacing = 0.3f;
    o.levels = 2;
    o.cross = false;
    const Hatching h = hatch(p, o);
    std::vector<double> level0, all;
    for (const HatchStroke& s : h.strokes) {
        double z = 0.0;
        for (const glm::vec3& q : s.points) z += q.z;
        z /= double(s.points.size());
        (s.level == 0 ? level0 : all).push_back(z);
    }
    ASSERT_FALSE(all.empty());
    for (double z : level0) all.push_back(z);
    std::sort(all.begin(), all.end());
    for (size_t i = 0; i + 1 < all.size(); ++i) {
        EXPECT_GT(all[i + 1] - all[i], 0.25 * o.spacing);
        EXPECT_LT(all[i + 1] - all[i], 1.0 * o.spacing);
    }
    // Level-0 strokes come first and keep the coarse spacing among themselves.
    std::sort(level0.begin(), level0.end());
    for (size_t i = 0; i + 1 < level0.size(); ++i) EXPECT_GT(level0[i + 1] - level0[i], 0.5 * o.spacing);
}

// On a sphere (umbilic everywhere: the field is the smoothing's), every stroke lies on the
// surface, strokes of one family and level keep at least half their spacing apart, and every
// point of the sphere has a level-0 stroke of each family within twice the spacing.
TEST(Hatching, SphereStrokesCoverEvenly) {
    const Prepared p = prepare(builtin::sphere(48, 96, 1.0f));
    HatchOptions o;
    o.spacing = 0.25f;
    o.levels = 1;
    const Hatching h = hatch(p, o);
    ASSERT_FALSE(h.strokes.empty());
    std::vector<std::vector<std::pair<glm::dvec3, size_t>>> points(2);
    for (size_t k = 0; k < h.strokes.size(); ++k)
        for (const glm::vec3& q : h.strokes[k].points) {
            EXPECT_NEAR(glm::length(q), 1.0f, 2e-3f);
            points[h.strokes[k].family].push_back({glm::dvec3(q), k});
        }
    // Node pairs of different strokes: at least ~half the spacing apart (the stop distance;
    // nodes lie on edges, so allow a little less).
    for (int fam = 0; fam < 2; ++fam) {
        const auto& pts = points[fam];
        for (size_t i = 0; i < pts.size(); ++i)
            for (size_t j = i + 1; j < pts.size(); ++j)
                if (pts[i].second != pts[j].second) {
                    ASSERT_GT(glm::distance(pts[i].first, pts[j].first), 0.45 * o.spacing) << "family " << fam;
                }
    }
    std::mt19937 rng(3);
    std::normal_distribution<double> g;
    int far_points[2] = {0, 0};
    const int samples = 400;
    for (int i = 0; i < samples; ++i) {
        const glm::dvec3 q = glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)));
        for (int fam = 0; fam < 2; ++fam) {
            double best = 1e9;
            for (const auto& [pt, k] : points[fam]) best = std::min(best, glm::distance(pt, q));
            if (best > 2.0 * o.spacing) ++far_points[fam];
        }
    }
    EXPECT_LE(far_points[0], samples / 100);
    EXPECT_LE(far_points[1], samples / 100);
}

TEST(Hatching, SameSeedSameStrokesOtherSeedOthers) {
    const Prepared p = prepare(builtin::sphere(32, 64, 1.0f));
    HatchOptions o;
    o.spacing = 0.3f;
    const Hatching a = hatch(p, o), b = hatch(p, o);
    ASSERT_EQ(a.strokes.size(), b.strokes.size());
    for (size_t i = 0; i < a.strokes.size(); ++i) EXPECT_EQ(a.strokes[i].points, b.strokes[i].points);
    o.seed = 2;
    const Hatching c = hatch(p, o);
    bool differ = c.strokes.size() != a.strokes.size();
    for (size_t i = 0; !differ && i < a.strokes.size(); ++i) differ = a.strokes[i].points != c.strokes[i].points;
    EXPECT_TRUE(differ);
}

// A view draws a piece where the Lambertian tone is below its level's threshold (fading over
// `fade`), on the side facing the viewer, and its segments chain back into the strokes.
TEST(Hatching, ViewDrawsByToneOnFrontFaces) {
    const Prepared p = prepare(builtin::sphere(48, 96, 1.0f));
    HatchOptions o;
    o.spacing = 0.2f;
    o.levels = 1;
    const Hatching h = hatch(p, o);
    Camera cam;
    cam.eye = {0.0f, 0.0f, 5.0f};
    cam.target = {0.0f, 0.0f, 0.0f};
    cam.up = {0.0f, 1.0f, 0.0f};
    HatchView view;
    view.light = glm::normalize(glm::vec3(1.0f, 0.0f, 0.0f));
    view.thresholds = {0.5f, 0.2f};
    view.fade = 0.05f;
    const std::vector<LineSegment> segs = hatch_segments(p.mesh, p.mesh.normals, h, cam, view);
    ASSERT_FALSE(segs.empty());
    size_t family1 = 0;
    for (const LineSegment& s : segs) {
        // On a unit sphere the normal is the position: tone = x.
        const float tone_a = std::clamp(s.a.x, 0.0f, 1.0f), tone_b = std::clamp(s.b.x, 0.0f, 1.0f);
        EXPECT_TRUE(tone_a < 0.5f + 0.01f || tone_b < 0.5f + 0.01f);
        // Seen from z = 5, the unit sphere faces the eye where z > 1/5.
        EXPECT_TRUE(s.a.z > 0.19f || s.b.z > 0.19f) << "a back-facing piece";
        // The strength is one of the two families' fades.
        for (const auto& [tone, strength] : {std::pair{tone_a, s.strength_a}, std::pair{tone_b, s.strength_b}}) {
            const float f0 = std::clamp((0.5f - tone) / 0.05f, 0.0f, 1.0f),
                        f1 = std::clamp((0.2f - tone) / 0.05f, 0.0f, 1.0f);
            EXPECT_TRUE(std::abs(strength - f0) < 0.1f || std::abs(strength - f1) < 0.1f) << tone << " " << strength;
        }
        if (std::max(tone_a, tone_b) < 0.15f) ++family1;  // dark enough for both families
    }
    EXPECT_GT(family1, 0u);
    // Every front piece of family 0 darker than the threshold less the fade is drawn.
    size_t expected = 0;
    for (const HatchStroke& s : h.strokes) {
        if (s.family != 0) continue;
        for (size_t i = 0; i < s.faces.size(); ++i) {
            const glm::vec3 a = s.points[i], b = s.points[(i + 1) % s.points.size()];
            if (a.z > 0.25f && b.z > 0.25f && std::max(a.x, b.x) < 0.44f) ++expected;
        }
    }
    size_t drawn0 = 0;
    for (const LineSegment& s : segs)
        if (s.a.z > 0.25f && s.b.z > 0.25f && std::max(s.a.x, s.b.x) < 0.44f && std::min(s.a.x, s.b.x) >= 0.2f)
            ++drawn0;
    size_t expected_light = 0;
    for (const HatchStroke& s : h.strokes) {
        if (s.family != 0) continue;
        for (size_t i = 0; i < s.faces.size(); ++i) {
            const glm::vec3 a = s.points[i], b = s.points[(i + 1) % s.points.size()];
            if (a.z > 0.25f && b.z > 0.25f && std::max(a.x, b.x) < 0.44f && std::min(a.x, b.x) >= 0.2f)
                ++expected_light;
        }
    }
    EXPECT_GT(expected, 0u);
    EXPECT_EQ(drawn0, expected_light) << "between the two thresholds only family 0 draws, all of it";
    // The segments chain into polylines along the strokes: no node shared by three pieces.
    const std::vector<Chain> chains = chain_order(segs);
    size_t pieces = 0;
    for (const Chain& c : chains) pieces += c.segments.size();
    EXPECT_EQ(pieces, segs.size());
}

// Finer levels thin out towards the outline: with only level 1 drawn (tone threshold above
// every tone), no piece remains where n·v < thin at both ends; with thin = 0 some do.
TEST(Hatching, FinerLevelsFadeOutWhereTheSurfaceTurnsAway) {
    const Prepared p = prepare(builtin::sphere(48, 96, 1.0f));
    HatchOptions o;
    o.spacing = 0.3f;
    o.levels = 2;
    o.cross = false;
    const Hatching h = hatch(p, o);
    Camera cam;
    cam.eye = {0.0f, 0.0f, 5.0f};
    cam.target = {0.0f, 0.0f, 0.0f};
    cam.up = {0.0f, 1.0f, 0.0f};
    const ViewVector v(cam);
    auto grazing = [&](const glm::vec3& q) { return glm::dot(glm::dvec3(glm::normalize(q)), v.at(q)) < 0.25; };
    HatchView view;
    view.thresholds = {0.0f, 1.1f};
    view.thin = 0.0f;
    size_t near_outline = 0;
    for (const LineSegment& s : hatch_segments(p.mesh, p.mesh.normals, h, cam, view))
        near_outline += grazing(s.a) && grazing(s.b);
    EXPECT_GT(near_outline, 10u);
    view.thin = 0.25f;
    const std::vector<LineSegment> thinned = hatch_segments(p.mesh, p.mesh.normals, h, cam, view);
    ASSERT_FALSE(thinned.empty());
    for (const LineSegment& s : thinned) EXPECT_FALSE(grazing(s.a) && grazing(s.b));
}

// The field averages crosses, not vectors: on a flat grid whose principal directions alternate
// between x and y (the same cross), smoothing leaves every direction on an axis; averaging
// them as vectors would turn them to the diagonals.
TEST(Hatching, DirectionFieldAveragesCrossesNotVectors) {
    Mesh grid;
    const int n = 12;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            grid.positions.push_back({float(i), float(j), 0.0f});
            grid.normals.push_back({0.0f, 0.0f, 1.0f});
        }
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            const uint32_t a = uint32_t(j * n + i), b = a + 1, c = a + uint32_t(n), d = c + 1;
            grid.triangles.push_back({a, b, d});
            grid.triangles.push_back({a, d, c});
        }
    Curvature k;
    for (int v = 0; v < n * n; ++v) {
        const bool along_x = (v + v / n) % 2 == 0;
        k.pdir1.push_back(along_x ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0));
        k.pdir2.push_back(along_x ? glm::vec3(0, 1, 0) : glm::vec3(-1, 0, 0));
        k.k1.push_back(1.0f);
        k.k2.push_back(0.0f);
    }
    const std::vector<glm::vec3> field = hatch_direction_field(grid, grid.normals, k, 20);
    for (const glm::vec3& d : field) {
        EXPECT_NEAR(glm::length(d), 1.0f, 1e-5f);
        EXPECT_LT(std::min(std::abs(d.x), std::abs(d.y)), 0.02f) << d.x << ", " << d.y;
    }
}

void expect_same_strokes(const Hatching& a, const Hatching& b) {
    ASSERT_EQ(a.strokes.size(), b.strokes.size());
    for (size_t i = 0; i < a.strokes.size(); ++i) {
        const HatchStroke &s = a.strokes[i], &t = b.strokes[i];
        EXPECT_EQ(s.points, t.points) << "stroke " << i;
        EXPECT_EQ(s.faces, t.faces) << "stroke " << i;
        EXPECT_EQ(s.edges, t.edges) << "stroke " << i;
        EXPECT_EQ(s.t, t.t) << "stroke " << i;
        EXPECT_EQ(s.family, t.family);
        EXPECT_EQ(s.level, t.level);
        EXPECT_EQ(s.closed, t.closed);
    }
}

Hatching hatch_on_threads(const Prepared& p, const HatchOptions& o, size_t threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    return hatch(p, o);
}

// The families are traced on threads of their own and the field's rounds split between
// threads: the strokes must not depend on how many there are.
TEST(Hatching, SameStrokesOnOneTwoAndFourThreads) {
    // Over 2 × 4096 vertices, so the field's rounds are split into several ranges.
    const Prepared p = prepare(builtin::teapot(16));
    ASSERT_GT(p.mesh.positions.size(), 8192u);
    HatchOptions o;
    o.smoothing = 30;
    o.density = 0.5f;
    const Hatching one = hatch_on_threads(p, o, 1);
    ASSERT_GT(one.strokes.size(), 100u);
    expect_same_strokes(one, hatch_on_threads(p, o, 2));
    expect_same_strokes(one, hatch_on_threads(p, o, 4));
}

// The families never meet: with cross-hatching, the first family's strokes are exactly those
// traced without it, and come first; the second family follows.
TEST(Hatching, FirstFamilyIsTheSameWithAndWithoutCrossHatching) {
    const Prepared p = prepare(builtin::torus(1.0f, 0.4f, 96, 48));
    HatchOptions o;
    o.spacing = 0.12f;
    o.cross = false;
    const Hatching alone = hatch(p, o);
    o.cross = true;
    Hatching both = hatch(p, o);
    ASSERT_GT(both.strokes.size(), alone.strokes.size());
    for (size_t i = 0; i < both.strokes.size(); ++i)
        EXPECT_EQ(both.strokes[i].family, i < alone.strokes.size() ? 0 : 1) << "stroke " << i;
    both.strokes.resize(alone.strokes.size());
    expect_same_strokes(alone, both);
}

TEST(Hatching, DegenerateInputDoesNotCrash) {
    Mesh empty;
    const Hatching h0 = trace_hatching(empty, {}, Curvature{}, EdgeAdjacency{});
    EXPECT_TRUE(h0.strokes.empty());
    // Out-of-range and repeated indices, a zero-area face, NaN normal.
    Prepared p = prepare(builtin::sphere(8, 16, 1.0f));
    p.mesh.triangles.push_back({0, 0, 1});
    p.mesh.triangles.push_back({0, 1, 99999});
    p.mesh.positions.push_back(p.mesh.positions[0]);
    p.mesh.normals.push_back(glm::vec3(NAN));
    p.curvature = compute_curvature(p.mesh, p.mesh.normals);
    p.adjacency = build_edge_adjacency(p.mesh);
    HatchOptions o;
    o.spacing = 0.3f;
    const Hatching h = hatch(p, o);
    EXPECT_FALSE(h.strokes.empty());
    EXPECT_THROW(trace_hatching(p.mesh, {}, p.curvature, p.adjacency, o), std::invalid_argument);
}

}  // namespace
}  // namespace inkshade::geometry
