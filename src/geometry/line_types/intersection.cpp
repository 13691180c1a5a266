// `intersection`: where two surfaces of the mesh cross — the parts of an assembly, hair through
// a head, a self-intersecting sheet (extract_intersections; as Blender's Line Art draws them).
// View-independent: computed once per mesh and kept by MeshLineData.
#include "geometry/line_types/object_line_registry.hpp"

namespace inkshade::geometry {

namespace {

std::vector<LineSegment> extract(MeshLineData& data, const LineView&, const LineSettings&) {
    return data.intersections();
}

const ObjectLineRegistration registration{
    {.name = "intersection",
     .summary = "intersections: where two surfaces of the mesh cross (parts of an assembly, self-intersections)",
     .params = object_line_params(glm::vec3(0.0f), 1.0f, {}, 0.0f)},
    extract,
    {.intersections = true}};

}  // namespace

}  // namespace inkshade::geometry
