#include "geometry/chaining.hpp"
#include "geometry/key_numbering.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace inkshade::geometry {
namespace {

LineSegment seg(glm::vec3 a, glm::vec3 b, uint64_t ka, uint64_t kb, float sa = 1.0f, float sb = 1.0f) {
    LineSegment s;
    s.a = a;
    s.b = b;
    s.edge_a = ka;
    s.edge_b = kb;
    s.strength_a = sa;
    s.strength_b = sb;
    return s;
}

TEST(Chaining, StrengthTravelsWithItsPointThroughReversal) {
    // As in ChainsFollowSegmentDirection: the walk starts at segment 1's b end and is reversed.
    std::vector<LineSegment> segs = {seg({1, 0, 0}, {2, 0, 0}, 11, 12, 0.1f, 0.2f),
                                     seg({2, 0, 0}, {3, 0, 0}, 12, 13, 0.2f, 0.3f),
                                     seg({0, 0, 0}, {1, 0, 0}, 10, 11, 0.0f, 0.1f)};
    const auto lines = chain_segments(segs);
    ASSERT_EQ(lines.size(), 1u);
    ASSERT_EQ(lines[0].points.size(), 4u);
    ASSERT_EQ(lines[0].strength.size(), 4u);
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(lines[0].points[i], glm::vec3(float(i), 0, 0));
        EXPECT_FLOAT_EQ(lines[0].strength[i], 0.1f * float(i));
    }
}

TEST(Chaining, VertexKeysChainEdgeLinesAndJunctionsSplitThem) {
    // A unit square of four mesh edges (vertex nodes 0..3) is one closed loop.
    const glm::vec3 p[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    std::vector<LineSegment> square;
    for (uint32_t i = 0; i < 4; ++i)
        square.push_back(seg(p[i], p[(i + 1) % 4], vertex_key(i), vertex_key((i + 1) % 4), 0.5f, 0.5f));
    const auto loop = chain_segments(square);
    ASSERT_EQ(loop.size(), 1u);
    EXPECT_TRUE(loop[0].closed);
    EXPECT_EQ(loop[0].points.size(), 4u);
    EXPECT_EQ(loop[0].strength, std::vector<float>(4, 0.5f));
    EXPECT_FLOAT_EQ(polyline_length(loop[0]), 4.0f);
    // A spur at vertex 1 makes it a junction of degree three: three open chains.
    square.push_back(seg(p[1], {2, 0, 0}, vertex_key(1), vertex_key(4)));
    const auto split = chain_segments(square);
    ASSERT_EQ(split.size(), 2u);  // 1→2→3→0→1 runs from the junction back to it, plus the spur
    for (const auto& l : split) EXPECT_FALSE(l.closed);
    // Vertex keys never collide with edge keys or face-interior keys.
    EXPECT_NE(vertex_key(3), edge_key(3, 4));
    EXPECT_NE(face_interior_key(3, 0), edge_key(3, 3));
    EXPECT_NE(face_interior_key(3, 0), face_interior_key(3, 1));
}

TEST(Chaining, ChainOrderMarksWholeComponents) {
    // An open run with two free ends and a closed loop are whole components; the three chains
    // meeting at a junction (node 20, degree three) are not: with one of them hidden, the other
    // two would join into one polyline.
    const std::vector<LineSegment> segs = {
        seg({0, 0, 0}, {1, 0, 0}, 1, 2), seg({1, 0, 0}, {2, 0, 0}, 2, 3),                                   // run
        seg({0, 1, 0}, {1, 1, 0}, 10, 11), seg({1, 1, 0}, {1, 2, 0}, 11, 12), seg({1, 2, 0}, {0, 1, 0}, 12, 10),  // loop
        seg({5, 0, 0}, {6, 0, 0}, 21, 20), seg({6, 0, 0}, {7, 0, 0}, 20, 22), seg({6, 0, 0}, {6, 1, 0}, 20, 23)};
    const std::vector<Chain> chains = chain_order(segs);
    ASSERT_EQ(chains.size(), 5u);
    int whole = 0, at_junction = 0;
    for (const Chain& c : chains) {
        const bool junction = c.segments[0] >= 5;
        EXPECT_EQ(c.component, !junction) << "chain from segment " << c.segments[0];
        (junction ? at_junction : whole) += 1;
        EXPECT_EQ(c.closed, c.segments[0] >= 2 && c.segments[0] <= 4);
    }
    EXPECT_EQ(whole, 2);
    EXPECT_EQ(at_junction, 3);
}

TEST(Chaining, NumbersManyKeysInOrderOfFirstInsertion) {
    // More keys than the table was sized for (it grows), neighbouring and far-apart keys mixed.
    KeyNumbering numbers(4);
    std::vector<uint64_t> keys;
    for (uint32_t i = 0; i < 5000; ++i) keys.push_back(i % 2 ? edge_key(i, i + 1) : (uint64_t(i) << 40) | 7u);
    for (uint32_t i = 0; i < keys.size(); ++i) ASSERT_EQ(numbers.insert(keys[i]), i);
    for (uint32_t i = 0; i < keys.size(); ++i) ASSERT_EQ(numbers.insert(keys[i]), i);  // found again
    EXPECT_EQ(numbers.size(), keys.size());
    EXPECT_EQ(numbers.insert(~uint64_t(0)), keys.size());  // any 64-bit value is a key
}

// Two isolines crossing the same edges (keys 1, 2, 3): each is its own chain, where one key
// space would make nodes of degree four that end every chain.
TEST(Chaining, IsolinesSharingEdgeKeysChainApart) {
    std::vector<LineSegment> segs;
    for (uint32_t isoline : {0u, 1u}) {
        const float y = 0.1f * float(isoline);
        for (uint64_t k = 1; k <= 2; ++k) {
            segs.push_back(seg({float(k - 1), y, 0}, {float(k), y, 0}, k, k + 1));
            segs.back().isoline = isoline;
        }
    }
    std::swap(segs[1], segs[2]);  // interleaved
    const auto lines = chain_segments(segs);
    ASSERT_EQ(lines.size(), 2u);
    for (const Polyline& line : lines) {
        ASSERT_EQ(line.points.size(), 3u);
        for (const glm::vec3& p : line.points) EXPECT_EQ(p.y, line.points[0].y) << "points of one isoline only";
    }
    KeyNumbering numbers(4);
    EXPECT_EQ(numbers.insert(7, 0), 0u);
    EXPECT_EQ(numbers.insert(7, 1), 1u);
    EXPECT_EQ(numbers.insert(7), 0u);
}

TEST(Chaining, FaceInteriorKeysEndChains) {
    // Two segments meeting on edge key 5; the outer ends are cut inside faces 0 and 1.
    const std::vector<LineSegment> segs = {seg({0, 0, 0}, {1, 0, 0}, face_interior_key(0, 0), 5, 0.0f, 1.0f),
                                           seg({1, 0, 0}, {2, 0, 0}, 5, face_interior_key(1, 1), 1.0f, 0.0f)};
    const auto lines = chain_segments(segs);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_FALSE(lines[0].closed);
    EXPECT_EQ(lines[0].points.size(), 3u);
    EXPECT_EQ(lines[0].strength, (std::vector<float>{0.0f, 1.0f, 0.0f}));
}

TEST(Chaining, DropShortRemovesOnlyShortChainsAndKeepsOrder) {
    Polyline a, b, c, loop;
    a.points = {{0, 0, 0}, {0.3f, 0, 0}};                      // 0.3
    b.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};              // 2
    c.points = {{0, 0, 0}};                                    // 0
    loop.points = {{0, 0, 0}, {0.4f, 0, 0}, {0.4f, 0.4f, 0}};  // 0.4 + 0.4 + 0.566 closed
    loop.closed = true;
    EXPECT_FLOAT_EQ(polyline_length(a), 0.3f);
    EXPECT_NEAR(polyline_length(loop), 0.8f + 0.4f * std::sqrt(2.0f), 1e-6f);
    const auto kept = drop_short({a, b, c, loop}, 1.0f);
    ASSERT_EQ(kept.size(), 2u);
    EXPECT_EQ(kept[0].points, b.points);
    EXPECT_EQ(kept[1].points, loop.points);  // long only with its closing step
    EXPECT_EQ(drop_short({a, b, c, loop}, 0.0f).size(), 4u);
    EXPECT_TRUE(drop_short({}, 1.0f).empty());
}

