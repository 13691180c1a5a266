// `topo`: topographic lines, level sets of height along a direction — rtsc's lines of constant
// depth by default, or a map's contour lines along a world axis (extract_topo_lines).
#include "geometry/line_types/object_line_registry.hpp"
#include "geometry/topo_lines.hpp"

namespace inkshade::geometry {

namespace {

std::vector<LineSegment> extract(MeshLineData& data, const LineView& view, const LineSettings& settings) {
    TopoOptions options;
    options.direction = line_direction(settings, "direction");
    options.world = line_number(settings, "frame") != 0.0f;
    options.count = int(line_number(settings, "count"));
    options.spacing = line_number(settings, "spacing");
    options.offset = line_number(settings, "offset");
    options.back_faces = line_number(settings, "back-faces") != 0.0f;
    return extract_topo_lines(data.mesh(), data.normals(), view.camera, options);
}

const ObjectLineRegistration registration{
    {.name = "topo",
     .summary = "topographic lines: level sets of height along a direction, by default depth as rtsc draws them",
     .params = object_line_params(
         glm::vec3(0.5f), 1.0f,
         {list_param("direction", {0.0f, 0.0f, 1.0f}, 3, -1000.0f, 1000.0f,
                     "the direction of increasing height (default: the camera's z axis, lines of constant depth "
                     "as rtsc draws them)"),
          choice_param("frame", {"camera", "world"}, 0,
                       "the frame of `direction`: the camera's (x right, y up, z towards the viewer) or world "
                       "coordinates (e.g. 0,1,0 for a model with +y up: a map's contour lines)"),
          int_param("count", 20, 1, 1000,
                    "lines across the bounding sphere's diameter, from its lowest point (rtsc's ntopo, 20); "
                    "used when spacing is 0"),
          float_param("spacing", 0.0f, 0.0f, 1e9f,
                      "world units between lines, heights measured from the origin; 0 = the diameter / count"),
          float_param("offset", 0.0f, -1000.0f, 1000.0f,
                      "shift of every line in units of the spacing (rtsc's topo_offset, 0)"),
          bool_param("back-faces", false,
                     "also on faces turned away from the viewer (rtsc culls faces whose three corners have n·v <= 0)")},
         1.0f)},
    extract};

}  // namespace

}  // namespace inkshade::geometry
