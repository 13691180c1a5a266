// Auto-smooth on a dense noisy scan (docs/inputs.md#normals-and-hard-edges): the file has no
// normals and noise tilts neighbouring faces past the 30° default in many places, yet its
// contour must be what smooth vertex normals give (rtsc's): the sphere's silhouette circle,
// and nothing on the noise inside it.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "analytic_meshes.hpp"
#include "geometry/adjacency.hpp"
#include "geometry/normals.hpp"
#include "inkshade/io.hpp"
#include "inkshade/line_drawing.hpp"
#include "support/off_text.hpp"
#include "support/temp_dir.hpp"

namespace inkshade::geometry {
namespace {

// Share of the edges of two faces whose face normals differ by more than `degrees`.
double sharp_edge_share(const Mesh& m, float degrees) {
    const EdgeAdjacency adj = build_edge_adjacency(m);
    const std::vector<glm::vec3> fn = face_normals(m);
    size_t sharp = 0, pairs = 0;
    for (size_t e = 0; e < adj.edge_count(); ++e) {
        if (adj.face_count(e) != 2) continue;
        ++pairs;
        sharp += glm::dot(fn[adj.face(e, 0)], fn[adj.face(e, 1)]) < std::cos(glm::radians(degrees));
    }
    return double(sharp) / double(pairs);
}

TEST(NoisyScanContour, DefaultAutoSmoothDrawsTheSilhouetteCircleOnly) {
    const Mesh sphere = test::noisy_sphere(64, 0.2f);
    ASSERT_GT(sharp_edge_share(sphere, 30.0f), 0.05);  // the noise exceeds the default angle often
    test::TempDir dir;
    const Mesh loaded = load_mesh(dir.write("scan.off", test::off_text(sphere)));  // default --smooth-angle 30

    Camera camera;
    camera.eye = {0.6f, 0.8f, 4.0f};
    camera.target = glm::vec3(0.0f);
    camera.orthographic = true;
    camera.ortho_height = 2.5f;
    const int size = 400;
    const float pixels_per_unit = float(size) / camera.ortho_height;
    LineExtractor extractor(loaded);
    const LineDrawing drawing = extractor.draw(camera, size, size, {{"contour", {}}});
    ASSERT_EQ(drawing.layers.size(), 1u);
    // The silhouette of the unit sphere is the unit circle around the image centre; the noise
    // (±0.5 % of the radius) and the noisy normals move it by a few pixels at most.
    const float tolerance = 0.02f;
    int bins_hit[64] = {};
    size_t points = 0;
    for (const LinePath& path : drawing.layers[0].visible)
        for (const glm::vec2& p : path.points) {
            const glm::vec2 d = (p - glm::vec2(size / 2.0f)) / pixels_per_unit;
            EXPECT_NEAR(glm::length(d), 1.0f, tolerance)
                << "contour point off the silhouette at " << p.x << ", " << p.y;
            const float angle = std::atan2(d.y, d.x) + std::numbers::pi_v<float>;
            bins_hit[std::min(63, int(angle / (2.0f * std::numbers::pi_v<float>)*64.0f))] = 1;
            ++points;
        }
    EXPECT_GT(points, 100u);
    int covered = 0;
    for (int hit : bins_hit) covered += hit;
    EXPECT_EQ(covered, 64);  // all the way round
}

}  // namespace
}  // namespace inkshade::geometry
