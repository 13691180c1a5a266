// A model file's cameras and lights in a scene (`--camera`, `--lights file`; docs/inputs.md,
// "Cameras and lights"): the file's camera becomes camera options, exactly as if they were
// given by flags, and its light the scene's one light in the units the shading model takes.
#include "scene/file_scene.hpp"

#include <algorithm>
#include <cmath>

#include "core/name_suggestion.hpp"
#include "inkshade/error.hpp"
#include "scene/option_name.hpp"

namespace inkshade {

namespace {

std::string light_type_name(FileLightType type) {
    switch (type) {
        case FileLightType::Directional: return "directional";
        case FileLightType::Point: return "point";
        case FileLightType::Spot: return "spot";
    }
    return "?";
}

// "0 'Main', 1 'Top'": the cameras as `--camera` takes them (at most 20).
std::string camera_list(const std::vector<FileCamera>& cameras) {
    std::string out;
    for (size_t i = 0; i < cameras.size() && i < 20; ++i)
        out += (i ? ", " : "") + std::to_string(i) + " '" + cameras[i].name + "'";
    if (cameras.size() > 20) out += ", ... (" + std::to_string(cameras.size()) + " in all)";
    return out;
}

// The camera `text` names: a name (exactly, else ignoring case), else an index.
const FileCamera& find_camera(const std::vector<FileCamera>& cameras, const std::string& text,
                              const std::string& option, const std::string& model) {
    for (const FileCamera& c : cameras)
        if (c.name == text) return c;
    for (const FileCamera& c : cameras)
        if (equal_ignoring_case(c.name, text)) return c;
    const bool digits = !text.empty() && text.size() < 10 &&
                        std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (digits && std::stoul(text) < cameras.size()) return cameras[std::stoul(text)];
    std::vector<std::string> names;
    for (const FileCamera& c : cameras) names.push_back(c.name);
    throw InputError(option + ": " + model + " has no camera " + (digits ? text : "'" + text + "'") +
                     (digits ? "" : did_you_mean(text, names)) + "; its cameras: " + camera_list(cameras));
}

// The camera options that place and project the view as the file's camera does: eye at the
// node, looking along its -Z with its +Y up; the target is the point of the view axis nearest
// the model's centre (the centre of an orbit in the viewer), at least a model radius ahead.
CameraOptions camera_options(const FileCamera& c, const BoundingBox& box, UpAxis up_axis) {
    const NodePlacement& p = c.placement;
    const float radius = std::max(0.5f * box.diagonal(), 1e-6f);
    const float ahead = std::max(glm::dot(box.center() - p.position, p.forward), radius);
    CameraOptions o;
    o.up_axis = up_axis;  // eye, target and up stay in the model's coordinates whatever the axis
    o.eye = p.position;
    o.target = p.position + ahead * p.forward;
    o.up = p.up;
    o.orthographic = c.orthographic;
    if (c.orthographic)
        o.ortho_height = 2.0f * c.ymag;
    else
        o.fov_degrees = c.yfov_degrees;
    o.near_plane = c.znear;
    o.far_plane = c.zfar;  // unset (a perspective camera's infinite far): fitted to the model
    return o;
}

// The image size with the camera's aspect, its longer side that of `size`.
void take_aspect(RenderOptions& options, float aspect) {
    if (!(aspect > 0.0f) || !std::isfinite(aspect)) return;
    const int side = std::max(options.width, options.height);
    const auto scaled = [](float v) { return std::clamp(int(std::lround(v)), 1, 16384); };
    if (aspect >= 1.0f)
        options.width = side, options.height = scaled(float(side) / aspect);
    else
        options.width = scaled(float(side) * aspect), options.height = side;
}

}  // namespace

LightUnits light_units(const ShadingSelection& shading) {
    const ShadingModel& model = shading_model(shading.model);
    if (model.param("light-intensity")) return LightUnits::ThreejsParams;
    if (const ParamSpec* c = model.param("convention"); c && c->type == ParamType::Choice) {
        const auto it = std::find(c->choices.begin(), c->choices.end(), "threejs");
        if (it != c->choices.end() && int(value_or_default(*c, shading.params).at(0)) == it - c->choices.begin())
            return LightUnits::Physical;
    }
    return LightUnits::Display;
}

Light file_scene_light(const FileLight& f, const Style& style, const BoundingBox& box) {
    Light l;
    apply_style_light(style, l);  // the ambient, and the light colour display models scale
    const NodePlacement& p = f.placement;
    switch (f.type) {
        case FileLightType::Directional:
            // Placed as the default key light, at 1.5 diagonals from the centre, shining along -Z.
            l.type = LightType::Directional;
            l.target = box.center();
            l.position = box.center() - p.forward * 1.5f * std::max(box.diagonal(), 1e-6f);
            break;
        case FileLightType::Point:
            l.type = LightType::Point;
            l.position = p.position;
            l.target = box.center();
            break;
        case FileLightType::Spot:
            l.type = LightType::Spot;
            l.position = p.position;
            l.target = p.position + p.forward;
            l.cos_inner = std::cos(f.inner_cone_angle);
            l.cos_outer = std::cos(f.outer_cone_angle);
            break;
    }
    l.range = f.range.value_or(0.0f);
    switch (light_units(style.shading)) {
        case LightUnits::ThreejsParams:  // intensity, decay, distance: Scene::shading
            l.color = f.color;
            l.intensity = 1.0f;
            break;
        case LightUnits::Physical:  // three.js's GLTFLoader: intensity as it is, decay 2, distance = range
            l.color = f.color;
            l.intensity = f.intensity;
            l.decay = 2.0f;
            l.physical_falloff = f.type != FileLightType::Directional;
            break;
        case LightUnits::Display: l.color *= f.color; break;  // the style's strength, the file's tint
    }
    return l;
}

std::vector<std::string> Scene::apply_file_scene(const Mesh& mesh) {
    std::vector<std::string> warnings;
    // Python sets the mesh itself: no file name to give.
    const std::string file = model.empty() ? "the mesh" : model;
    if (!file_camera.empty()) {
        const std::string option = option_name(names, "camera");
        if (mesh.cameras.empty()) throw InputError(option + ": " + file + " has no cameras");
        const FileCamera& c = find_camera(mesh.cameras, file_camera, option, file);
        camera = camera_options(c, mesh.bounds(), camera.up_axis.value_or(UpAxis::PosY));
        if (size_from_camera) {
            if (c.orthographic)
                take_aspect(options, c.xmag / c.ymag);
            else if (c.aspect_ratio)
                take_aspect(options, *c.aspect_ratio);
        }
    }
    if (lights == LightSource::File) {
        const std::string option = option_name(names, "lights") + " file: " + file;
        // One line for the problem: the unusable light itself when it was the only one.
        if (mesh.lights.empty() && !mesh.unusable_lights.empty())
            throw InputError(option + ": " + mesh.unusable_lights.front());
        if (mesh.lights.empty()) throw InputError(option + " has no lights (glTF KHR_lights_punctual)");
        for (const std::string& unusable : mesh.unusable_lights) warnings.push_back(file + ": " + unusable + "; ignored");
        file_light = mesh.lights.front();
        if (mesh.lights.size() > 1)
            warnings.push_back(file + ": " + std::to_string(mesh.lights.size()) +
                               " lights; Inkshade shades with one, the first: '" + file_light->name + "' (" +
                               light_type_name(file_light->type) + ")");
    }
    return warnings;
}

ShadingSelection Scene::shading() const {
    ShadingSelection s = style.shading;
    if (file_light && light_units(s) == LightUnits::ThreejsParams) {
        // three.js's GLTFLoader: intensity as it is, decay 2, distance = range (0: infinite).
        s.params["light-intensity"] = {file_light->intensity};
        s.params["light-decay"] = {2.0f};
        s.params["light-distance"] = {file_light->range.value_or(0.0f)};
    }
    return s;
}

}  // namespace inkshade
