#include "geometry/line_types/object_line_registry.hpp"

#include <map>
#include <stdexcept>
#include <string>

#include "geometry/brush_names.hpp"
#include "inkshade/error.hpp"

namespace inkshade::geometry {

namespace {

std::map<std::string, ObjectLineType>& registered() {
    static std::map<std::string, ObjectLineType> map;
    return map;
}

// Stylised strokes (docs/lines.md): thickness along a stroke and colour; every default leaves
// the stroke as it was.
void add_thickness_and_color_params(std::vector<ParamSpec>& params) {
    params.push_back(
        float_param("taper-in", 0.0f, 0.0f, 100000.0f,
                    "the width grows from 0 at a stroke's start to full over this many pixels (Freestyle's "
                    "TaperShader); 0 = none"));
    params.push_back(float_param("taper-out", 0.0f, 0.0f, 100000.0f,
                                 "the width falls to 0 over this many pixels before a stroke's end; 0 = none"));
    params.push_back(list_param("depth-width", {1.0f, 1.0f}, 2, 0.0f, 16.0f,
                                "width factors at the model's nearest and farthest depth, linear between "
                                "(Blender's thickness modifier Distance from Camera)"));
    params.push_back(list_param("curvature-width", {1.0f, 1.0f}, 2, 0.0f, 16.0f,
                                "width factors at zero image curvature and at 1/curvature-radius and above, "
                                "linear between (Blender's Curvature 3D, measured in the image)"));
    params.push_back(float_param("curvature-radius", 10.0f, 0.1f, 100000.0f,
                                 "the radius (pixels) from which a bend takes the second curvature-width factor"));
    params.push_back(float_param("level-width", 1.0f, 0.0f, 16.0f,
                                 "width factor per occlusion level: width × level-width ^ level (thinner hidden "
                                 "lines)"));
    params.push_back(float_param("calligraphy", 0.0f, 0.0f, 1.0f,
                                 "strokes across the nib are this much thinner: factor 1 − calligraphy × (1 − |cos "
                                 "angle to the nib|) (Freestyle's CalligraphicShader)"));
    params.push_back(float_param("nib-angle", 90.0f, -180.0f, 180.0f,
                                 "the nib's direction in degrees from the image's +x, counter-clockwise: strokes "
                                 "along it are the thickest"));
    params.push_back(float_param("noise", 0.0f, 0.0f, 1.0f,
                                 "relative width noise along the stroke: width × (1 + noise × n), n smooth seeded "
                                 "value noise in [−1, 1] (Freestyle's ThicknessNoiseShader)"));
    params.push_back(float_param("noise-period", 50.0f, 1.0f, 100000.0f,
                                 "wavelength in pixels of the width noise and the sketch jitter along a stroke"));
    params.push_back(int_param("seed", 0, 0, 1000000,
                               "seed of the width noise and the sketch jitter (and of hatch strokes' layout)"));
    params.push_back(choice_param("color-along", {"none", "depth", "length"}, 0,
                                  "blend the colour towards color-end by depth (near → far over the model) or "
                                  "along the stroke (start → end)"));
    params.push_back(color_param("color-end", glm::vec3(0.0f), "the far (or end) colour of color-along"));
}

// Stylised strokes: caps and joins, dashes and brush, their coherence over frames, chain
// splitting and sketchy passes; every default leaves the stroke as it was.
void add_pattern_params(std::vector<ParamSpec>& params) {
    params.push_back(choice_param("cap", {"butt", "round", "square"}, 1, "the shape of a stroke's ends"));
    params.push_back(choice_param("join", {"miter", "round", "bevel"}, 1,
                                  "the shape of a stroke's corners (SVG; GPU strokes join round)"));
    params.push_back(list_param("dash", {0.0f}, 8, 0.0f, 100000.0f,
                                "dash pattern: on, off, ... lengths in pixels along each stroke (an odd list "
                                "repeats, as SVG's stroke-dasharray); 0 = solid"));
    params.push_back(choice_param("brush", brush_names(), 0,
                                  "GPU strokes' texture, repeated along the stroke, times its coverage (the SVG "
                                  "keeps the outline and names the brush in data-brush); none = solid"));
    params.push_back(float_param("brush-length", 0.0f, 0.0f, 100000.0f,
                                 "pixels of stroke per repeat of the brush texture; 0 = 4 x width"));
    params.push_back(bool_param("coherence", false,
                                "in a sequence of frames (batch views, animation, viewer), dashes, brush, noise "
                                "and jitter follow the previous frame's strokes instead of each chain's start "
                                "(Kalnins et al. 2003)"));
    params.push_back(choice_param("coherence-by", {"surface", "image"}, 0,
                                  "how coherence finds the previous frame's strokes: their surface points seen "
                                  "from this frame's camera (marks move with the surface), or their image "
                                  "points (marks stay where they were in the image)"));
    params.push_back(float_param("split-angle", 0.0f, 0.0f, 180.0f,
                                 "a stroke ends where its direction turns by more than this many degrees; 0 = "
                                 "never"));
    params.push_back(float_param("max-length", 0.0f, 0.0f, 1000000.0f,
                                 "longer strokes are cut into equal pieces of at most this many pixels; 0 = never"));
    params.push_back(bool_param("split-cusps", false, "a stroke ends at a cusp, where its image direction reverses"));
    params.push_back(
        int_param("sketch-passes", 1, 1, 8, "draw each stroke this many times, each pass displaced by sketch-jitter"));
    params.push_back(float_param("sketch-jitter", 0.0f, 0.0f, 100.0f,
                                 "the largest displacement in pixels of a sketch pass's points (smooth seeded noise)"));
}

// The occlusion levels drawn.
void add_level_params(std::vector<ParamSpec>& params) {
    params.push_back(int_param("min-level", 0, 0, kMaxOcclusionLevel,
                               "lowest occlusion level drawn: how many surfaces lie in front of a line (0 = "
                               "visible; quantitative invisibility, Appel 1967)"));
    params.push_back(int_param("max-level", 0, 0, kMaxOcclusionLevel,
                               "highest occlusion level drawn; levels from 1 up go to dashed layers TYPE-hidden-N "
                               "(SVG and JSON only)"));
    params.push_back(list_param("hidden-dash", {0.0f}, 8, 0.0f, 100000.0f,
                                "dash pattern of the hidden layers (SVG): on, off, ... lengths in pixels; 0 = 3 "
                                "and 2 times the stroke width"));
    params.push_back(bool_param("hidden", false,
                                "also output every hidden level, as dashed layers TYPE-hidden-N (technical "
                                "drawing convention; every max-level)"));
}

}  // namespace

ObjectLineRegistration::ObjectLineRegistration(LineType type, ExtractLineSegments extract, LineTypeNeeds needs) {
    if (needs.creases && !type.param("angle"))
        throw std::logic_error("line type " + type.name + " needs creases but has no angle parameter");
    type.space = LineSpace::Object;
    registered()[type.name] = {extract, needs};
    LineTypeRegistration{std::move(type)};
}

const ObjectLineType* object_line_type(const std::string& type_name) {
    auto it = registered().find(type_name);
    return it == registered().end() ? nullptr : &it->second;
}

std::vector<ParamSpec> object_line_params(glm::vec3 color, float width_px, std::vector<ParamSpec> own,
                                          float min_length_px) {
    std::vector<ParamSpec> params = stroke_params(color, width_px);
    for (auto& p : own) params.push_back(std::move(p));
    params.push_back(float_param("min-length", min_length_px, 0.0f, 10000.0f,
                                 "drop polylines shorter than this many pixels (after hidden-line removal): the "
                                 "specks curvature noise leaves (DeCarlo et al. 2003 §4 discard short pieces)"));
    params.push_back(int_param("smooth", 0, 0, 100,
                               "Laplacian smoothing iterations in the image (weight 0.5, ends fixed); 0 keeps the "
                               "exact interpolated points"));
    params.push_back(bool_param("taper", false,
                                "line strength (fading, e.g. suggestive contours near their trim point) scales "
                                "the stroke width instead of its opacity"));
    add_thickness_and_color_params(params);
    add_pattern_params(params);
    add_level_params(params);
    return params;
}

ParamSpec feature_size_param(const std::string& made_dimensionless) {
    return float_param("feature-size", 0.0f, 0.0f, 1e9f,
                       "world length making " + made_dimensionless +
                           " dimensionless; 0 = automatic, as rtsc: 1% of the reciprocal of the 10th percentile of "
                           "|k1|, |k2|, at most 5% of the bounding sphere's radius");
}

float line_number(const LineSettings& settings, const std::string& name) { return line_param(settings, name).at(0); }

glm::vec3 line_direction(const LineSettings& settings, const std::string& name) {
    const ParamValue& v = line_param(settings, name);
    const std::string what = settings.type + "." + name;
    if (v.size() != 3) throw InputError(what + " needs 3 numbers (x,y,z), got " + std::to_string(v.size()));
    const glm::vec3 d(v[0], v[1], v[2]);
    if (d == glm::vec3(0.0f)) throw InputError(what + " must not be 0,0,0");
    return d;
}

}  // namespace inkshade::geometry
