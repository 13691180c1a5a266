// Isophotes (line type `isophote`): lines of equal diffuse brightness n·l = c under a
// directional light l, drawn as rtsc 1.6 draws them (Rusinkiewicz and DeCarlo's "Real-Time
// Suggestive Contours" software, draw_isophotes): per-vertex normals, the light turning with
// the camera, evenly spaced levels on both sides of the terminator n·l = 0. Their shapes carry
// the surface's curvature (Koenderink & van Doorn 1980, "Photometric invariants related to
// solid shape").
#pragma once
#include <vector>

#include "geometry/contours.hpp"
#include "inkshade/camera.hpp"
#include "inkshade/mesh.hpp"

namespace inkshade::geometry {

struct IsophoteOptions {
    // Towards the light in the camera's frame (x right, y up, z towards the viewer); rtsc's
    // light follows the camera and points along its z axis by default (a headlight).
    glm::vec3 direction{0.0f, 0.0f, 1.0f};
    // n·l = k / levels for every integer |k| < levels (rtsc's niso, 20): the terminator, the
    // lit side and the unlit one (rtsc's "negative isophotes", seen when the light is away from
    // the camera). 0 draws `values` instead.
    int levels = 20;
    // The n·l values drawn when levels is 0 (each in [-1, 1]; order and repeats do not matter).
    std::vector<float> values;
    // Also on faces turned away from the viewer (rtsc culls those whose three corners have
    // n·v ≤ 0: on a closed model they are hidden, and under a headlight they hold the unlit half).
    bool back_faces = false;
};

// The n·l of each isoline, strictly increasing: LineSegment::isoline indexes it.
std::vector<double> isophote_levels(const IsophoteOptions& options);

// Isophote segments (extract_isolines of n·l, n the unit vertex normal). `normals` holds one
// normal per vertex (throws std::invalid_argument otherwise); a zero direction is an
// InputError.
std::vector<LineSegment> extract_isophotes(const Mesh& mesh, const std::vector<glm::vec3>& normals,
                                           const Camera& camera, const IsophoteOptions& options = {});

}  // namespace inkshade::geometry
