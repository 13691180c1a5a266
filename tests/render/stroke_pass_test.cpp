// StrokePass: anti-aliased capsule strokes of polylines in image pixels. Pixels whose centres
// lie well inside the stroke are fully covered, well outside untouched, on the border about
// half covered; the join of an L has no gap and, at half opacity, is not blended twice; the
// taper narrows the stroke; strokes behind the depth buffer are hidden; per-point widths and
// colours (the layer's stroke modifiers) and butt and square caps.
#include <cmath>

#include "gpu/framebuffer.hpp"
#include "render/render_fixture.hpp"
#include "render/stroke_pass.hpp"

namespace inkshade::test {
namespace {

constexpr int kW = 64;

float distance_to_path(glm::vec2 p, const std::vector<glm::vec2>& pts) {
    float d = INFINITY;
    for (size_t i = 0; i + 1 < pts.size(); ++i) {
        glm::vec2 a = pts[i], ab = pts[i + 1] - a;
        float t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
        d = std::min(d, glm::length(p - (a + t * ab)));
    }
    return d;
}

// Draws `paths` black on white into a kW x kW framebuffer whose depth is cleared to `depth`.
Image draw(const std::vector<LinePath>& paths, const render::StrokeStyle& style, int samples = 4, float depth = 1.0f) {
    shared_renderer();  // a current context
    gpu::Framebuffer fb(kW, kW, samples);
    fb.bind();
    glClearColor(1, 1, 1, 1);
    glClearDepth(depth);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    render::StrokePass pass;
    pass.draw(paths, style, kW, kW, samples);
    fb.resolve();
    return fb.read(false);
}

LinePath path(std::vector<glm::vec2> pts) {
    LinePath p;
    p.points = std::move(pts);
    return p;
}

TEST(StrokePass, CoverageMatchesAnalyticDistance) {
    const std::vector<glm::vec2> pts = {{10, 10}, {50, 10}, {50, 50}};
    render::StrokeStyle style;
    style.width = 5.0f;
    for (int samples : {1, 4}) {
        Image img = draw({path(pts)}, style, samples);
        int inside = 0, outside = 0, border = 0;
        double border_sum = 0.0;
        for (int y = 0; y < kW; ++y)
            for (int x = 0; x < kW; ++x) {
                const float d = distance_to_path({x + 0.5f, y + 0.5f}, pts);
                const int v = img.pixel(x, y)[0];
                if (d < 2.5f - 0.75f) {
                    EXPECT_LE(v, 5) << "uncovered inside at " << x << "," << y << " samples " << samples;
                    ++inside;
                } else if (d > 2.5f + 0.75f) {
                    EXPECT_GE(v, 250) << "covered outside at " << x << "," << y << " samples " << samples;
                    ++outside;
                } else if (std::abs(d - 2.5f) < 0.05f) {
                    // A pixel centre on the stroke's edge: about half covered.
                    EXPECT_NEAR(v, 128, 70) << "border pixel " << x << "," << y << " samples " << samples;
                    border_sum += v;
                    ++border;
                }
            }
        EXPECT_GT(inside, 150);
        ASSERT_GT(border, 20);
        // Half covered on average: the edge is where the width puts it (a stroke 0.05 px too
        // wide or narrow moves the mean by about 13).
        EXPECT_NEAR(border_sum / border, 127.5, 8.0) << "samples " << samples;  // measured 126-130
    }
}

// With MSAA the stencil lets each sample take the colour once: the round join and the
// overlapping segment ends are as grey as the straight parts at half opacity.
TEST(StrokePass, HalfOpacityJoinIsNotBlendedTwice) {
    render::StrokeStyle style;
    style.width = 6.0f;
    style.opacity = 0.5f;
    Image img = draw({path({{10, 10}, {50, 10}, {50, 50}})}, style);
    const int straight = img.pixel(30, 10)[0];
    EXPECT_NEAR(straight, 128, 3);
    EXPECT_NEAR(int(img.pixel(50, 10)[0]), straight, 2);  // the join
    EXPECT_NEAR(int(img.pixel(49, 11)[0]), straight, 2);
}

TEST(StrokePass, StrengthTapersWidth) {
    LinePath p = path({{8, 32}, {56, 32}});
    p.strength = {1.0f, 0.2f};
    render::StrokeStyle style;
    style.width = 10.0f;
    Image img = draw({p}, style);
    // Half-width 5 at x = 8, 1 at x = 56: at x = 12 rows 28..35 are covered, at x = 52 only 31..32.
    EXPECT_LE(int(img.pixel(12, 28)[0]), 5);
    EXPECT_GE(int(img.pixel(52, 28)[0]), 250);
    EXPECT_LE(int(img.pixel(52, 31)[0]), 60);
}

TEST(StrokePass, DepthTestHidesStrokesBehindTheSurface) {
    LinePath p = path({{8, 32}, {56, 32}});
    p.depth = {0.6f, 0.6f};
    render::StrokeStyle style;
    style.width = 4.0f;
    EXPECT_GE(int(draw({p}, style, 4, 0.5f).pixel(32, 32)[0]), 250);  // behind: hidden
    EXPECT_LE(int(draw({p}, style, 4, 0.7f).pixel(32, 32)[0]), 5);    // in front: drawn
    // Lying on the surface (equal depth): the bias keeps it visible.
    EXPECT_LE(int(draw({p}, style, 4, 0.6f).pixel(32, 32)[0]), 5);
}

TEST(StrokePass, PerPointWidthsAndColours) {
    LinePath p = path({{8, 32}, {56, 32}});
    p.width = {12.0f, 2.0f};  // radius 6 → 1
    p.color = {glm::vec3(1, 0, 0), glm::vec3(0, 0, 1)};
    render::StrokeStyle style;
    style.width = 40.0f;  // the path's own widths win
    const Image img = draw({p}, style);
    // At x = 12.5 the radius is 6 - 5 × 4.5 / 48 = 5.53: row 27 (centre 27.5, 4.5 away) covered.
    EXPECT_LE(int(img.pixel(12, 27)[1]), 5);
    EXPECT_GE(int(img.pixel(12, 25)[1]), 250);
    EXPECT_GE(int(img.pixel(52, 28)[1]), 250) << "near the thin end";
    // Red at the start, blue at the end, a blend between.
    const uint8_t* a = img.pixel(10, 32);
    EXPECT_GE(int(a[0]), 240);
    EXPECT_LE(int(a[2]), 20);
    const uint8_t* b = img.pixel(54, 32);
    EXPECT_LE(int(b[0]), 20);
    EXPECT_GE(int(b[2]), 240);
    const uint8_t* m = img.pixel(32, 32);  // half way: equal parts (whatever the encoding)
    EXPECT_NEAR(int(m[0]), int(m[2]), 8);
    EXPECT_GT(int(m[0]), 60);
    EXPECT_LT(int(m[0]), 200);
}

TEST(StrokePass, ButtAndSquareCapsEndTheStrokeFlat) {
    const LinePath p = path({{20, 32}, {44, 32}});
    render::StrokeStyle style;
    style.width = 10.0f;
    // Round: the cap reaches 5 px past each end; butt: nothing past the ends; square: a full
    // 5 px past them, corners included.
    const Image round = draw({p}, style);
    style.cap = geometry::StrokeCap::Butt;
    const Image butt = draw({p}, style);
    style.cap = geometry::StrokeCap::Square;
    const Image square = draw({p}, style);
    EXPECT_LE(int(round.pixel(17, 32)[0]), 5);
    EXPECT_GE(int(round.pixel(15, 27)[0]), 250) << "the round cap's corner is empty";
    EXPECT_GE(int(butt.pixel(19, 32)[0]), 250);
    EXPECT_GE(int(butt.pixel(44, 32)[0]), 250);
    EXPECT_LE(int(butt.pixel(20, 32)[0]), 5);
    EXPECT_LE(int(butt.pixel(43, 28)[0]), 5);
    EXPECT_LE(int(square.pixel(15, 27)[0]), 5) << "the square cap's corner is full";
    EXPECT_LE(int(square.pixel(47, 35)[0]), 5);
    EXPECT_GE(int(square.pixel(14, 32)[0]), 250);
    EXPECT_GE(int(square.pixel(49, 32)[0]), 250);
}

}  // namespace
}  // namespace inkshade::test

