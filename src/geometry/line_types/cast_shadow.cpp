// `cast-shadow`: the boundaries of the shadows the key light casts onto the surfaces, found by
// rays towards the light (extract_cast_shadows), seen from the camera.
#include "geometry/cast_shadows.hpp"
#include "geometry/line_types/object_line_registry.hpp"

namespace inkshade::geometry {

namespace {

std::vector<LineSegment> extract(MeshLineData& data, const LineView& view, const LineSettings&) {
    return extract_cast_shadows(data.mesh(), data.normals(), view.light, view.scene);
}

const ObjectLineRegistration registration{
    {.name = "cast-shadow",
     .summary = "cast shadows: boundaries of the shadows the key light casts onto the surfaces (rays towards "
                "the light)",
     .params = object_line_params(glm::vec3(0.2f), 1.0f, {}, 1.0f)},
    extract};

}  // namespace

}  // namespace inkshade::geometry
