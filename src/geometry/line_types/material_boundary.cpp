// `material-boundary`: edges between faces of different materials (extract_material_boundaries).
#include "geometry/line_types/object_line_registry.hpp"
#include "geometry/material_boundaries.hpp"

namespace inkshade::geometry {

namespace {

std::vector<LineSegment> extract(MeshLineData& data, const LineView&, const LineSettings&) {
    return extract_material_boundaries(data.mesh());
}

const ObjectLineRegistration registration{
    {.name = "material-boundary",
     .summary = "material boundaries: edges between faces of different materials (matched by position across "
                "a model's parts)",
     .params = object_line_params(glm::vec3(0.0f), 1.0f, {}, 0.0f)},
    extract};

}  // namespace

}  // namespace inkshade::geometry
