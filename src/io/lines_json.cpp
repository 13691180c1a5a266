// JSON form of a LineDrawing for scripts (--lines-json); schema in docs/lines.md:
// {"width", "height", "layers": [{"type", "params", "stroke", "paths": [{"hidden", "level", "closed",
// "points": [[x, y], ...], "depth": [...], "strength": [...], optional "width": [...] and
// "color": [[r, g, b], ...]}]}]}; with LinesJsonDetail::Full also "world": [[x, y, z], ...],
// "face": [...], "barycentric": [[b0, b1, b2], ...], "tangent": [[tx, ty], ...] and "normal".
// Numbers are rounded (1e-3 px, 1e-7 depth, 1e-4 strength) so the text is short and stable;
// world positions, barycentric weights, tangents and normals are the floats' shortest decimals.
#include <charconv>
#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "inkshade/line_drawing.hpp"

namespace inkshade {

namespace {

double rounded(double v, double unit) { return std::isfinite(v) ? std::round(v / unit) * unit : 0.0; }

// A float parameter as the double of its shortest decimal text (0.01, not 0.009999999776).
double clean(float v) { return std::isfinite(v) ? std::stod(format_number(v)) : 0.0; }

nlohmann::json param_json(const ParamSpec& spec, const ParamValue& value) {
    switch (spec.type) {
        case ParamType::Bool: return value.at(0) != 0.0f;
        case ParamType::Int: return int(std::lround(value.at(0)));
        case ParamType::Choice: return format_param_value(spec, value);
        case ParamType::Float: return clean(value.at(0));
        default: {
            nlohmann::json a = nlohmann::json::array();
            for (float v : value) a.push_back(clean(v));
            return a;
        }
    }
}

// The double of a float's shortest decimal text, which the JSON writes back as that text.
double shortest(float v) {
    if (!std::isfinite(v)) return 0.0;
    char buf[32];
    const auto end = std::to_chars(buf, buf + sizeof buf, v).ptr;
    double d = 0.0;
    std::from_chars(buf, end, d);
    return d;
}

nlohmann::json vec3_json(const glm::vec3& v) { return {shortest(v.x), shortest(v.y), shortest(v.z)}; }

// Each point's surface location (when the drawing kept it) and its image tangent and normal.
void add_point_detail(const LinePath& p, nlohmann::json& j) {
    if (!p.surface.empty()) {
        nlohmann::json world = nlohmann::json::array(), face = nlohmann::json::array(),
                       barycentric = nlohmann::json::array();
        for (const SurfacePoint& s : p.surface) {
            world.push_back(vec3_json(s.world));
            face.push_back(s.face);
            barycentric.push_back(vec3_json(s.barycentric));
        }
        j["world"] = world;
        j["face"] = face;
        j["barycentric"] = barycentric;
    }
    nlohmann::json tangent = nlohmann::json::array(), normal = nlohmann::json::array();
    for (const glm::vec2& t : path_tangents(p)) {
        tangent.push_back({shortest(t.x), shortest(t.y)});
        const glm::vec2 n = path_normal(t);
        normal.push_back({shortest(n.x), shortest(n.y)});
    }
    j["tangent"] = tangent;
    j["normal"] = normal;
}

nlohmann::json path_json(const LinePath& p, bool hidden, LinesJsonDetail detail) {
    nlohmann::json points = nlohmann::json::array(), depth = nlohmann::json::array(),
                   strength = nlohmann::json::array();
    for (const glm::vec2& q : p.points) points.push_back({rounded(q.x, 1e-3), rounded(q.y, 1e-3)});
    for (float d : p.depth) depth.push_back(rounded(d, 1e-7));
    for (float s : p.strength) strength.push_back(rounded(s, 1e-4));
    nlohmann::json j = {{"hidden", hidden}, {"level", p.level}, {"closed", p.closed},
                        {"points", points}, {"depth", depth},   {"strength", strength}};
    // Present only when the layer's stroke modifiers set them (docs/lines.md).
    if (!p.width.empty()) {
        nlohmann::json width = nlohmann::json::array();
        for (float w : p.width) width.push_back(rounded(w, 1e-3));
        j["width"] = width;
    }
    if (!p.color.empty()) {
        nlohmann::json color = nlohmann::json::array();
        for (const glm::vec3& c : p.color)
            color.push_back({rounded(c.r, 1e-4), rounded(c.g, 1e-4), rounded(c.b, 1e-4)});
        j["color"] = color;
    }
    if (detail == LinesJsonDetail::Full) add_point_detail(p, j);
    return j;
}

}  // namespace

std::string format_lines_json(const LineDrawing& drawing, LinesJsonDetail detail) {
    nlohmann::json layers = nlohmann::json::array();
    for (const LineLayer& layer : drawing.layers) {
        const LineType& type = line_type(layer.settings.type);
        nlohmann::json params = nlohmann::json::object();
        for (const ParamSpec& spec : type.params)
            params[spec.name] = param_json(spec, value_or_default(spec, layer.settings.params));
        const Stroke stroke = stroke_of(layer.settings);
        nlohmann::json paths = nlohmann::json::array();
        for (const LinePath& p : layer.visible) paths.push_back(path_json(p, false, detail));
        for (const LinePath& p : layer.hidden) paths.push_back(path_json(p, true, detail));
        layers.push_back({{"type", type.name},
                          {"lineset", layer.settings.lineset},
                          {"params", params},
                          {"stroke",
                           {{"color", {clean(stroke.color.r), clean(stroke.color.g), clean(stroke.color.b)}},
                            {"opacity", clean(stroke.opacity)},
                            {"width", clean(stroke.width)}}},
                          {"paths", paths}});
    }
    nlohmann::json root = {{"width", drawing.width}, {"height", drawing.height}, {"layers", layers}};
    return root.dump() + "\n";
}

}  // namespace inkshade
