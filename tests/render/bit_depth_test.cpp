// RenderOptions::bit_depth 16: RGBA16 colour targets read back at 16 bits. The pixels of a
// smooth gradient match its formula to a few 16-bit levels (8 bits cannot: half a level is 128
// of them) and take many more distinct values; rounded to 8 bits they are the 8-bit render.
#include <set>

#include "inkshade/error.hpp"
#include "render/render_fixture.hpp"

namespace inkshade::test {
namespace {

// A square wider than the test camera's view in the z = 0 plane, its vertex colours rising from
// kLeft at x = -2 to kRight at x = 2: in the image, a gradient along x of 16 8-bit levels.
constexpr float kLeft = 100.0f / 255.0f, kRight = 116.0f / 255.0f;
Mesh gradient_square() {
    Mesh m;
    m.positions = {{-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0}};
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    m.colors = {glm::vec3(kLeft), glm::vec3(kRight), glm::vec3(kRight), glm::vec3(kLeft)};
    return m;
}

float gradient_at(float pixel_x) {
    const float x = ray_origin(ortho_camera(), pixel_x, 0.0f).x;
    return kLeft + (kRight - kLeft) * (x + 2.0f) / 4.0f;
}

Image render_gradient(int bit_depth) {
    ShadingSelection lambert;
    lambert.model = "lambert";
    RenderOptions o;
    o.width = o.height = kSize;
    o.bit_depth = bit_depth;
    return render_ortho(gradient_square(), ambient_only(), lambert, o);
}

TEST(BitDepth, SixteenBitGradientMatchesTheFormulaWithManyMoreLevels) {
    const Image wide = render_gradient(16), narrow = render_gradient(8);
    ASSERT_EQ(wide.rgba16.size(), size_t(kSize) * kSize * 4);
    EXPECT_TRUE(narrow.rgba16.empty());
    std::set<int> levels16, levels8;
    double worst16 = 0.0, worst8 = 0.0;
    for (int y = 0; y < kSize; y += 17)
        for (int x = 0; x < kSize; ++x) {
            const double want = 65535.0 * gradient_at(x + 0.5f);
            const size_t i = (size_t(y) * kSize + x) * 4;
            for (int c = 0; c < 3; ++c) {
                worst16 = std::max(worst16, std::abs(wide.rgba16[i + c] - want));
                worst8 = std::max(worst8, std::abs(257.0 * narrow.rgba[i + c] - want));
            }
            EXPECT_EQ(wide.rgba16[i + 3], 65535);
            levels16.insert(wide.rgba16[i]);
            levels8.insert(narrow.rgba[i]);
        }
    EXPECT_LE(worst16, 8.0) << "16-bit levels off the formula";
    EXPECT_GT(worst8, 64.0) << "8 bits round by up to 128 16-bit levels: the test tells them apart";
    EXPECT_LE(levels8.size(), 17u);
    EXPECT_GE(levels16.size(), 200u) << "one level a pixel across the 256-pixel row";
}

// The lit sphere at 16 bits, scaled to 8, is the 8-bit render within one level; a transparent
// background stays alpha 0 and the division by alpha happens at 16 bits.
TEST(BitDepth, SixteenBitsScaledTo8AreThe8BitRender) {
    ShadingSelection lambert;
    lambert.model = "lambert";
    const Light light = directional_light({1, 1, 2}, glm::vec3(0.9f), glm::vec3(0.1f));
    for (const float alpha : {1.0f, 0.0f}) {
        RenderOptions o;
        o.width = o.height = kSize;
        o.background = glm::vec4(1, 1, 1, alpha);
        const Image narrow = render_ortho(fine_sphere(), light, lambert, o);
        o.bit_depth = 16;
        const Image wide = render_ortho(fine_sphere(), light, lambert, o);
        ASSERT_EQ(wide.rgba16.size(), narrow.rgba.size());
        int off = 0;
        for (size_t i = 0; i < narrow.rgba.size(); ++i) {
            // Colour is compared premultiplied: divided by a small alpha, the 8-bit colour carries
            // its rounding error magnified (what 16 bits avoid). Where the edge of the sphere is
            // partly transparent the 8-bit resolve rounds twice (each sample, then their mean),
            // so half a level more is allowed there.
            const size_t a = i - i % 4 + 3;
            const bool partial = narrow.rgba[a] != 0 && narrow.rgba[a] != 255;
            const double alpha16 = i == a ? 1.0 : wide.rgba16[a] / 65535.0;
            const double alpha8 = i == a ? 1.0 : narrow.rgba[a] / 255.0;
            const bool differ =
                std::abs(wide.rgba16[i] / 257.0 * alpha16 - narrow.rgba[i] * alpha8) > (partial ? 1.5 : 1.0);
            if (differ && off < 5)
                ADD_FAILURE() << "pixel " << i / 4 << " channel " << i % 4 << ": " << wide.rgba16[i] << " (alpha "
                              << wide.rgba16[a] << ") against " << int(narrow.rgba[i]) << " (alpha "
                              << int(narrow.rgba[a]) << ")";
            off += differ;
            EXPECT_EQ(int(wide.rgba[i]), int(to_8_bits(wide.rgba16[i])));
        }
        EXPECT_EQ(off, 0) << "alpha " << alpha;
        EXPECT_EQ(wide.rgba16[3], alpha == 1.0f ? 65535 : 0) << "corner";
        EXPECT_EQ(wide.rgba16[(size_t(kSize / 2) * kSize + kSize / 2) * 4 + 3], 65535) << "centre";
    }
}

TEST(BitDepth, OtherDepthsAreRefused) {
    shared_renderer().set_mesh(gradient_square());
    RenderOptions o;
    o.width = o.height = 8;
    o.bit_depth = 12;
    ShadingSelection lambert;
    lambert.model = "lambert";
    try {
        shared_renderer().render(ortho_camera(), ambient_only(), lambert, o);
        FAIL() << "bit depth 12 accepted";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "bit depth: expected 8 or 16, got 12");
    }
}

}  // namespace
}  // namespace inkshade::test
