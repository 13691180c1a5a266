// The passes a frame runs, seen through their timings (PassTiming names are what
// `inkshade render --timing` prints): only those the style and the shading model need, in
// stage order; image-space lines after the resolve unless strokes follow; the shadow map drawn
// again only for a new mesh or light; under MeshUse::OneFrame the CPU passes that need the
// mesh-wide line data first.
#include "render/render_fixture.hpp"

namespace inkshade::test {
namespace {

LineSettings line(const std::string& type) { return {type, {}}; }

std::vector<std::string> pass_names(Renderer& r, const ShadingSelection& shading,
                                    const std::vector<LineSettings>& lines, const Light& light = Light{}) {
    std::vector<PassTiming> timings;
    r.render(ortho_camera(), light, shading, lines, RenderOptions{.width = 48, .height = 48}, &timings);
    std::vector<std::string> names;
    for (const PassTiming& t : timings) names.push_back(t.pass);
    return names;
}

using Names = std::vector<std::string>;

TEST(PassPlan, ShadingAloneIsShadingResolveReadback) {
    Renderer& r = shared_renderer();
    r.set_mesh(builtin::sphere(8, 16));
    EXPECT_EQ(pass_names(r, {}, {}), (Names{"shading", "resolve", "readback"}));
    // rim-contour is a test inside the shading pass, not a pass.
    EXPECT_EQ(pass_names(r, {}, {line("rim-contour")}), (Names{"shading", "resolve", "readback"}));
}

TEST(PassPlan, ImageLinesFollowTheResolveUnlessStrokesFollow) {
    Renderer& r = shared_renderer();
    r.set_mesh(builtin::sphere(8, 16));
    EXPECT_EQ(pass_names(r, {}, {line("hull"), line("suggestive-image")}),
              (Names{"shading", "hull", "gbuffer", "resolve", "image-lines", "readback"}));
    EXPECT_EQ(pass_names(r, {}, {line("contour"), line("edges"), line("threejs-outline"), line("hull")}),
              (Names{"shading", "hull", "threejs-outline", "gbuffer", "image-lines", "vector-lines", "strokes",
                     "resolve", "readback"}));
}

TEST(PassPlan, EveryPassOfTheKrViewWithAllLineTypes) {
    Renderer& r = shared_renderer();
    r.set_mesh(builtin::sphere(8, 16));
    EXPECT_EQ(pass_names(r, {.model = "kr"},
                         {line("contour"), line("rim-contour"), line("edges"), line("hull"), line("threejs-outline"),
                          line("suggestive-image")}),
              (Names{"radial-curvature", "shading", "hull", "threejs-outline", "gbuffer", "image-lines", "vector-lines",
                     "strokes", "resolve", "readback"}));
}

TEST(PassPlan, ShadowMapIsDrawnAgainOnlyForANewMeshOrLight) {
    Renderer& r = shared_renderer();
    r.set_mesh(builtin::sphere(8, 16));
    const ShadingSelection mtoon{.model = "mtoon"};
    const Names with_shadow{"shadow", "shading", "resolve", "readback"}, without{"shading", "resolve", "readback"};
    EXPECT_EQ(pass_names(r, mtoon, {}), with_shadow);
    EXPECT_EQ(pass_names(r, mtoon, {}), without);
    Light moved;
    moved.position = {3, 4, 5};
    EXPECT_EQ(pass_names(r, mtoon, {}, moved), with_shadow);
    EXPECT_EQ(pass_names(r, mtoon, {}, moved), without);
    r.set_mesh(builtin::sphere(8, 16));
    EXPECT_EQ(pass_names(r, mtoon, {}, moved), with_shadow);
    // Shadows off: no shadow pass at all.
    EXPECT_EQ(pass_names(r, {.model = "mtoon", .params = {{"shadows", {0.0f}}}}, {}), without);
}

TEST(PassPlan, OneFrameRunsTheLineDataPassesBeforeTheUpload) {
    Renderer& r = shared_renderer();
    r.set_mesh(builtin::sphere(8, 16), MeshUse::OneFrame);
    const std::vector<LineSettings> lines{line("contour"), line("hull")};
    EXPECT_EQ(pass_names(r, {.model = "kr"}, lines),
              (Names{"radial-curvature", "vector-lines", "shading", "hull", "strokes", "resolve", "readback"}));
    // Later frames recompute that data in the usual order.
    EXPECT_EQ(pass_names(r, {.model = "kr"}, lines),
              (Names{"radial-curvature", "shading", "hull", "vector-lines", "strokes", "resolve", "readback"}));
}

}  // namespace
}  // namespace inkshade::test
