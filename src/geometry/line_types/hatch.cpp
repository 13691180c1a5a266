// `hatch` (optional line type): hatching strokes along the principal directions, drawn where
// the surface is dark (Hertzmann & Zorin 2000; trace_hatching, hatch_segments).

#include "geometry/isolines.hpp"
#include "geometry/line_types/object_line_registry.hpp"

namespace inkshade::geometry {

namespace {

std::vector<LineSegment> extract(MeshLineData& data, const LineView& line_view, const LineSettings& settings) {
    const HatchOptions options{.spacing = line_number(settings, "spacing"),
                               .density = line_number(settings, "density"),
                               .levels = int(line_number(settings, "levels")),
                               .cross = line_number(settings, "cross") != 0.0f,
                               .smoothing = int(line_number(settings, "smoothing")),
                               .seed = uint32_t(line_number(settings, "seed"))};
    const Hatching& hatching = data.hatching(options);
    // The light is given in camera space (x right, y up, z towards the viewer), as rtsc's
    // light follows the camera; the renderer's default key light comes from the same side.
    const glm::dvec3 light =
        camera_to_world(line_view.camera, glm::dvec3(line_direction(settings, "light")), "hatch.light");
    HatchView view;
    view.light = glm::vec3(light);
    for (size_t i = 0; i < line_param(settings, "tones").size(); ++i)
        view.thresholds.push_back(line_param(settings, "tones").at(i));
    view.fade = line_number(settings, "fade");
    view.thin = line_number(settings, "thin");
    return hatch_segments(data.mesh(), data.normals(), hatching, line_view.camera, view);
}

const ObjectLineRegistration registration{
    {.name = "hatch",
     .summary = "hatching along principal curvature directions, denser where darker (Hertzmann & Zorin 2000)",
     .params = object_line_params(
         glm::vec3(0.0f), 0.75f,
         {float_param("spacing", 0.0f, 0.0f, 1e9f,
                      "world distance between neighbouring strokes of the lightest level; 0 = 1.5% of the "
                      "bounding-box diagonal / density"),
          float_param("density", 1.0f, 0.01f, 100.0f,
                      "with spacing 0: strokes this many times denser than at 1.5% of the diagonal apart"),
          int_param("levels", 2, 1, 4, "density levels per direction, each adding strokes halfway between"),
          bool_param("cross", true, "also strokes across the first direction (cross-hatching)"),
          list_param("tones", {0.8f, 0.6f, 0.4f, 0.2f}, 8, 0.0f, 1.0f,
                     "a level's strokes are drawn where the Lambertian tone n·l is below its value: first "
                     "direction's levels, then the cross direction's; levels without a value are not drawn"),
          list_param("light", {-0.6f, 0.8f, 1.0f}, 3, -1e6f, 1e6f,
                     "direction towards the light in camera space (x right, y up, z towards the viewer); "
                     "the default is the renderer's default key light"),
          float_param("fade", 0.05f, 0.0f, 1.0f, "strokes fade in over this much tone below their threshold"),
          float_param("thin", 0.25f, 0.0f, 1.0f,
                      "level k > 0 fades out where n·v < thin·2^(k−1), so strokes do not crowd towards the "
                      "outline; 0 = never"),
          int_param("smoothing", 30, 0, 1000, "smoothing iterations of the principal-direction field")},
         0.0f)},
    extract,
    {.adjacency = true, .curvature = true}};

}  // namespace

}  // namespace inkshade::geometry
