// `intersection`: where two surfaces of the mesh cross — the parts of an assembly, hair through
// a head, a self-intersecting sheet (extract_intersections; as Blender's Line Art draws them).
// View-independent: computed once per mesh and kept by MeshLineData. Each segment's owner (its
// `face`) is the crossing object of higher `priority` (intersection_priority.hpp).
#include <algorithm>

#include "geometry/intersection_priority.hpp"
#include "geometry/line_types/object_line_registry.hpp"

namespace inkshade::geometry {

namespace {

std::vector<LineSegment> extract(MeshLineData& data, const LineView&, const LineSettings& settings) {
    std::vector<LineSegment> segments = data.intersections();
    const ParamValue& priorities = line_param(settings, "priority");
    if (std::any_of(priorities.begin(), priorities.end(), [](float p) { return p != 0.0f; }))
        assign_intersection_owners(segments, object_numbers(data.face_objects()), priorities);
    return segments;
}

const ObjectLineRegistration registration{
    {.name = "intersection",
     .summary = "intersections: where two surfaces of the mesh cross (parts of an assembly, self-intersections)",
     .params = object_line_params(
         glm::vec3(0.0f), 1.0f,
         {list_param("priority", {0.0f}, 64, 0.0f, 255.0f,
                     "per object (connected piece, numbered in the order of its first face): the line where two "
                     "objects cross belongs to the one of higher priority (Line Art's intersection priority); "
                     "0 past the list")},
         0.0f)},
    extract,
    {.intersections = true}};

}  // namespace

}  // namespace inkshade::geometry
