// Pixels of the `cel` model against a CPU evaluation of its formula (docs/shading.md; the
// settings of the presets cel-000, cel-002 and cel-004) on a finely tessellated unit sphere
// seen orthographically, whose analytic normal is known at every pixel. Pixels within two
// pixels of a band, highlight or rim edge are left out: there the tessellated normal and the
// analytic one may fall on different sides of a threshold.
#include <algorithm>
#include <array>
#include <cmath>
#include <set>

#include "geometry/builtin_models.hpp"
#include "render/render_fixture.hpp"

namespace inkshade::test {
namespace {

// The model's parameters, mirrored on the CPU; to_params() feeds the renderer the same values.
struct CelParams {
    int driver = 0;  // 0 half-lambert, 1 ndotl
    std::vector<float> thresholds{0.8f, 0.6f, 0.4f, 0.2f};
    std::vector<float> levels{1.0f, 0.75f, 0.5f, 0.25f, 0.0f};
    glm::vec3 shade{0.0f};
    float smoothing = 1.0f;
    bool specular = false;
    float shininess = 32.0f;
    float specular_threshold = 0.5f;
    glm::vec3 specular_color{1.0f};
    bool rim = false;
    glm::vec3 rim_color{1.0f};
    float rim_threshold = 0.716f;
    float rim_power = 0.1f;

