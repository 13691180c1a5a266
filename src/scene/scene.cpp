// make_scene: the request's values checked once for every front end, and its style resolved
// (named style or shading model, a three.js scene's lights, --set overrides, colour options).
#include "inkshade/scene.hpp"

#include <algorithm>
#include <cmath>
#include <cctype>
#include <functional>
#include <sstream>
#include <tuple>

#include "core/name_suggestion.hpp"
#include "inkshade/error.hpp"
#include "inkshade/mesh_writer.hpp"
#include "inkshade/options.hpp"
#include "io/mtoon_detection.hpp"
#include "io/text_scanner.hpp"
#include "scene/file_scene.hpp"
#include "scene/option_name.hpp"

namespace inkshade {

namespace {

void check_color(const std::optional<glm::vec4>& c, const char* option, OptionNames names) {
    if (!c) return;
    for (int i = 0; i < 4; ++i)
        if (!((*c)[i] >= 0.0f && (*c)[i] <= 1.0f))
            throw InputError(option_name(names, option) + ": components must be in [0, 1]");
}

constexpr float kMaxMorphWeight = 1000.0f;

// The pose's values; the names are the model file's, checked when it loads.
void check_pose(const SceneRequest& r) {
    for (const auto& [list, option] : {std::pair{&r.expressions, "expression"}, std::pair{&r.morphs, "morph"}})
        for (const NamedWeight& w : *list) {
            if (w.name.empty()) throw InputError(option_name(r.names, option) + ": empty name");
            if (!std::isfinite(w.weight)) throw InputError(option_name(r.names, option) + ": weights must be finite");
            if (list == &r.expressions && !(w.weight >= 0.0f && w.weight <= 1.0f))
                throw InputError(option_name(r.names, option) + ": " + w.name +
                                 ": expression weights are in [0, 1], got " + (std::ostringstream() << w.weight).str());
            // Morph weights are 0..1 in use; a thousand times a target's offsets is already far
            // outside any model, and a larger weight would only fail later on a vertex.
            if (list == &r.morphs && !(std::abs(w.weight) <= kMaxMorphWeight))
                throw InputError(option_name(r.names, option) + ": " + w.name + ": morph weights are in [-" +
                                 std::to_string(int(kMaxMorphWeight)) + ", " + std::to_string(int(kMaxMorphWeight)) +
                                 "], got " + (std::ostringstream() << w.weight).str());
        }
}

// The style as the request names it, before any override.
Style named_style(const SceneRequest& r) {
    if (!r.style.empty() && !r.shading.empty())
        throw InputError(option_name(r.names, "style") + " and " + option_name(r.names, "shading") +
                         " are alternatives: use one (a style names its shading model)");
    if (r.style_data && r.style.empty() && r.shading.empty()) return *r.style_data;
    Style s = !r.shading.empty() ? shading_model_style(r.shading)  // the model's defaults, not a preset's
                                 : load_style(r.style.empty() ? default_style_name(r.model) : r.style);
    if (const auto& data = r.style_data) {
        // A scene's lights and background stay the scene's whatever the look.
        s.light_color = data->light_color;
        s.ambient = data->ambient;
        s.background = data->background;
        const ShadingModel& model = shading_model(s.shading.model);
        if (auto it = data->shading.params.find("ambient-intensity");
            it != data->shading.params.end() && model.param("ambient-intensity"))
            s.shading.params["ambient-intensity"] = it->second;
        for (LightValue which : {LightValue::Intensity, LightValue::Decay, LightValue::Distance})
            if (const std::optional<float> v = light_value(*data, which)) set_light_value(s, which, *v);
    }
    return s;
}

// The line types `names` lists, each named once (any case; InputError with the closest name for
// an unknown one), for the errors of `option`; `check` sees each as typed before the repeat test.
std::vector<const LineType*> listed_line_types(
    const std::vector<std::string>& names, const std::string& option,
    const std::function<void(const std::string& typed, const LineType&)>& check = {}) {
    std::vector<const LineType*> types;
    for (const std::string& name : names) {
        if (name.empty()) throw InputError(option + ": empty line type name");
        const LineType& type = line_type(name);
        if (check) check(name, type);
        if (std::find(types.begin(), types.end(), &type) != types.end())
            throw InputError(option + ": '" + type.name + "' is listed twice");
        types.push_back(&type);
    }
    return types;
}

// The line types the request adds to an image's style, before the overrides so that
// TYPE.param=value reaches them; a type the style draws keeps its parameters.
void add_lines(const SceneRequest& r, Style& s) {
    for (const LineType* type : listed_line_types(r.added_lines, option_name(r.names, "lines")))
        if (std::none_of(s.lines.begin(), s.lines.end(), [&](const LineSettings& l) { return l.type == type->name; }))
            s.lines.push_back({type->name, {}});
}

// --set overrides, then the colour options, which win over the style's.
void apply_overrides(const SceneRequest& r, Style& s) {
    for (const std::string& set : r.sets) {
        try {
            apply_override(s, set);
        } catch (const InputError& e) {
            throw InputError(option_name(r.names, "set") + " " + set + ": " + e.what());
        }
    }
    if (r.base_color) {
        // An explicit colour multiplies the mesh's own colours; a style's `mesh-colors = false`
        // (ink's fill) still leaves them out.
        s.shading.base_color = *r.base_color;
        if (s.shading.base_color_use == BaseColorUse::Fallback) s.shading.base_color_use = BaseColorUse::Multiply;
    }
    if (r.background) s.background = *r.background;
    if (r.light_color) s.light_color = *r.light_color;
    if (r.ambient) s.ambient = *r.ambient;
    const std::tuple<const std::optional<float>&, LightValue, const char*> values[] = {
        {r.light_intensity, LightValue::Intensity, "light-intensity"},
        {r.light_decay, LightValue::Decay, "light-decay"},
        {r.light_distance, LightValue::Distance, "light-distance"}};
    for (const auto& [value, which, option] : values)
        if (value) {
            try {
                set_light_value(s, which, *value);
            } catch (const InputError& e) {
                std::string what = e.what();
                // "light-intensity: expected ..." or "parameter light-intensity: ...": the option's name instead
                if (size_t colon = what.find(": "); colon != std::string::npos) what = what.substr(colon + 2);
                throw InputError(option_name(r.names, option) + ": " + what);
            }
        }
}

// The object-space line types of the line drawing, in order, with the style's parameters where
// it has them.
std::vector<LineSettings> select_vector_lines(const Style& style, const SceneRequest& r) {
    auto from_style = [&](const std::string& name) {
        for (const LineSettings& l : style.lines)
            if (l.type == name) return l;
        return LineSettings{name, {}};
    };
    std::vector<LineSettings> out;
    if (!r.vector_lines) {
        for (const LineSettings& l : style.lines)
            if (line_type(l.type).space == LineSpace::Object) out.push_back(l);
        if (out.empty())
            for (const std::string& name : default_vector_lines()) out.push_back(from_style(name));
        return out;
    }
    const std::string option = option_name(r.names, "vector-lines");
    const auto object_space = [&](const std::string& typed, const LineType& type) {
        if (type.space == LineSpace::Object) return;
        std::string names;
        for (const LineType* t : line_types())
            if (t->space == LineSpace::Object) names += (names.empty() ? "" : ", ") + t->name;
        throw InputError(option + ": '" + typed + "' is drawn in the image by `inkshade render`, not as vector " +
                         "lines (choose " + names + ")");
    };
    for (const LineType* type : listed_line_types(*r.vector_lines, option, object_space))
        out.push_back(from_style(type->name));
    if (out.empty()) throw InputError(option + ": no line type given");
    return out;
}

// The file's camera places and projects the view, and its light replaces the key light: the
// options that would do the same are refused beside them rather than ignored.
void check_file_scene_alternatives(const SceneRequest& r) {
    auto name = [&](const char* option) { return option_name(r.names, option); };
    if (!r.file_camera.empty()) {
        const CameraOptions& o = r.camera;
        const std::pair<bool, const char*> given[] = {{bool(o.azimuth_degrees), "azimuth"},
                                                      {bool(o.elevation_degrees), "elevation"},
                                                      {bool(o.distance), "distance"},
                                                      {bool(o.eye), "eye"},
                                                      {bool(o.target), "target"},
                                                      {bool(o.up), "up"},
                                                      {o.fov_degrees != CameraOptions{}.fov_degrees, "fov"},
                                                      {o.orthographic, "ortho"},
                                                      {bool(o.ortho_height), "ortho-height"},
                                                      {bool(o.near_plane), "near"},
                                                      {bool(o.far_plane), "far"}};
        for (const auto& [set, option] : given)
            if (set)
                throw InputError(name("camera") + " and " + name(option) +
                                 " are alternatives: the file's camera places and projects the view");
    }
    if (r.lights == LightSource::File) {
        const std::pair<bool, const char*> given[] = {{bool(r.light_position), "light-pos"},
                                                      {bool(r.light_target), "light-target"},
                                                      {r.light_type != LightType::Directional, "light-type"}};
        for (const auto& [set, option] : given)
            if (set)
                throw InputError(name("lights") + " file and " + name(option) +
                                 " are alternatives: the file's light is placed by its node");
    }
}

// The camera's checks beyond the option table's ranges (make_scene checks those).
void check_camera_options(const CameraOptions& o, OptionNames names) {
    auto name = [&](const char* option) { return option_name(names, option); };
    for (auto [value, option] : {std::pair{o.azimuth_degrees, "azimuth"}, std::pair{o.elevation_degrees, "elevation"}})
        if (value && !std::isfinite(*value)) throw InputError(name(option) + ": must be a finite number");
    if (o.distance && !(*o.distance > 0.0f && std::isfinite(*o.distance)))
        throw InputError(name("distance") + ": must be a positive number");
    for (auto [value, option] : {std::pair{o.eye, "eye"}, std::pair{o.target, "target"}, std::pair{o.up, "up"}})
        if (value && !is_finite(*value)) throw InputError(name(option) + ": must be finite");
    if (o.up && glm::length(*o.up) == 0.0f) throw InputError(name("up") + ": must not be zero");
    const auto& near = o.near_plane;
    const auto& far = o.far_plane;
    if (near && !std::isfinite(*near)) throw InputError(name("near") + ": must be a finite number");
    // An orthographic view may start behind the eye (three.js allows a negative near).
    if (near && !(*near > 0.0f) && !o.orthographic) throw InputError(name("near") + ": must be a positive number");
    if (far && !(std::isfinite(*far) && *far > near.value_or(0.0f)))
        throw InputError(name("far") + ": must be greater than " + name("near"));
    if (o.ortho_height && !(*o.ortho_height > 0.0f && std::isfinite(*o.ortho_height)))
        throw InputError(name("ortho-height") + ": must be a positive number");
}

// The AOV names of the request, each once.
AovSet parse_aovs(const SceneRequest& r) {
    const std::string option = option_name(r.names, "aov");
    AovSet set = aov_set(option, r.aovs);
    if (r.lineset_ids.value_or(false)) set.add(Aov::LineSets);
    if (!set.empty() && !r.outputs.image)
        throw InputError(option + ": AOVs come with an image (`render`), not with a line drawing alone");
    return set;
}

}  // namespace

std::string default_style_name(const std::string& model) {
    // A file with MToon materials is authored for three-vrm's look (docs/mtoon.md, "One command").
    return io::uses_mtoon_materials(model) ? "vrm" : "lambert";
}

AovSet aov_set(const std::string& option, const std::vector<std::string>& names) {
    AovSet set;
    for (const std::string& name : names) {
        const std::optional<Aov> aov = aov_named(name);
        if (!aov) {
            std::string valid;
            for (const std::string& n : aov_names()) valid += (valid.empty() ? "" : ", ") + n;
            throw InputError(option + ": unknown AOV '" + name + "' (expected " + valid + ")" +
                             did_you_mean(name, aov_names()));
        }
        if (set.contains(*aov)) throw InputError(option + ": '" + aov_name(*aov) + "' is listed twice");
        set.add(*aov);
    }
    return set;
}

OcclusionLevels parse_occlusion_levels(const std::string& text) {
    auto fail = [&]() -> OcclusionLevels {
        throw InputError("occlusion levels: expected A-B with 0 <= A <= B <= " + std::to_string(kMaxOcclusionLevel) +
                         " (0 = visible), A, or A- for A and deeper; got '" + text + "'");
    };
    auto number = [&](const std::string& digits) {
        if (digits.empty() || digits.size() > 3 || !std::all_of(digits.begin(), digits.end(), ::isdigit)) fail();
        const int v = std::stoi(digits);
        if (v > kMaxOcclusionLevel) fail();
        return v;
    };
    const size_t dash = text.find('-');
    if (dash == std::string::npos) {
        const int a = number(text);
        return {a, a};
    }
    const int a = number(text.substr(0, dash));
    const std::string rest = text.substr(dash + 1);
    const int b = rest.empty() ? kMaxOcclusionLevel : number(rest);
    if (b < a) fail();
    return {a, b};
}

const std::vector<std::string>& default_vector_lines() {
    // The lines of a classic line drawing: outline, interior shape cues, sharp edges, open edges.
    static const std::vector<std::string> lines = {"contour", "suggestive", "crease", "border"};
    return lines;
}

void check_request(const SceneRequest& r) {
    auto name = [&](const char* option) { return option_name(r.names, option); };
    if (r.size.x < 1 || r.size.y < 1 || r.size.x > 16384 || r.size.y > 16384)
        throw InputError(name("size") + ": each side must be in 1..16384, got " + std::to_string(r.size.x) + "x" +
                         std::to_string(r.size.y));
    check_option_values(r);  // every range and choice of the option table
    check_camera_options(r.camera, r.names);
    for (auto [value, option] : {std::pair{r.light_position, "light-pos"}, std::pair{r.light_target, "light-target"}})
        if (value && !is_finite(*value)) throw InputError(name(option) + ": must be finite");
    for (auto [value, option] : {std::pair{r.light_color, "light-color"}, std::pair{r.ambient, "ambient"},
                                 std::pair{r.base_color, "base-color"}})
        check_color(value ? std::optional<glm::vec4>(glm::vec4(*value, 1.0f)) : std::nullopt, option, r.names);
    check_color(r.background, "background", r.names);
    check_pose(r);
    if (!r.outputs.image && !r.outputs.line_drawing) throw InputError("the request asks for no output");
    check_file_scene_alternatives(r);
    parse_aovs(r);
    if (!r.export_mesh.empty() && !is_mesh_export_path(r.export_mesh) && r.export_mesh != "obj" &&
        r.export_mesh != "ply")
        throw InputError(name("export-mesh") + ": expected FILE.obj or FILE.ply (batch: obj or ply), got " +
                         io::quote_token(r.export_mesh));
    if (r.svg_fill && !r.outputs.line_drawing)
        throw InputError(name("svg-fill") + ": fills come with an SVG line drawing (`lines`), not with an image alone");
}

Scene make_scene(const SceneRequest& r) {
    check_request(r);
    const AovSet aovs = parse_aovs(r);
    Scene scene;
    scene.model = r.model;
    const Style named = named_style(r);
    if (r.outputs.image) {
        scene.style = named;
        add_lines(r, scene.style);
        apply_overrides(r, scene.style);
    }
    if (r.outputs.line_drawing) {
        // Overrides after the selection, so TYPE.param=value reaches a type that --lines adds.
        Style lines_style = named;
        lines_style.lines = select_vector_lines(named, r);
        if (r.occlusion_levels)
            for (LineSettings& l : lines_style.lines) {
                l.params["min-level"] = {float(r.occlusion_levels->min)};
                l.params["max-level"] = {float(r.occlusion_levels->max)};
            }
        if (r.hidden)
            for (LineSettings& l : lines_style.lines) l.params["hidden"] = {1.0f};
        apply_overrides(r, lines_style);  // hidden=0 given by --set wins over `hidden`
        scene.vector_lines = lines_style.lines;
        if (!r.outputs.image) scene.style = std::move(lines_style);
    }
    scene.options.width = r.size.x;
    scene.options.height = r.size.y;
    scene.options.samples = r.samples;
    scene.options.background = scene.style.background;
    scene.options.srgb_output = r.srgb;
    scene.options.bit_depth = r.bit_depth;
    if (!r.section_plane.empty())
        scene.section_plane = parse_section_plane(option_name(r.names, "section-plane"), r.section_plane);
    scene.aovs = aovs;
    scene.options.aovs = aovs.gpu();
    scene.camera = r.camera;
    scene.light_type = r.light_type;
    scene.light_position = r.light_position;
    scene.light_target = r.light_target;
    scene.smooth_angle = r.smooth_angle.value_or(scene.style.smooth_angle.value_or(LoadOptions{}.smooth_angle));
    scene.time = r.time.value_or(0.0f);
    scene.animation = r.animation;
    scene.expressions = r.expressions;
    scene.morphs = r.morphs;
    scene.spring_bones = r.spring_bones;
    scene.camera.up_axis = r.camera.up_axis.value_or(scene.style.up_axis.value_or(UpAxis::PosY));
    // The three.js convention: a scene file's, the threejs-* models (unlit ones too), mtoon's
    // threejs convention.
    if (r.style_data || scene.style.shading.model.starts_with("threejs-") ||
        light_units(scene.style.shading) != LightUnits::Display)
        scene.normal_weighting = NormalWeighting::Area;
    scene.names = r.names;
    scene.file_camera = r.file_camera;
    scene.size_from_camera = r.size_from_camera;
    scene.lights = r.lights;
    scene.svg_fill = r.svg_fill;
    scene.lines_json_detail = r.lines_json_detail;
    apply_drawing_sheet(r, scene);
    return scene;
}

LoadOptions Scene::load_options() const {
    return LoadOptions{.smooth_angle = smooth_angle,
                       .normal_weighting = normal_weighting,
                       .pose = {.animation = animation,
                                .time = time,
                                .expressions = expressions,
                                .morphs = morphs,
                                .spring_bones = spring_bones}};
}

Camera Scene::frame(const BoundingBox& box) const { return frame(box, float(options.width) / float(options.height)); }

Camera Scene::frame(const BoundingBox& box, float aspect) const { return frame_camera(box, camera, aspect); }

Camera Scene::frame(const Mesh& mesh) const { return frame(mesh, float(options.width) / float(options.height)); }

Camera Scene::frame(const Mesh& mesh, float aspect) const {
    return frame_camera(mesh.bounds(), camera, aspect, mesh.positions);
}

Light Scene::light(const BoundingBox& box, const Camera& cam) const {
    if (file_light) return file_scene_light(*file_light, style, box);
    Light l = default_light(box, cam);
    l.type = light_type;
    if (light_position) l.position = *light_position;
    if (light_target) l.target = *light_target;
    if (l.type == LightType::Directional && l.position == l.target)
        throw InputError(option_name(names, "light-pos") +
                         ": equals the light's target, so a directional light has no direction");
    apply_style_light(style, l);
    // mtoon's threejs convention: a point light fades as three.js's does (the threejs-* models
    // apply their own light-decay and light-distance parameters in their shaders).
    l.physical_falloff = l.type != LightType::Directional && light_units(style.shading) == LightUnits::Physical;
    return l;
}

Image render_scene(Renderer& renderer, const Scene& scene, const Camera& camera, const Light& light,
                   std::vector<PassTiming>* timings) {
    RenderOptions options = scene.options;
    options.time = scene.time;  // mtoon's UV animation
    return renderer.render(camera, light, scene.shading(), scene.style.lines, options, timings);
}

LineDrawing draw_scene_lines(LineExtractor& extractor, const Scene& scene, const Camera& camera,
                             std::vector<LineTiming>* timings, StrokeSequence* sequence) {
    const LineContext context{.light = scene.light(extractor.bounds(), camera),
                              .section = scene.section_plane,
                              .surface = scene.lines_json_detail == LinesJsonDetail::Full};
    LineDrawing drawing = extractor.draw(camera, scene.options.width, scene.options.height, scene.vector_lines,
                                         timings, sequence, context);
    if (scene.paper_mm) drawing.paper_mm = *scene.paper_mm;
    if (scene.svg_fill)
        drawing.fills = extractor.fills(camera, scene.options.width, scene.options.height, context,
                                        scene.style.shading.base_color);
    return drawing;
}

}  // namespace inkshade
