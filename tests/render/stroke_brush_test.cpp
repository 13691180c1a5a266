// Brushes of GPU strokes (StrokePass with StrokeStyle::brush): the texture repeats every brush
// length of arc length along the stroke, runs on across the joins of a polyline (many short
// segments draw what one long one draws), multiplies the coverage without widening or
// narrowing the stroke, and a brush of full texels draws the solid stroke.
#include <cmath>

#include "gpu/framebuffer.hpp"
#include "render/brush_texture.hpp"
#include "render/render_fixture.hpp"
#include "render/stroke_pass.hpp"

namespace inkshade::test {
namespace {

constexpr int kW = 256, kH = 32;
constexpr float kPi = 3.14159265f;

// Draws `paths` black on white into a kW x kH framebuffer.
Image draw(const std::vector<LinePath>& paths, const render::StrokeStyle& style, int samples = 4) {
    shared_renderer();  // a current context
    gpu::Framebuffer fb(kW, kH, samples);
    fb.bind();
    glClearColor(1, 1, 1, 1);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    render::StrokePass pass;
    pass.draw(paths, style, kW, kH, samples);
    fb.resolve();
    return fb.read(false);
}

LinePath path(std::vector<glm::vec2> pts) {
    LinePath p;
    p.points = std::move(pts);
    return p;
}

// A brush whose every column is 0.5 + 0.5 cos(2 pi u): one period per repeat, darkest at u = 0.
render::BrushImage cosine_brush() {
    render::BrushImage b;
    b.width = 64;
    b.height = 4;
    b.grey.resize(size_t(b.width) * b.height);
    for (int y = 0; y < b.height; ++y)
        for (int x = 0; x < b.width; ++x)
            b.grey[size_t(y) * b.width + x] =
                uint8_t(std::lround(255 * (0.5 + 0.5 * std::cos(2 * kPi * (x + 0.5f) / 64))));
    return b;
}

// Coverage (1 = black) along row y for x in [x0, x1).
std::vector<float> coverage_row(const Image& img, int y, int x0, int x1) {
    std::vector<float> c;
    for (int x = x0; x < x1; ++x) c.push_back(1.0f - img.pixel(x, y)[0] / 255.0f);
    return c;
}

// The lag in [lo, hi] at which the profile best matches itself shifted (least mean square difference).
int best_period(const std::vector<float>& c, int lo, int hi) {
    int best = 0;
    double best_err = INFINITY;
    for (int lag = lo; lag <= hi; ++lag) {
        double err = 0.0;
        for (size_t i = 0; i + lag < c.size(); ++i) err += (c[i] - c[i + lag]) * (c[i] - c[i + lag]);
        err /= double(c.size() - lag);
        if (err < best_err) best_err = err, best = lag;
    }
    return best;
}

TEST(StrokeBrush, CoverageAlongTheCentreRepeatsWithTheBrushLength) {
    const render::BrushImage brush = cosine_brush();
    for (float length : {18.0f, 30.0f}) {
        render::StrokeStyle style;
        style.width = 8.0f;
        style.brush = &brush;
        style.brush_length = length;
        // Starts at x = 8 so that s = x + 0.5 - 8 at pixel centres.
        const Image img = draw({path({{8, 16}, {248, 16}})}, style);
        const std::vector<float> c = coverage_row(img, 16, 16, 240);
        EXPECT_EQ(best_period(c, 10, 40), int(length)) << "brush length " << length;
        // The profile is the cosine of the arc length: it correlates with it, in phase.
        double dot = 0.0, cc = 0.0, kk = 0.0, mean = 0.0;
        for (float v : c) mean += v;
        mean /= c.size();
        for (size_t i = 0; i < c.size(); ++i) {
            const float s = 16 + i + 0.5f - 8;
            const double k = std::cos(2 * kPi * s / length);
            dot += (c[i] - mean) * k, cc += (c[i] - mean) * (c[i] - mean), kk += k * k;
        }
        EXPECT_GT(dot / std::sqrt(cc * kk), 0.97) << "brush length " << length;
        const auto [lo, hi] = std::minmax_element(c.begin(), c.end());
        EXPECT_GT(*hi - *lo, 0.6f) << "the pattern is drawn";
    }
}

// A coherent stroke (LinePath::u, docs/lines.md "Temporal coherence") reads the brush at its u,
// not at its own arc length: with u = 7 + s the profile is the cosine of s + 7, and it no longer
// matches the cosine of s.
TEST(StrokeBrush, CoherentStrokeReadsTheBrushAtItsParameter) {
    const render::BrushImage brush = cosine_brush();
    render::StrokeStyle style;
    style.width = 8.0f;
    style.brush = &brush;
    const float length = 28.0f, offset = 7.0f;
    style.brush_length = length;
    LinePath p = path({{8, 16}, {248, 16}});
    p.u = {offset, offset + 240.0f};
    const std::vector<float> c = coverage_row(draw({p}, style), 16, 16, 240);
    auto correlation = [&](float shift) {
        double dot = 0.0, cc = 0.0, kk = 0.0, mean = 0.0;
        for (float v : c) mean += v;
        mean /= double(c.size());
        for (size_t i = 0; i < c.size(); ++i) {
            const float s = 16 + float(i) + 0.5f - 8;
            const double k = std::cos(2 * kPi * (s + shift) / length);
            dot += (c[i] - mean) * k, cc += (c[i] - mean) * (c[i] - mean), kk += k * k;
        }
        return dot / std::sqrt(cc * kk);
    };
    EXPECT_GT(correlation(offset), 0.97);
    EXPECT_LT(correlation(0.0f), 0.5) << "a quarter period out of phase";
}

// 30 segments of 8 px along the same line: the arc length runs on at every joint, so the
// coverage is that of the single segment (restarting the texture per segment would make the
// period 8 px). With MSAA (the default) a sample is covered once per draw; single-sampled, the
// overlapping ends of segments blend twice wherever the alpha is below 1, a brush's as an
// opacity's, so there a 4 px stroke's pixels half way between joints (beyond the other
// segments' round ends) compare.
TEST(StrokeBrush, PatternRunsOnAcrossSegmentJoints) {
    const render::BrushImage brush = cosine_brush();
    render::StrokeStyle style;
    style.width = 8.0f;
    style.brush = &brush;
    style.brush_length = 22.0f;
    std::vector<glm::vec2> many;
    for (int i = 0; i <= 30; ++i) many.push_back({8.0f + 8.0f * i, 16.0f});
    for (int samples : {1, 4}) {
        style.width = samples == 1 ? 4.0f : 8.0f;
        const std::vector<float> one = coverage_row(draw({path({{8, 16}, {248, 16}})}, style, samples), 16, 12, 244);
        const std::vector<float> split = coverage_row(draw({path(many)}, style, samples), 16, 12, 244);
        double worst = 0.0;
        for (size_t i = 0; i < one.size(); ++i) {
            const int x = 12 + int(i);
            if (samples == 1 && std::abs((x - 8) % 8 - 4) > 0) continue;  // 4 px from both joints
            worst = std::max(worst, double(std::abs(one[i] - split[i])));
        }
        EXPECT_LT(worst, 0.04) << "samples " << samples;
    }
}

// A shipped brush keeps the stroke's outline: the pixels it touches are those the solid stroke
// touches (the brush only scales coverage), so the SVG outline still matches.
TEST(StrokeBrush, ShippedBrushKeepsTheWidth) {
    for (const char* name : {"pencil", "ink", "chalk", "marker"}) {
        const render::BrushImage* brush = render::shipped_brush(name);
        ASSERT_NE(brush, nullptr) << name;
        EXPECT_EQ(brush->width, 64);
        EXPECT_EQ(brush->height, 16);
        render::StrokeStyle solid;
        solid.width = 10.0f;
        render::StrokeStyle brushed = solid;
        brushed.brush = brush;
        const Image a = draw({path({{8, 16}, {248, 16}})}, solid);
        const Image b = draw({path({{8, 16}, {248, 16}})}, brushed);
        // Per column, the outermost rows with ink: the same both ways within a pixel.
        int differing = 0, darker = 0;
        for (int x = 0; x < kW; ++x) {
            int top_a = kH, bottom_a = -1, top_b = kH, bottom_b = -1;
            for (int y = 0; y < kH; ++y) {
                if (a.pixel(x, y)[0] < 250) top_a = std::min(top_a, y), bottom_a = std::max(bottom_a, y);
                if (b.pixel(x, y)[0] < 250) top_b = std::min(top_b, y), bottom_b = std::max(bottom_b, y);
                darker += b.pixel(x, y)[0] + 1 < a.pixel(x, y)[0];
            }
            EXPECT_LE(top_a, top_b) << name << " column " << x;
            EXPECT_GE(bottom_a, bottom_b) << name << " column " << x;
            differing += std::abs(top_a - top_b) > 1 || std::abs(bottom_a - bottom_b) > 1;
        }
        EXPECT_EQ(darker, 0) << name << ": a brush only takes coverage away";
        // The ink brush runs dry in places: whole columns may lose an edge row there.
        EXPECT_LE(differing, std::string(name) == "ink" ? kW / 2 : kW / 20) << name;
    }
    EXPECT_EQ(render::shipped_brush("none"), nullptr);
    EXPECT_EQ(render::shipped_brush("felt"), nullptr);
}

// A brush of full texels changes nothing: the brush multiplies the coverage, nothing else.
TEST(StrokeBrush, FullBrushDrawsTheSolidStroke) {
    render::BrushImage full;
    full.width = 8;
    full.height = 2;
    full.grey.assign(16, 255);
    render::StrokeStyle solid;
    solid.width = 5.0f;
    render::StrokeStyle brushed = solid;
    brushed.brush = &full;
    const std::vector<LinePath> paths = {path({{10, 10}, {120, 25}, {200, 5}})};
    for (int samples : {1, 4}) {
        const Image a = draw(paths, solid, samples), b = draw(paths, brushed, samples);
        int worst = 0;
        for (size_t i = 0; i < a.rgba.size(); ++i) worst = std::max(worst, std::abs(int(a.rgba[i]) - int(b.rgba[i])));
        EXPECT_LE(worst, 1) << "samples " << samples;
    }
}

}  // namespace
}  // namespace inkshade::test
