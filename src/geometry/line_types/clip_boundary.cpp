// `clip-boundary`: where the near plane and the section plane (--section-plane) cut the mesh
// (extract_plane_cut), closed outlines on a closed mesh.
#include "geometry/line_types/object_line_registry.hpp"
#include "geometry/plane_cuts.hpp"

namespace inkshade::geometry {

namespace {

std::vector<LineSegment> extract(MeshLineData& data, const LineView& view, const LineSettings& settings) {
    std::vector<LineSegment> segments;
    if (line_number(settings, "near") != 0.0f) segments = extract_plane_cut(data.mesh(), near_plane_of(view.camera), 0);
    if (view.section && line_number(settings, "section") != 0.0f) {
        const std::vector<LineSegment> cut = extract_plane_cut(data.mesh(), *view.section, 1);
        segments.insert(segments.end(), cut.begin(), cut.end());
    }
    return segments;
}

const ObjectLineRegistration registration{
    {.name = "clip-boundary",
     .summary = "clip boundaries: where the camera's near plane and the section plane (--section-plane) cut "
                "the mesh, as closed outlines",
     .params = object_line_params(
         glm::vec3(0.0f), 1.5f,
         {bool_param("near", true, "draw the cut of the camera's near plane"),
          bool_param("section", true, "draw the cut of the section plane (--section-plane), when there is one")},
         0.0f)},
    extract};

}  // namespace

}  // namespace inkshade::geometry
