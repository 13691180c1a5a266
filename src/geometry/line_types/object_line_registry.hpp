// Object-space line types (LineSpace::Object): each file in this folder registers its
// LineType (name, parameters) together with the function that extracts its segments, so
// LineExtractor needs no list of types and adding one touches one file.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "geometry/contours.hpp"
#include "geometry/line_types/mesh_line_data.hpp"
#include "inkshade/camera.hpp"
#include "inkshade/lines.hpp"
#include "inkshade/section_plane.hpp"

namespace inkshade::geometry {

class RayScene;

// What one view gives the extractors besides the mesh: the camera, the key light (light-contour),
// the section plane (clip-boundary) and the mesh's ray-casting scene (silhouette and
// external-contour look behind the contour).
struct LineView {
    const Camera& camera;
    const Light& light;
    const std::optional<SectionPlane>& section;
    const RayScene& scene;
};

// The segments of one line type for one view (world coordinates, node keys as in
// contours.hpp); visibility, chaining and clean-up are LineExtractor's.
using ExtractLineSegments = std::vector<LineSegment> (*)(MeshLineData& data, const LineView& view,
                                                         const LineSettings& settings);

// What a type reads or asks of the drawing besides the mesh's positions and normals, declared at
// its registration: LineExtractor plans a drawing's mesh-wide work from the needs of its layers
// (computed up front and concurrently, MeshLineData::prepare) and names no type.
struct LineTypeNeeds {
    // Edge adjacency; crease classification comes with it (at the default angle unless a
    // layer asks for `creases`), and the borders from that classification.
    bool adjacency = false;
    // Crease classification at the angle (degrees) of the type's `angle` parameter; implies
    // adjacency. The registration checks that the type has that parameter.
    bool creases = false;
    bool curvature = false;      // principal curvatures and their derivatives (feature size too)
    bool intersections = false;  // where two surfaces of the mesh cross
    // The segments are occluding contours: their visibility test walks the folds around them
    // (VisibilityOptions::contour, over the faces of contour_surroundings).
    bool contour_folds = false;
    // The segments lie on the interpolated surface away from contours (suggestive contours):
    // their visibility test takes the contours' slope allowance (VisibilityOptions::own_slope).
    bool own_slope = false;
};

// A registered object-space type: how to extract it and what that needs.
struct ObjectLineType {
    ExtractLineSegments extract = nullptr;
    LineTypeNeeds needs;
};

struct ObjectLineRegistration {
    ObjectLineRegistration(LineType type, ExtractLineSegments extract, LineTypeNeeds needs = {});
};

// The registration of an object-space type, or nullptr.
const ObjectLineType* object_line_type(const std::string& type_name);

// The parameters of an object-space type: stroke_params(color, width), then `own`, then the
// clean-up and output parameters every object-space type has (min-length, smooth, taper,
// hidden), with `min_length_px` as the default of min-length.
std::vector<ParamSpec> object_line_params(glm::vec3 color, float width_px, std::vector<ParamSpec> own,
                                          float min_length_px);

// The `feature-size` parameter of the curvature-based types: the world length that makes
// `made_dimensionless` (e.g. "threshold") dimensionless; 0 = automatic (feature_size.hpp).
ParamSpec feature_size_param(const std::string& made_dimensionless);

// The value of a Float/Int/Bool parameter of `settings` as one number.
float line_number(const LineSettings& settings, const std::string& name);

// A FloatList parameter holding a direction, exactly three numbers not all zero (InputError
// naming TYPE.NAME otherwise).
glm::vec3 line_direction(const LineSettings& settings, const std::string& name);

}  // namespace inkshade::geometry
