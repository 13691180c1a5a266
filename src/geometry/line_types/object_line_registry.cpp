#include "geometry/line_types/object_line_registry.hpp"

#include <map>
#include <string>

#include "inkshade/error.hpp"

namespace inkshade::geometry {

namespace {

struct Registered {
    ExtractLineSegments extract = nullptr;
    MeshLineNeeds needs;
};

std::map<std::string, Registered>& extractors() {
    static std::map<std::string, Registered> map;
    return map;
}

}  // namespace

ObjectLineRegistration::ObjectLineRegistration(LineType type, ExtractLineSegments extract, MeshLineNeeds needs) {
    type.space = LineSpace::Object;
    extractors()[type.name] = {extract, needs};
    LineTypeRegistration{std::move(type)};
}

ExtractLineSegments object_line_extractor(const std::string& type_name) {
    auto it = extractors().find(type_name);
    return it == extractors().end() ? nullptr : it->second.extract;
}

MeshLineNeeds object_line_needs(const std::string& type_name) {
    auto it = extractors().find(type_name);
    return it == extractors().end() ? MeshLineNeeds{} : it->second.needs;
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
    params.push_back(int_param("min-level", 0, 0, kMaxOcclusionLevel,
                               "lowest occlusion level drawn: how many surfaces lie in front of a line (0 = "
                               "visible; quantitative invisibility, Appel 1967)"));
    params.push_back(int_param("max-level", 0, 0, kMaxOcclusionLevel,
                               "highest occlusion level drawn; levels from 1 up go to dashed layers TYPE-hidden-N "
                               "(SVG and JSON only)"));
    params.push_back(bool_param("hidden", false,
                                "also output every hidden level, as dashed layers TYPE-hidden-N (technical "
                                "drawing convention; every max-level)"));
    return params;
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
