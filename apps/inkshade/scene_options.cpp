#include "scene_options.hpp"

#include <charconv>
#include <cmath>
#include <sstream>

#include "inkshade/color.hpp"
#include "inkshade/error.hpp"

namespace inkshade::cli {

glm::vec3 parse_vec3(const std::string& option, const std::string& text) {
    glm::vec3 v(0.0f);
    std::stringstream ss(text);
    std::string item;
    int i = 0;
    while (std::getline(ss, item, ',')) {
        float f = 0;
        auto [ptr, ec] = std::from_chars(item.data(), item.data() + item.size(), f);
        if (i >= 3 || item.empty() || ec != std::errc() || ptr != item.data() + item.size() || !std::isfinite(f))
            throw InputError(option + ": expected x,y,z but got '" + text + "'");
        v[i++] = f;
    }
    if (i != 3) throw InputError(option + ": expected x,y,z but got '" + text + "'");
    return v;
}

void SceneOptions::add_to(CLI::App& cmd, bool model_required) {
    cmd.add_option("MODEL", model, "mesh file (.obj .stl .ply .off) or builtin:sphere|torus|torus-knot|teapot")
        ->required(model_required);
    cmd.add_option("--style", style, "built-in style name or style file (.toml); see `inkshade styles`");
    cmd.add_option("--shading", shading, "shading model with default parameters (default lambert)");
    cmd.add_option("--set", sets,
                   "parameter override [model.]param=value, or TYPE.param=value for a line type (repeatable)")
        ->allow_extra_args(false);  // one value per --set, so MODEL may follow
    cmd.add_option("--size", size, "image size WxH")->capture_default_str();
    cmd.add_option("--azimuth", azimuth, "camera azimuth in degrees about +y (0 = from +z)");
    cmd.add_option("--elevation", elevation, "camera elevation in degrees");
    cmd.add_option("--distance", distance, "camera distance from the target (world units)");
    cmd.add_option("--eye", eye, "camera position x,y,z");
    cmd.add_option("--target", target, "camera target x,y,z (default: model centre)");
    cmd.add_option("--up", up, "camera up vector x,y,z")->capture_default_str();
    cmd.add_option("--fov", fov, "vertical field of view in degrees")->capture_default_str();
    cmd.add_flag("--ortho", ortho, "orthographic projection");
    cmd.add_option("--ortho-height", ortho_height, "orthographic view height in world units (default: framed to the model)");
    cmd.add_option("--near", near, "near clipping plane distance (default: fitted to the model)");
    cmd.add_option("--far", far, "far clipping plane distance (default: fitted to the model)");
    cmd.add_option("--light-pos", light_pos, "light position x,y,z (world; default above-left of the camera)");
    cmd.add_option("--light-target", light_target,
                   "point a directional light shines towards, x,y,z (default: the model centre)");
    cmd.add_option("--light-type", light_type, "directional (from position to the model centre) or point")
        ->capture_default_str();
    cmd.add_option("--light-color", light_color, "light colour E (default 0.9 grey)");
    cmd.add_option("--ambient", ambient, "ambient colour A (default 0.1 grey)");
    cmd.add_option("--base-color", base_color, "base colour C, multiplies mesh colours (default white)");
    cmd.add_option("--background", background, "background colour or 'transparent' (default: the style's, white)");
    cmd.add_option("--samples", samples, "MSAA samples (1 = off)")->capture_default_str();
    cmd.add_flag("--srgb", srgb, "sRGB-encode the output (default: formula values as they are)");
}

glm::ivec2 SceneOptions::image_size() const {
    int w = 0, h = 0;
    char x = 0;
    std::istringstream in(size);
    if (!(in >> w >> x >> h) || (x != 'x' && x != 'X') || !in.eof() || w <= 0 || h <= 0 || w > 16384 || h > 16384)
        throw InputError("--size: expected WxH with each side in 1..16384, got '" + size + "'");
    return {w, h};
}

RenderOptions SceneOptions::render_options(const Style& style) const {
    RenderOptions o;
    const glm::ivec2 wh = image_size();
    o.width = wh.x;
    o.height = wh.y;
    if (samples < 1 || samples > 16) throw InputError("--samples: expected 1..16, got " + std::to_string(samples));
    o.samples = samples;
    o.background = style.background;
    o.srgb_output = srgb;
    return o;
}

Style SceneOptions::resolved_style() const {
    Style s = loaded_style();
    apply_overrides(s);
    return s;
}

Style SceneOptions::loaded_style() const {
    if (!style.empty() && !shading.empty())
        throw InputError("--style and --shading are alternatives: use one (a style names its shading model)");
    if (scene_style && style.empty() && shading.empty()) return *scene_style;
    Style s = !shading.empty() ? load_style(shading_model(shading).name)  // validates the model name
                               : load_style(style.empty() ? "lambert" : style);
    if (scene_style) {
        // The scene's lights and background stay the scene's whatever the look.
        s.light_color = scene_style->light_color;
        s.ambient = scene_style->ambient;
        s.background = scene_style->background;
        const ShadingModel& model = shading_model(s.shading.model);
        for (const char* name : {"light-intensity", "ambient-intensity", "light-decay", "light-distance"})
            if (auto it = scene_style->shading.params.find(name); it != scene_style->shading.params.end() && model.param(name))
                s.shading.params[name] = it->second;
    }
    return s;
}

void SceneOptions::apply_overrides(Style& s) const {
    for (const std::string& set : sets) {
        try {
            apply_override(s, set);
        } catch (const InputError& e) {
            throw InputError("--set " + set + ": " + e.what());
        }
    }
    auto color = [](const std::string& opt, const std::string& text) {
        try {
            return parse_color(text);
        } catch (const InputError& e) {
            throw InputError(opt + ": " + e.what());
        }
    };
    if (!base_color.empty()) s.shading.base_color = glm::vec3(color("--base-color", base_color));
    if (!background.empty()) s.background = color("--background", background);
    if (!light_color.empty()) s.light_color = glm::vec3(color("--light-color", light_color));
    if (!ambient.empty()) s.ambient = glm::vec3(color("--ambient", ambient));
}

Camera SceneOptions::camera(const BoundingBox& box, float aspect) const {
    return frame_camera(box, camera_options(), aspect);
}

CameraOptions SceneOptions::camera_options() const {
    CameraOptions o;
    o.azimuth_degrees = azimuth;
    o.elevation_degrees = elevation;
    if (distance && (!(*distance > 0.0f) || !std::isfinite(*distance)))
        throw InputError("--distance: must be a positive number");
    o.distance = distance;
    if (!eye.empty()) o.eye = parse_vec3("--eye", eye);
    if (!target.empty()) o.target = parse_vec3("--target", target);
    if (!up.empty()) {
        o.up = parse_vec3("--up", up);
        if (glm::length(*o.up) == 0.0f) throw InputError("--up: must not be zero");
    }
    if (!(fov > 0.0f && fov < 180.0f)) throw InputError("--fov: expected degrees in (0, 180)");
    o.fov_degrees = fov;
    o.orthographic = ortho;
    if (near && !(*near > 0.0f && std::isfinite(*near)) && !ortho) throw InputError("--near: must be a positive number");
    if (near && !std::isfinite(*near)) throw InputError("--near: must be a finite number");
    if (far && !(std::isfinite(*far) && *far > near.value_or(0.0f))) throw InputError("--far: must be greater than --near");
    if (ortho_height && !(*ortho_height > 0.0f && std::isfinite(*ortho_height)))
        throw InputError("--ortho-height: must be a positive number");
    o.near_plane = near;
    o.far_plane = far;
    o.ortho_height = ortho_height;
    return o;
}

Light SceneOptions::light(const BoundingBox& box, const Camera& camera, const Style& style) const {
    Light l = default_light(box, camera);
    if (light_type == "point") l.type = LightType::Point;
    else if (light_type != "directional")
        throw InputError("--light-type: expected directional or point, got '" + light_type + "'");
    if (!light_pos.empty()) l.position = parse_vec3("--light-pos", light_pos);
    if (!light_target.empty()) l.target = parse_vec3("--light-target", light_target);
    if (l.type == LightType::Directional && l.position == l.target)
        throw InputError("--light-pos: equals the light's target, so a directional light has no direction");
    apply_style_light(style, l);
    return l;
}

}  // namespace inkshade::cli
