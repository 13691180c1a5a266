#include "scene_options.hpp"

#include <sstream>

#include "inkshade/io.hpp"

namespace inkshade::cli {

void SceneOptions::add_to(CLI::App& cmd, bool model_required) {
    SceneRequest& r = request;
    CameraOptions& c = r.camera;
    cmd.add_option("MODEL", r.model,
                   "mesh file (" + readable_extensions() + ") or builtin:sphere|torus|torus-knot|teapot")
        ->required(model_required);
    cmd.add_option("--style", r.style, "built-in style name or style file (.toml); see `inkshade styles`");
    cmd.add_option("--shading", r.shading, "shading model with default parameters (default lambert)");
    cmd.add_option("--set", r.sets,
                   "parameter override [model.]param=value, or TYPE.param=value for a line type (repeatable)")
        ->allow_extra_args(false);  // one value per --set, so MODEL may follow
    cmd.add_option("--size", size, "image size WxH")->capture_default_str();
    cmd.add_option("--azimuth", c.azimuth_degrees, "camera azimuth in degrees about +y (0 = from +z)");
    cmd.add_option("--elevation", c.elevation_degrees, "camera elevation in degrees");
    cmd.add_option("--distance", c.distance, "camera distance from the target (world units)");
    cmd.add_option("--eye", eye, "camera position x,y,z");
    cmd.add_option("--target", target, "camera target x,y,z (default: model centre)");
    cmd.add_option("--up", up, "camera up vector x,y,z")->capture_default_str();
    cmd.add_option("--up-axis", up_axis,
                   "the model's up axis: y (glTF, three.js, most OBJ), z (many CAD and Blender exports), x, -x, "
                   "-y or -z; azimuth turns about it (default: the style's up-axis, else y)");
    cmd.add_option("--smooth-angle", r.smooth_angle,
                   "auto-smooth for files without normals: shading normals split at edges sharper than this "
                   "many degrees (default: the style's, else 30; 180 = all smooth)");
    cmd.add_option("--time", r.time,
                   "the moment drawn, in seconds >= 0: the time --animation is sampled at (clamped to its "
                   "keyframes) and mtoon's UV animation scrolled and turned by speed x time (default 0)")
        ->option_text("SECONDS");
    cmd.add_option("--animation", r.animation,
                   "pose a glTF/VRM model by one of its animations (name or index) at --time (default: none, the "
                   "file's pose)");
    cmd.add_option("--morph", morphs,
                   "morph target weight NAME=W of a glTF/VRM model (names from mesh.extras.targetNames; repeatable)")
        ->allow_extra_args(false);
    cmd.add_option("--expression", expressions,
                   "VRM expression NAME=W, W in [0, 1] (happy, angry, sad, relaxed, surprised, aa, blink, ... or "
                   "the file's custom names; repeatable)")
        ->allow_extra_args(false);
    cmd.add_option("--fov", c.fov_degrees, "vertical field of view in degrees")->capture_default_str();
    cmd.add_flag("--ortho", c.orthographic, "orthographic projection");
    cmd.add_option("--ortho-height", c.ortho_height,
                   "orthographic view height in world units (default: framed to the model)");
    cmd.add_option("--margin", c.margin,
                   "auto-framing: fraction of the image's width or height left free on each side of the model, "
                   "on the limiting axis, in [0, 0.5)")
        ->capture_default_str();
    cmd.add_option("--near", c.near_plane, "near clipping plane distance (default: fitted to the model)");
    cmd.add_option("--far", c.far_plane, "far clipping plane distance (default: fitted to the model)");
    cmd.add_option("--camera", r.file_camera,
                   "view through a camera of the model file (glTF), by name or index (`inkshade info` lists them); "
                   "without --size the image takes its aspect ratio");
    cmd.add_option("--light-pos", light_pos, "light position x,y,z (world; default above-left of the camera)");
    cmd.add_option("--light-target", light_target,
                   "point a directional light shines towards, x,y,z (default: the model centre)");
    cmd.add_option("--light-type", light_type, "directional (from position to the model centre) or point")
        ->capture_default_str();
    cmd.add_option("--lights", lights,
                   "style (the style's key light, placed by the options above) or file (the model file's first "
                   "glTF KHR_lights_punctual light)")
        ->capture_default_str();
    cmd.add_option("--light-color", light_color, "light colour E (default 0.9 grey)");
    cmd.add_option("--light-intensity", r.light_intensity,
                   "light intensity: E = light colour x intensity (three.js Light.intensity; default the style's, "
                   "else 1)");
    cmd.add_option("--light-decay", r.light_decay,
                   "point light decay: E / max(d^decay, 0.01) where the model takes physical light units "
                   "(threejs-*, mtoon convention=threejs; three.js PointLight.decay, default 2)");
    cmd.add_option("--light-distance", r.light_distance,
                   "point light distance: its light fades to zero there, in physical units (three.js "
                   "PointLight.distance; default 0 = no limit)");
    cmd.add_option("--ambient", ambient, "ambient colour A (default 0.1 grey)");
    cmd.add_option("--base-color", base_color, "base colour C, multiplies mesh colours (default white)");
    cmd.add_option("--background", background, "background colour or 'transparent' (default: the style's, white)");
    cmd.add_option("--samples", r.samples, "MSAA samples (1 = off)")->capture_default_str();
    cmd.add_flag("--srgb", r.srgb, "decode textures from sRGB, sRGB-encode the output (default: as they are)");
}

std::optional<std::vector<std::string>> split_names(const std::string& text) {
    if (text.empty()) return std::nullopt;
    std::vector<std::string> names;
    std::stringstream ss(text);
    for (std::string name; std::getline(ss, name, ',');) names.push_back(name);
    return names;
}

SceneRequest SceneOptions::to_request(const CLI::App& cmd, const std::string& scene_file) const {
    SceneRequest r = request;
    r.size = parse_image_size("--size", size);
    if (!eye.empty()) r.camera.eye = parse_vec3("--eye", eye);
    if (!target.empty()) r.camera.target = parse_vec3("--target", target);
    if (!up.empty()) r.camera.up = parse_vec3("--up", up);
    if (!up_axis.empty()) r.camera.up_axis = parse_up_axis("--up-axis", up_axis);
    r.light_type = parse_light_type("--light-type", light_type);
    r.lights = parse_light_source("--lights", lights);
    r.size_from_camera = cmd.count("--size") == 0;
    if (!light_pos.empty()) r.light_position = parse_vec3("--light-pos", light_pos);
    if (!light_target.empty()) r.light_target = parse_vec3("--light-target", light_target);
    if (!light_color.empty()) r.light_color = glm::vec3(parse_color("--light-color", light_color));
    if (!ambient.empty()) r.ambient = glm::vec3(parse_color("--ambient", ambient));
    if (!base_color.empty()) r.base_color = glm::vec3(parse_color("--base-color", base_color));
    if (!background.empty()) r.background = parse_color("--background", background);
    for (const std::string& m : morphs) r.morphs.push_back(parse_named_weight("--morph", m));
    for (const std::string& e : expressions) r.expressions.push_back(parse_named_weight("--expression", e));
    if (!scene_file.empty())
        apply_threejs_scene(scene_file, r, [&](const std::string& option) {
            return cmd.count(option == "model" ? "MODEL" : "--" + option) > 0;
        });
    return r;
}

}  // namespace inkshade::cli
