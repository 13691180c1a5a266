// Topographic lines (line type `topo`): level sets of height along a direction, evenly spaced —
// a map's contour lines, or, along the view axis as rtsc 1.6 draws them (draw_topolines),
// slices of constant depth.
#pragma once
#include <vector>

#include "geometry/contours.hpp"
#include "inkshade/camera.hpp"
#include "inkshade/mesh.hpp"

namespace inkshade::geometry {

struct TopoOptions {
    // The direction of increasing height, in the camera's frame (x right, y up, z towards the
    // viewer; rtsc's camera z axis: lines of constant depth) or, with `world`, in world
    // coordinates (e.g. a model's up axis, for a map's contour lines).
    glm::vec3 direction{0.0f, 0.0f, 1.0f};
    bool world = false;
    // Without `spacing`: the bounding sphere's diameter in `count` steps (rtsc's ntopo, 20),
    // heights from the sphere's lowest point.
    int count = 20;
    // World units between lines, heights measured from the origin (0 = from `count`).
    float spacing = 0.0f;
    // Shift of every line, in units of the spacing (rtsc's topo_offset, 0).
    float offset = 0.0f;
    // Also on faces turned away from the viewer (rtsc culls those whose three corners have
    // n·v ≤ 0).
    bool back_faces = false;
};

// The most lines one drawing may ask for: a spacing giving more is an InputError.
constexpr size_t kMaxTopoLines = 10000;

// Heights (world units along the unit world direction, from the origin) of the lines crossing
// the mesh's bounding sphere, increasing: LineSegment::isoline indexes them. Throws InputError
// for a zero direction or more than kMaxTopoLines lines.
std::vector<double> topo_levels(const Mesh& mesh, const Camera& camera, const TopoOptions& options);

// Topographic segments: extract_isolines of p·d, d the unit world direction. `normals` (one per
// vertex; std::invalid_argument otherwise) tell the faces turned away.
std::vector<LineSegment> extract_topo_lines(const Mesh& mesh, const std::vector<glm::vec3>& normals,
                                            const Camera& camera, const TopoOptions& options = {});

}  // namespace inkshade::geometry
