// Object-space line types (LineSpace::Object): each file in this folder registers its
// LineType (name, parameters) together with the function that extracts its segments, so
// LineExtractor needs no list of types and adding one touches one file.
#pragma once
#include <string>
#include <vector>

#include "geometry/contours.hpp"
#include "geometry/line_types/mesh_line_data.hpp"
#include "inkshade/camera.hpp"
#include "inkshade/lines.hpp"

namespace inkshade::geometry {

// The segments of one line type for one view (world coordinates, node keys as in
// contours.hpp); visibility, chaining and clean-up are LineExtractor's.
using ExtractLineSegments = std::vector<LineSegment> (*)(MeshLineData& data, const Camera& camera,
                                                         const LineSettings& settings);

struct ObjectLineRegistration {
    // `needs`: the mesh-wide data extract() reads, so LineExtractor can compute what a drawing
    // needs up front and concurrently (MeshLineData::prepare).
    ObjectLineRegistration(LineType type, ExtractLineSegments extract, MeshLineNeeds needs = {});
};

// The extractor of an object-space type, or nullptr.
ExtractLineSegments object_line_extractor(const std::string& type_name);
// What the type's extractor reads (nothing for unknown types).
MeshLineNeeds object_line_needs(const std::string& type_name);

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
