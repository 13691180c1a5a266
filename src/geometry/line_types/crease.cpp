// `crease`: mesh edges whose dihedral angle exceeds a threshold, convex and concave
// alike, plus non-manifold edges (extract_creases).
#include "geometry/line_types/object_line_registry.hpp"

namespace inkshade::geometry {

namespace {

std::vector<LineSegment> extract(MeshLineData& data, const LineView&, const LineSettings& settings) {
    const CreaseLines& c = data.creases(line_number(settings, "angle"));
    std::vector<LineSegment> segments;
    segments.reserve(c.ridges.size() + c.valleys.size() + c.non_manifold.size());
    for (const auto* list : {&c.ridges, &c.valleys, &c.non_manifold})
        segments.insert(segments.end(), list->begin(), list->end());
    return segments;
}

const ObjectLineRegistration registration{
    {.name = "crease",
     .summary = "creases: edges whose face normals differ by more than an angle, and non-manifold edges",
     .params = object_line_params(
         glm::vec3(0.0f), 1.0f,
         {float_param("angle", 60.0f, 0.0f, 180.0f,
                      "dihedral threshold in degrees between the two face normals (60°: about Blender's and "
                      "trimesh2's sharp-edge angle, above the facets of a tessellated curved surface)")},
         0.0f)},
    extract,
    {.creases = true}};

}  // namespace

}  // namespace inkshade::geometry
