// Temporal coherence through batch: the views of a turntable job are one sequence, so a
// coherent layer's dashes stay on the surface from frame to frame (docs/lines.md, "Temporal
// coherence"); and the renderer hands its frame's strokes to the caller's sequence.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "inkshade/batch.hpp"
#include "inkshade/scene.hpp"
#include "support/temp_dir.hpp"

namespace inkshade {
namespace {

std::string style_toml(bool coherence) {
    return std::string(
               "[shading]\nmodel = \"lambert\"\n[[lines]]\ntype = \"contour\"\nwidth = 1.5\n"
               "dash = \"12,8\"\n") +
           (coherence ? "coherence = true\n" : "");
}

// The start of every dash of the SVG's contour layer (each path's "M x y").
std::vector<glm::dvec2> dash_starts(const std::string& svg_path) {
    std::ifstream in(svg_path);
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string svg = ss.str();
    std::vector<glm::dvec2> out;
    const size_t layer = svg.find("<g id=\"contour\"");
    const size_t end = svg.find("</g>", layer);
    for (size_t at = svg.find("d=\"M", layer); at < end; at = svg.find("d=\"M", at + 1)) {
        double x = 0.0, y = 0.0;
        std::istringstream(svg.substr(at + 4, 40)) >> x >> y;
        out.emplace_back(x, y);
    }
    return out;
}

// Per pair of consecutive views, how far each dash start of the first is from the nearest of
// the next: the median over the turntable.
double median_dash_motion(const std::string& style, const std::string& dir) {
    BatchDefaults d;
    d.views = "turntable:36:0";  // from the equator: the orbit turns the sphere about the image's vertical
    d.styles = style;
    d.options.size = {160, 160};
    d.outputs = {.png = false, .svg = true};
    const std::vector<BatchJob> jobs = expand_jobs({{"builtin:sphere", "sphere"}}, d);
    BatchOptions options;
    options.output_dir = dir;
    const BatchSummary s = run_batch(jobs, options, nullptr);
    EXPECT_EQ(s.done, 36u);
    std::vector<double> motion;
    std::vector<glm::dvec2> previous;
    for (const BatchJob& job : jobs) {
        const std::vector<glm::dvec2> starts = dash_starts(dir + "/" + job.stem + ".svg");
        EXPECT_GT(starts.size(), 15u) << job.stem;
        for (const glm::dvec2& p : previous) {
            double best = 1e9;
            for (const glm::dvec2& q : starts) best = std::min(best, glm::length(q - p));
            motion.push_back(best);
        }
        previous = starts;
    }
    std::sort(motion.begin(), motion.end());
    return motion.empty() ? 1e9 : motion[motion.size() / 2];
}

TEST(BatchCoherence, TurntableDashesStayOnTheSphere) {
    test::TempDir dir;
    const std::string coherent = dir.write("coherent.toml", style_toml(true));
    const std::string plain = dir.write("plain.toml", style_toml(false));
    const double still = median_dash_motion(coherent, dir.file("coherent"));
    const double moving = median_dash_motion(plain, dir.file("plain"));
    // A dash start is at most half a period (10 px) from one of the next frame's: restarting
    // the pattern at each chain's start puts them anywhere in that range.
    EXPECT_LE(still, 0.5);
    EXPECT_GE(moving, 2.0);
    std::cout << "median dash motion per frame: coherent " << still << " px, plain " << moving << " px\n";
}

TEST(BatchCoherence, RendererLeavesItsFrameInTheSequence) {
    SceneRequest request;
    request.model = "builtin:sphere";
    request.style = "ink-vector";
    request.size = {96, 96};
    request.sets = {"contour.coherence=true"};
    Scene scene = make_scene(request);
    const Mesh mesh = load_mesh("builtin:sphere");
    Renderer renderer;
    renderer.set_mesh(mesh);
    const Camera camera = scene.frame(mesh);
    StrokeSequence sequence;
    scene.options.stroke_sequence = &sequence;
    render_scene(renderer, scene, camera, scene.light(mesh.bounds(), camera));
    ASSERT_FALSE(sequence.layers.empty());
    EXPECT_EQ(sequence.width, 96);
    EXPECT_EQ(sequence.camera.eye, camera.eye);
    bool contour = false;
    for (const ParameterisedLayer& layer : sequence.layers)
        if (layer.type == "contour") contour = !layer.paths.empty() && !layer.paths[0].u.empty();
    EXPECT_TRUE(contour);
}

}  // namespace
}  // namespace inkshade
