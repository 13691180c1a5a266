// `isophote`: lines of equal diffuse brightness n·l, as rtsc draws them (extract_isophotes).
#include <string>

#include "geometry/isophotes.hpp"
#include "geometry/line_types/object_line_registry.hpp"

namespace inkshade::geometry {

namespace {

std::vector<LineSegment> extract(MeshLineData& data, const LineView& view, const LineSettings& settings) {
    IsophoteOptions options;
    options.direction = line_direction(settings, "direction");
    options.levels = int(line_number(settings, "levels"));
    options.values = line_param(settings, "values");
    options.back_faces = line_number(settings, "back-faces") != 0.0f;
    return extract_isophotes(data.mesh(), data.normals(), view.camera, options);
}

const ObjectLineRegistration registration{
    {.name = "isophote",
     .summary = "isophotes: lines of equal diffuse brightness n·l for a light turning with the camera (rtsc)",
     .params = object_line_params(
         glm::vec3(0.6f), 1.0f,
         {list_param("direction", {0.0f, 0.0f, 1.0f}, 3, -1000.0f, 1000.0f,
                     "towards the light, in the camera's frame (x right, y up, z towards the viewer); rtsc's light "
                     "turns with the camera, default along its z axis (a headlight)"),
          int_param("levels", 20, 0, 1000,
                    "draw n·l = k / levels for every integer |k| < levels (rtsc's niso, 20); 0 = draw `values`"),
          list_param("values", {0.2f, 0.4f, 0.6f, 0.8f}, 32, -1.0f, 1.0f, "the n·l values drawn when levels = 0"),
          bool_param("back-faces", false,
                     "also on faces turned away from the viewer (rtsc culls faces whose three corners have n·v <= 0)")},
         1.0f)},
    extract};

}  // namespace

}  // namespace inkshade::geometry
