// One request, four front ends, the same bytes: the library (make_scene + Renderer +
// LineExtractor), `inkshade render` / `inkshade lines`, and `inkshade batch` write
// byte-identical PNG and SVG files for the same model, style, view and size. (The Python module
// is compared with the same CLI files in tests/python.)
#include <gtest/gtest.h>

#include <fstream>

#include "cli/run_cli.hpp"
#include "inkshade/io.hpp"
#include "inkshade/scene.hpp"

namespace inkshade {
namespace {

using test::run_cli;
using test::slurp;
using test::TempDir;

// What the library writes for the request: make_scene, then the renderer and line extractor.
void library_files(SceneRequest request, const std::string& png, const std::string& svg) {
    request.outputs = {.image = true, .line_drawing = true};
    const Scene scene = make_scene(request);
    const Mesh mesh = load_mesh(scene.model);
    const Camera camera = scene.frame(mesh);
    Renderer renderer;
    renderer.set_mesh(mesh);
    write_png(png, render_scene(renderer, scene, camera, scene.light(mesh.bounds(), camera)));
    LineExtractor extractor(mesh);
    write_svg(svg, draw_scene_lines(extractor, scene, camera), scene.style.background);
}

TEST(FrontEnds, LibraryCliAndBatchWriteTheSameBytes) {
    TempDir dir;
    const std::string manifest = dir.file("jobs.jsonl");
    std::ofstream(manifest) << R"({"model": "builtin:torus", "views": "60:30", "styles": "anime,ink-vector", )"
                            << R"("size": "96x64", "format": "png,svg"})"
                            << "\n";
    const auto batch = run_cli("batch " + manifest + " -o " + dir.file("out") + " -q");
    ASSERT_EQ(batch.status, 0) << batch.err;
    for (const std::string style : {"anime", "ink-vector"}) {
        SCOPED_TRACE(style);
        SceneRequest request;
        request.model = "builtin:torus";
        request.style = style;
        request.size = {96, 64};
        request.camera.azimuth_degrees = 60.0f;
        request.camera.elevation_degrees = 30.0f;
        library_files(request, dir.file(style + "-lib.png"), dir.file(style + "-lib.svg"));

        const std::string options = " builtin:torus --style " + style + " --size 96x64 --azimuth 60 --elevation 30";
        auto r = run_cli("render" + options + " -o " + dir.file(style + "-cli.png"));
        ASSERT_EQ(r.status, 0) << r.err;
        r = run_cli("lines" + options + " -o " + dir.file(style + "-cli.svg"));
        ASSERT_EQ(r.status, 0) << r.err;

        const std::string batch_stem = dir.file("out/torus/" + style + "/az060_el30");
        const std::string png = slurp(dir.file(style + "-lib.png")), svg = slurp(dir.file(style + "-lib.svg"));
        ASSERT_GT(png.size(), 100u);
        ASSERT_NE(svg.find("<path"), std::string::npos);
        EXPECT_TRUE(png == slurp(dir.file(style + "-cli.png"))) << "render differs from the library";
        EXPECT_TRUE(png == slurp(batch_stem + ".png")) << "batch PNG differs from the library";
        EXPECT_TRUE(svg == slurp(dir.file(style + "-cli.svg"))) << "lines differs from the library";
        EXPECT_TRUE(svg == slurp(batch_stem + ".svg")) << "batch SVG differs from the library";
    }
}

}  // namespace
}  // namespace inkshade