namespace inkshade::test {
namespace {

// A right angle at (40, 20) of a stroke 12 px wide (right along y = 20, then down x = 40): the
// outer corner of the two segments' edges is (46, 14), the miter's tip (a miter sqrt 2 x the
// width long is within the limit 4). A round join reaches 6 px from the vertex, so the pixel
// centred at (45.5, 14.5), 7.8 px away, is empty; a miter covers it; a bevel cuts the corner
// along x - y = 26 through (40, 14) and (46, 20), and that pixel lies 3.5 px beyond the cut.
TEST(StrokePass, MiterAndBevelJoinsFillTheCornerAsSvgDoes) {
    const LinePath p = path({{10, 20}, {40, 20}, {40, 50}});
    render::StrokeStyle style;
    style.width = 12.0f;
    for (int samples : {1, 4}) {
        const Image round = draw({p}, style, samples);
        style.join = geometry::StrokeJoin::Miter;
        const Image miter = draw({p}, style, samples);
        style.join = geometry::StrokeJoin::Bevel;
        const Image bevel = draw({p}, style, samples);
        style.join = geometry::StrokeJoin::Round;
        EXPECT_GE(int(round.pixel(45, 14)[0]), 250) << "round join reaches the corner, samples " << samples;
        EXPECT_LE(int(miter.pixel(45, 14)[0]), 5) << "miter misses the corner, samples " << samples;
        EXPECT_LE(int(miter.pixel(44, 15)[0]), 5) << "miter misses the corner, samples " << samples;
        EXPECT_GE(int(miter.pixel(47, 13)[0]), 250) << "miter beyond its tip, samples " << samples;
        EXPECT_GE(int(bevel.pixel(45, 14)[0]), 250) << "bevel fills beyond its cut, samples " << samples;
        // Inside the bevel's triangle (40,20)-(46,20)-(40,14): near the cut, on the vertex side.
        EXPECT_LE(int(bevel.pixel(41, 17)[0]), 5) << "bevel leaves a gap, samples " << samples;
        // No seam where the join meets its segments: every pixel well inside the stroke is full.
        for (const Image* img : {&miter, &bevel})
            for (int y = 15; y < 50; ++y)
                for (int x = 10; x < 46; ++x) {
                    const bool in_h = x >= 11 && x <= 38 && y >= 15 && y <= 24;
                    const bool in_v = x >= 35 && x <= 44 && y >= 22 && y <= 48;
                    if (in_h || in_v) {
                        EXPECT_LE(int(img->pixel(x, y)[0]), 5) << x << "," << y << " samples " << samples;
                    }
                }
    }
}

// A miter longer than SVG's limit (4 x the width: a turn sharper than about 151 degrees) is
// drawn as a bevel, and a straight run of collinear points gets no join at all.
TEST(StrokePass, SharpMiterFallsBackToBevel) {
    // A hairpin: in along +x, out turned by 165 degrees (cos 82.5 degrees < 1/4: over the limit).
    const float a = glm::radians(165.0f);
    const glm::vec2 v(40, 32), out = v + 30.0f * glm::vec2(std::cos(a), std::sin(a));
    const LinePath p = path({{10, 32}, v, out});
    render::StrokeStyle style;
    style.width = 6.0f;
    style.join = geometry::StrokeJoin::Miter;
    const Image miter = draw({p}, style);
    style.join = geometry::StrokeJoin::Bevel;
    const Image bevel = draw({p}, style);
    for (int y = 0; y < kW; ++y)
        for (int x = 0; x < kW; ++x) EXPECT_EQ(int(miter.pixel(x, y)[0]), int(bevel.pixel(x, y)[0])) << x << "," << y;
    // Nothing past the vertex along +x beyond the stroke's flat end and its bevel (3 px out).
    EXPECT_GE(int(miter.pixel(46, 32)[0]), 250);
}

}  // namespace
}  // namespace inkshade::test
