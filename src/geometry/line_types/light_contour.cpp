// `light-contour`: where the key light grazes the surface, n·l = 0 interpolated across faces
// (extract_light_contours): the shadow terminator of smooth shading, seen from the camera.
#include "geometry/light_contours.hpp"
#include "geometry/line_types/object_line_registry.hpp"

namespace inkshade::geometry {

namespace {

std::vector<LineSegment> extract(MeshLineData& data, const LineView& view, const LineSettings&) {
    return extract_light_contours(data.mesh(), data.normals(), view.light);
}

const ObjectLineRegistration registration{
    {.name = "light-contour",
     .summary = "light contours: zero crossings of n·l for the key light (directional: its direction; point: "
                "towards its position), the smooth shading's terminator",
     .params = object_line_params(glm::vec3(0.35f), 1.0f, {}, 1.0f)},
    extract};

}  // namespace

}  // namespace inkshade::geometry