TEST(Chaining, SmoothingKeepsOpenEndsAndFlattensZigzag) {
    Polyline zig;
    for (int i = 0; i <= 20; ++i) {
        zig.points.emplace_back(float(i), i % 2 ? 0.1f : -0.1f, 0.0f);
        zig.strength.push_back(float(i));
    }
    std::vector<Polyline> lines = {zig};
    smooth_polylines(lines, 10);
    const auto& p = lines[0].points;
    ASSERT_EQ(p.size(), zig.points.size());
    EXPECT_EQ(p.front(), zig.points.front());  // ends fixed, bit for bit
    EXPECT_EQ(p.back(), zig.points.back());
    for (size_t i = 5; i + 5 < p.size(); ++i) EXPECT_LT(std::abs(p[i].y), 0.01f) << i;  // was ±0.1
    EXPECT_EQ(lines[0].strength, zig.strength);
    // A closed loop has no fixed point: every point moves, the centroid stays.
    Polyline square;
    square.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    square.closed = true;
    std::vector<Polyline> loops = {square};
    smooth_polylines(loops, 1);
    glm::vec3 centroid(0.0f);
    for (size_t i = 0; i < 4; ++i) {
        EXPECT_NE(loops[0].points[i], square.points[i]);
        centroid += 0.25f * loops[0].points[i];
    }
    EXPECT_NEAR(glm::distance(centroid, glm::vec3(0.5f, 0.5f, 0.0f)), 0.0f, 1e-6f);
    // Zero iterations and two-point chains are left alone.
    std::vector<Polyline> same = {zig};
    smooth_polylines(same, 0);
    EXPECT_EQ(same[0].points, zig.points);
    Polyline two;
    two.points = {{0, 0, 0}, {1, 1, 1}};
    std::vector<Polyline> twos = {two};
    smooth_polylines(twos, 5);
    EXPECT_EQ(twos[0].points, two.points);
}

}  // namespace
}  // namespace inkshade::geometry