    ParamValues to_params() const {
        return {
            {"driver", {float(driver)}},
            {"thresholds", thresholds},
            {"levels", levels},
            {"shade-color", {shade.r, shade.g, shade.b}},
            {"smoothing", {smoothing}},
            {"specular", {specular ? 1.0f : 0.0f}},
            {"shininess", {shininess}},
            {"specular-threshold", {specular_threshold}},
            {"specular-color", {specular_color.r, specular_color.g, specular_color.b}},
            {"rim", {rim ? 1.0f : 0.0f}},
            {"rim-color", {rim_color.r, rim_color.g, rim_color.b}},
            {"rim-threshold", {rim_threshold}},
            {"rim-power", {rim_power}},
        };
    }
};

// Preset cel-000, the five bands of Qu, Chen & Zwicker 2022, "Non-Photorealistic Shading
// Techniques for Anime-Style Rendering", eq. 4: half-Lambert > 0.8 -> 1, > 0.6 -> 0.75,
// > 0.4 -> 0.5, > 0.2 -> 0.25, else 0.
CelParams cel000() {
    CelParams p;
    p.smoothing = 0.0f;
    return p;
}

// Preset cel-002, three-tone cel: intensities 1.0 / 0.66 / 0.33 on the Lambert cosine.
CelParams cel002() {
    CelParams p;
    p.driver = 1;
    p.thresholds = {0.66f, 0.33f};
    p.levels = {1.0f, 0.66f, 0.33f};
    p.smoothing = 0.0f;
    return p;
}

// Preset cel-004: three bands on n.l, hard Blinn-Phong highlight, rim.
CelParams cel004() {
    CelParams p;
    p.driver = 1;
    p.thresholds = {0.5f, 0.0f};
    p.levels = {1.0f, 0.6f, 0.3f};
    p.smoothing = 0.0f;
    p.specular = true;
    p.rim = true;
    return p;
}

struct Scene : PixelScene {
    CelParams cel;
};

Scene make_scene(const CelParams& cel, glm::vec3 light_dir = {1.0f, 1.0f, 0.5f}) {
    Scene s;
    s.light = directional_light(light_dir, glm::vec3(0.9f, 0.85f, 0.8f), glm::vec3(0.1f, 0.12f, 0.15f));
    s.shading.model = "cel";
    s.shading.base_color = glm::vec3(0.8f, 0.6f, 0.4f);
    s.options.width = s.options.height = kSize;
    s.options.background = glm::vec4(0, 0, 0, 1);
    s.cel = cel;
    return s;
}

const glm::vec3 kView(0, 0, 1);  // orthographic camera on +z

float driver_value(const Scene& s, const glm::vec3& n) {
    float ndotl = glm::dot(n, s.l());
    return s.cel.driver == 0 ? 0.5f * ndotl + 0.5f : std::max(ndotl, 0.0f);
}

// Index of the band: the first i with d > thresholds[i], else the number of thresholds.
int band_of(const CelParams& p, float d) {
    for (size_t i = 0; i < p.thresholds.size(); ++i)
        if (d > p.thresholds[i]) return int(i);
    return int(p.thresholds.size());
}

// levels[band], the last level below every threshold; missing levels repeat the last one.
float level_of(const CelParams& p, int band) {
    if (size_t(band) >= p.thresholds.size()) return p.levels.back();
    return p.levels[std::min(size_t(band), p.levels.size() - 1)];
}

bool highlight_at(const Scene& s, const glm::vec3& n) {
    const glm::vec3 l = s.l();
    if (!s.cel.specular || glm::dot(n, l) <= 0.0f) return false;
    return std::pow(std::max(glm::dot(n, glm::normalize(l + kView)), 0.0f), s.cel.shininess) > s.cel.specular_threshold;
}

bool rim_at(const Scene& s, const glm::vec3& n) {
    float ndotl = glm::dot(n, s.l());
    if (!s.cel.rim || ndotl <= 0.0f) return false;
    return (1.0f - glm::dot(n, kView)) * std::pow(ndotl, s.cel.rim_power) > s.cel.rim_threshold;
}

// The formula with hard edges: C*(E*mix(shade, 1, level) + A) + highlight + rim.
glm::vec3 cel_formula(const Scene& s, const glm::vec3& n) {
    const CelParams& p = s.cel;
    float level = level_of(p, band_of(p, driver_value(s, n)));
    glm::vec3 lit = glm::mix(p.shade, glm::vec3(1.0f), level);
    glm::vec3 c = s.shading.base_color * (s.light.color * lit + s.light.ambient);
    if (highlight_at(s, n)) c += p.specular_color * s.light.color;
    if (rim_at(s, n)) c += p.rim_color * s.light.color;
    return c;
}

// Which side of every edge the analytic normal at a pixel centre lies on.
int region_code(const Scene& s, const glm::vec3& n) {
    return band_of(s.cel, driver_value(s, n)) * 4 + (highlight_at(s, n) ? 2 : 0) + (rim_at(s, n) ? 1 : 0);
}

std::optional<glm::vec3> normal_at(float x, float y) {
    auto n = sphere_normal(ray_origin(ortho_camera(), x, y));
    if (!n || n->z < 0.05f) return std::nullopt;
    return n;
}

// The region code at pixel (px, py) when it is the same at the centre and at the eight
// pixel centres `radius` pixels away (all on the sphere), else -1.
int stable_region(const Scene& s, int px, int py, int radius = 2) {
    auto n = normal_at(px + 0.5f, py + 0.5f);
    if (!n) return -1;
    int code = region_code(s, *n);
    for (int dy = -radius; dy <= radius; dy += radius)
        for (int dx = -radius; dx <= radius; dx += radius) {
            auto m = normal_at(px + dx + 0.5f, py + dy + 0.5f);
            if (!m || region_code(s, *m) != code) return -1;
        }
    return code;
}

// Compares every `step`-th pixel away from edges with cel_formula (tolerance in bytes);
// counts compared pixels per band in `per_band` when given.
int compare_away_from_edges(const Image& img, const Scene& s, int step, int tolerance,
                            std::vector<int>* per_band = nullptr) {
    int compared = 0;
    for (int py = step / 2; py < kSize; py += step)
        for (int px = step / 2; px < kSize; px += step) {
            int code = stable_region(s, px, py);
            if (code < 0) continue;
            glm::vec3 n = *normal_at(px + 0.5f, py + 0.5f);
            glm::vec3 want = cel_formula(s, n);
            const uint8_t* got = img.pixel(px, py);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(int(got[c]), to_byte(want[c]), tolerance)
                    << "pixel (" << px << "," << py << ") channel " << c << " band " << code / 4 << " d "
                    << driver_value(s, n);
            if (per_band) {
                per_band->resize(std::max(per_band->size(), size_t(code / 4 + 1)));
                ++(*per_band)[size_t(code / 4)];
            }
            ++compared;
        }
    return compared;
}

class Cel : public ::testing::Test {
protected:
    static Image render(Scene& s) {
        s.shading.params = s.cel.to_params();
        Renderer& r = shared_renderer();
        r.set_mesh(fine_sphere());
        return r.render(ortho_camera(), s.light, s.shading, s.options);
    }
};

TEST_F(Cel, DefaultsMatchFormulaAwayFromBandEdges) {
    Scene s = make_scene(CelParams{});
    // The model's registered defaults must be the ones mirrored here: render with none set.
    Renderer& r = shared_renderer();
    r.set_mesh(fine_sphere());
    Image img = r.render(ortho_camera(), s.light, s.shading, s.options);
    EXPECT_GE(compare_away_from_edges(img, s, 8, 2), 50);
}

TEST_F(Cel, NdotlDriverAndShadeColorMatchFormula) {
    CelParams p;
    p.driver = 1;
    p.thresholds = {0.7f, 0.3f, 0.1f};
    p.levels = {0.9f, 0.6f, 0.35f, 0.1f};
    p.shade = {0.3f, 0.1f, 0.5f};
    p.smoothing = 0.0f;
    Scene s = make_scene(p, {-0.5f, 0.8f, 0.6f});
    std::vector<int> per_band;
    EXPECT_GE(compare_away_from_edges(render(s), s, 6, 2, &per_band), 50);
    ASSERT_EQ(per_band.size(), 4u);
    for (int count : per_band) EXPECT_GE(count, 5);
}

// Lists of mismatched lengths: below every threshold the last level applies; bands without
// a level of their own repeat the last one.
TEST_F(Cel, LevelListLongerOrShorterThanThresholds) {
    CelParams longer;
    longer.smoothing = 0.0f;
    longer.thresholds = {0.5f};
    longer.levels = {1.0f, 0.5f, 0.2f};  // 0.5 unused: "else the last level"
    Scene s = make_scene(longer);
    std::vector<int> per_band;
    EXPECT_GE(compare_away_from_edges(render(s), s, 4, 1, &per_band), 100);
    ASSERT_EQ(per_band.size(), 2u);
    EXPECT_GE(per_band[1], 20);

    CelParams shorter;
    shorter.smoothing = 0.0f;
    shorter.thresholds = {0.8f, 0.5f, 0.3f};
    shorter.levels = {1.0f, 0.4f};  // bands 1, 2 and below all 0.4
    s = make_scene(shorter);
    per_band.clear();
    EXPECT_GE(compare_away_from_edges(render(s), s, 4, 1, &per_band), 100);
    ASSERT_EQ(per_band.size(), 4u);
    EXPECT_GE(per_band[3], 20);
}

// With cel-000's parameters every one of the five bands shows exactly its level plus
// ambient: C*(E*level + A), pixel by pixel, away from the band edges.
TEST_F(Cel, Cel000FiveBandsAreExactLevels) {
    Scene s = make_scene(cel000());
    std::vector<int> per_band;
    EXPECT_GE(compare_away_from_edges(render(s), s, 2, 1, &per_band), 500);
    ASSERT_EQ(per_band.size(), 5u) << "every band sampled";
    for (size_t b = 0; b < per_band.size(); ++b) EXPECT_GE(per_band[b], 20) << "band " << b;
}

TEST_F(Cel, Cel002ThreeIntensitiesAreExact) {
    Scene s = make_scene(cel002());
    s.light.color = glm::vec3(1.0f);
    s.light.ambient = glm::vec3(0.0f);
    Image img = render(s);
    std::vector<int> per_band;
    EXPECT_GE(compare_away_from_edges(img, s, 2, 1, &per_band), 500);
    ASSERT_EQ(per_band.size(), 3u);
    for (size_t b = 0; b < per_band.size(); ++b) EXPECT_GE(per_band[b], 20) << "band " << b;
    // Only the three intensities times C appear inside the disc (no smooth shading).
    std::set<int> reds;
    for (int py = 0; py < kSize; ++py)
        for (int px = 0; px < kSize; ++px)
            if (stable_region(s, px, py, 1) >= 0) reds.insert(img.pixel(px, py)[0]);
    std::set<int> want{to_byte(0.8f * 0.33f), to_byte(0.8f * 0.66f), to_byte(0.8f)};
    EXPECT_EQ(reds, want);
}

TEST_F(Cel, Cel004BandsHighlightAndRimMatchFormula) {
    Scene s = make_scene(cel004(), {-0.6f, 0.5f, 0.8f});
    s.light.ambient = glm::vec3(0.0f);
    s.shading.base_color = glm::vec3(0.6f, 0.4f, 0.3f);
    s.cel.specular_color = glm::vec3(0.3f, 0.35f, 0.4f);
    s.cel.rim_color = glm::vec3(0.2f, 0.25f, 0.3f);
    s.cel.rim_threshold = 0.4f;  // a rim wide enough to sample away from the silhouette
    s.cel.rim_power = 1.0f;
    Image img = render(s);
    EXPECT_GE(compare_away_from_edges(img, s, 3, 2), 500);
    int highlight = 0, rim = 0;
    for (int py = 1; py < kSize; py += 3)
        for (int px = 1; px < kSize; px += 3) {
            int code = stable_region(s, px, py);
            highlight += code >= 0 && (code & 2);
            rim += code >= 0 && (code & 1);
        }
    EXPECT_GE(highlight, 10);
    EXPECT_GE(rim, 10);
}

// cel-004's highlight alone (black base colour, no ambient): a disc of exactly
// specular-color * E where max(n.h, 0)^p > threshold, and black everywhere else.
TEST_F(Cel, HardHighlightDiscOnlyWhereAnalyticHighlight) {
    CelParams p = cel004();
    p.rim = false;
    p.specular_color = glm::vec3(1.0f, 0.8f, 0.6f);
    Scene s = make_scene(p, {-0.6f, 0.5f, 1.0f});
    s.shading.base_color = glm::vec3(0.0f);
    s.light.ambient = glm::vec3(0.0f);
    Image img = render(s);
    const glm::vec3 on = p.specular_color * s.light.color;
    // Whether the analytic highlight covers a pixel centre within `radius` pixels.
    auto near_highlight = [&](int px, int py, int radius) {
        for (int dy = -radius; dy <= radius; ++dy)
            for (int dx = -radius; dx <= radius; ++dx) {
                auto n = normal_at(px + dx + 0.5f, py + dy + 0.5f);
                if (n && highlight_at(s, *n)) return true;
            }
        return false;
    };
    int inside = 0, outside = 0, stray = 0;
    for (int py = 0; py < kSize; ++py)
        for (int px = 0; px < kSize; ++px) {
            const uint8_t* got = img.pixel(px, py);
            if (got[0] > 0 && !near_highlight(px, py, 2)) ++stray;
            int code = stable_region(s, px, py);
            if (code < 0) continue;
            bool in = code & 2;
            (in ? inside : outside) += 1;
            for (int c = 0; c < 3; ++c)
                ASSERT_NEAR(int(got[c]), in ? to_byte(on[c]) : 0, 1)
                    << "pixel (" << px << "," << py << ") " << (in ? "inside" : "outside") << " the highlight";
        }
    EXPECT_GE(inside, 300);
    EXPECT_GE(outside, 10000);
    EXPECT_EQ(stray, 0) << "pixels lit farther than 2 pixels from the analytic highlight";
}

TEST_F(Cel, RimOnlyWhereAnalyticRim) {
    CelParams p;
    p.smoothing = 0.0f;
    p.thresholds = {1.0f};  // one band of level 0: no diffuse light, the rim alone
    p.levels = {0.0f, 0.0f};
    p.rim = true;
    p.rim_color = glm::vec3(0.5f, 0.7f, 1.0f);
    p.rim_threshold = 0.3f;
    p.rim_power = 0.5f;
    Scene s = make_scene(p, {1.0f, 0.3f, 0.4f});
    s.shading.base_color = glm::vec3(1.0f);
    s.light.ambient = glm::vec3(0.0f);
    Image img = render(s);
    const glm::vec3 on = p.rim_color * s.light.color;
    int inside = 0, outside = 0;
    for (int py = 0; py < kSize; ++py)
        for (int px = 0; px < kSize; ++px) {
            int code = stable_region(s, px, py);
            if (code < 0) continue;
            bool in = code & 1;
            (in ? inside : outside) += 1;
            const uint8_t* got = img.pixel(px, py);
            for (int c = 0; c < 3; ++c)
                ASSERT_NEAR(int(got[c]), in ? to_byte(on[c]) : 0, 1)
                    << "pixel (" << px << "," << py << ") " << (in ? "inside" : "outside") << " the rim";
        }
    EXPECT_GE(inside, 300);
    EXPECT_GE(outside, 10000);
}

// Pixels of a white sphere under white light and no ambient read the level directly.
// smoothing = 0 shows only the five levels; smoothing > 0 puts in-between values on the band
// edges (and only there), more of them for a wider smoothing.
TEST_F(Cel, SmoothingBlendsBandEdgesOnly) {
    auto render_levels = [](float smoothing) {
        CelParams p;
        p.smoothing = smoothing;
        Scene s = make_scene(p);
        s.shading.base_color = glm::vec3(1.0f);
        s.light.color = glm::vec3(1.0f);
        s.light.ambient = glm::vec3(0.0f);
        return std::make_pair(s, render(s));
    };
    auto between = [](const Scene& s, const Image& img, bool* off_edge) {
        int count = 0;
        for (int py = 0; py < kSize; ++py)
            for (int px = 0; px < kSize; ++px) {
                auto n = normal_at(px + 0.5f, py + 0.5f);
                // Skip the silhouette, where MSAA blends with the background.
                if (!n || !normal_at(px - 1.5f, py + 0.5f) || !normal_at(px + 2.5f, py + 0.5f) ||
                    !normal_at(px + 0.5f, py - 1.5f) || !normal_at(px + 0.5f, py + 2.5f))
                    continue;
                int g = img.pixel(px, py)[1];
                bool on_level = false;
                for (float level : s.cel.levels) on_level = on_level || std::abs(g - to_byte(level)) <= 1;
                if (on_level) continue;
                ++count;
                if (stable_region(s, px, py, 3) >= 0) *off_edge = true;
            }
        return count;
    };
    bool off_edge = false;
    auto [hard_scene, hard] = render_levels(0.0f);
    // With MSAA, a pixel on a band edge that two triangles share stores each triangle's own
    // level (their interpolated normals differ slightly), so a hard edge blends at a handful of
    // pixels where a mesh edge crosses it.
    int hard_count = between(hard_scene, hard, &off_edge);
    EXPECT_LE(hard_count, 8) << "smoothing 0 gives only the levels (but for MSAA at mesh edges)";
    auto [soft_scene, soft] = render_levels(1.0f);
    int soft_count = between(soft_scene, soft, &off_edge);
    EXPECT_GE(soft_count, 100) << "smoothing 1 blends band edges";
    EXPECT_GT(soft_count, 10 * hard_count);
    auto [wide_scene, wide] = render_levels(4.0f);
    int wide_count = between(wide_scene, wide, &off_edge);
    EXPECT_GT(wide_count, soft_count * 2) << "smoothing 4 blends wider edges";
    EXPECT_FALSE(off_edge) << "blended pixels lie within 3 pixels of a band edge";
}

// The shade colour takes black's place: the darkest band is C*(E*shade + A), the others
// mix(shade, 1, level).
TEST_F(Cel, ShadeColorReplacesBlack) {
    CelParams p = cel000();
    p.shade = glm::vec3(0.2f, 0.3f, 0.7f);
    Scene s = make_scene(p);
    std::vector<int> per_band;
    Image img = render(s);
    EXPECT_GE(compare_away_from_edges(img, s, 2, 1, &per_band), 500);
    ASSERT_EQ(per_band.size(), 5u);
    EXPECT_GE(per_band[4], 20);
    // In the darkest band, blue is C.b*(E.b*0.7 + A.b), far from black's C.b*A.b.
    for (int py = 0; py < kSize; ++py)
        for (int px = 0; px < kSize; ++px)
            if (stable_region(s, px, py) == 4 * 4) {
                ASSERT_NEAR(int(img.pixel(px, py)[2]), to_byte(0.4f * (0.8f * 0.7f + 0.15f)), 1);
            }
}

// three.js MeshToonMaterial with an N-texel gradient map and nearest filtering shades with
// texel[floor(N * (0.5 n.l + 0.5))]: the same as half-Lambert bands at (N-1)/N, ..., 1/N with
// the texels as levels from the bright end.
TEST_F(Cel, EvenThresholdsActAsNearestGradientMap) {
    const std::array<float, 4> gradient{0.1f, 0.45f, 0.7f, 0.95f};  // dark to bright, as in a texture
    CelParams p;
    p.smoothing = 0.0f;
    p.thresholds = {0.75f, 0.5f, 0.25f};
    p.levels = {gradient[3], gradient[2], gradient[1], gradient[0]};
    Scene s = make_scene(p);
    Image img = render(s);
    int compared = 0;
    for (int py = 1; py < kSize; py += 3)
        for (int px = 1; px < kSize; px += 3) {
            if (stable_region(s, px, py) < 0) continue;
            glm::vec3 n = *normal_at(px + 0.5f, py + 0.5f);
            float coord = 0.5f * glm::dot(n, s.l()) + 0.5f;
            float texel = gradient[size_t(std::clamp(int(std::floor(coord * 4.0f)), 0, 3))];
            glm::vec3 want = s.shading.base_color * (s.light.color * texel + s.light.ambient);
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(int(img.pixel(px, py)[c]), to_byte(want[c]), 1);
            ++compared;
        }
    EXPECT_GE(compared, 500);
}

}  // namespace
}  // namespace inkshade::test
