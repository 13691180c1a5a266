// Suggestive contours as rtsc 1.6 draws them with its defaults (issue 33): Inkshade's default
// `suggestive` layer, visible paths only, against the answer key of rtsc_suggestive.hpp (rtsc's
// normals, feature size, trim, fade and depth test), within 2 px both ways.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <sstream>
#include <string>

#include "analytic_meshes.hpp"
#include "geometry/rtsc_suggestive.hpp"
#include "inkshade/io.hpp"
#include "inkshade/line_drawing.hpp"
#include "support/off_text.hpp"
#include "support/temp_dir.hpp"

namespace inkshade::geometry {
namespace {

// `rtsc_mesh` as rtsc reads the file (every edge smooth), `drawn` as Inkshade loads it by default;
// the same surface. Views around the model, elevation varied, at size².
test::RtscAgreement suggestive_agreement(const Mesh& rtsc_mesh, const Mesh& drawn, int views, int size, bool print) {
    const test::RtscSuggestive key(rtsc_mesh);
    LineExtractor extractor(drawn);
    test::RtscAgreement sum;
    for (int k = 0; k < views; ++k) {
        CameraOptions options;
        options.azimuth_degrees = 360.0f / float(views) * float(k) + 10.0f;
        options.elevation_degrees = 25.0f + 5.0f * float(k % 3);
        const Camera camera = frame_camera(drawn.bounds(), options, 1.0f, drawn.positions);
        const LineDrawing drawing = extractor.draw(camera, size, size, {{"suggestive", {}}});
        const test::RtscAgreement a =
            test::rtsc_suggestive_agreement(key.drawn(camera, size, size), drawing.layers.at(0));
        if (print)
            std::printf("[ measure  ] view %d: recall %.3f precision %.3f (rtsc %.0f px, visible %.0f px)\n", k,
                        a.recall(), a.precision(), a.rtsc_visible, a.visible);
        sum += a;
    }
    return sum;
}

// A scan stand-in with suggestive contours all over: the unit sphere (meshed_cube pushed onto
// it) with bumps of ±8 % of the radius and scanner-like noise of ±0.3 edge lengths. The noise
// puts faces next to a suggestive contour a few pixels of their slope in front of it, which
// rtsc's polygon offset lets it through: without the slope allowance for suggestive contours
// (docs/lines.md, Visibility) recall here is 0.85.
Mesh bumpy_noisy_sphere(int n) {
    Mesh m = test::noisy_sphere(n, 0.3f);
    for (glm::vec3& p : m.positions) {
        const glm::vec3 d = glm::normalize(p);
        p *= 1.0f + 0.08f * std::sin(5.0f * d.x) * std::sin(5.0f * d.y + 1.0f) * std::sin(5.0f * d.z + 2.0f);
    }
    return m;
}

TEST(RtscSuggestive, BumpyNoisySphereDrawsWhatRtscDraws) {
    const Mesh sphere = bumpy_noisy_sphere(40);
    test::TempDir dir;
    const std::string file = dir.write("scan.off", test::off_text(sphere));
    LoadOptions smooth;
    smooth.smooth_angle = 180.0f;
    const test::RtscAgreement a = suggestive_agreement(load_mesh(file, smooth), load_mesh(file), 4, 512, true);
    EXPECT_GT(a.rtsc_visible, 1000.0) << "the key draws suggestive contours";
    EXPECT_GE(a.recall(), 0.9);
    EXPECT_GE(a.precision(), 0.9);
}

// INKSHADE_RTSC_MESHES=FILE[;FILE...]: each mesh's default suggestive contours against the
// key, 8 views at 1024². Skipped without it (the scans are not in the repository);
// docs/benchmarks.md has the figures.
TEST(RtscSuggestive, AgreementOfMeshesFromEnvironment) {
    const char* list = std::getenv("INKSHADE_RTSC_MESHES");
    if (!list || !*list) GTEST_SKIP() << "INKSHADE_RTSC_MESHES not set";
    std::stringstream files(list);
    for (std::string file; std::getline(files, file, ';');) {
        LoadOptions smooth;
        smooth.smooth_angle = 180.0f;
        const test::RtscAgreement a = suggestive_agreement(load_mesh(file, smooth), load_mesh(file), 8, 1024, true);
        std::printf("[ measure  ] %s: recall %.3f precision %.3f\n", file.c_str(), a.recall(), a.precision());
    }
}

}  // namespace
}  // namespace inkshade::geometry
