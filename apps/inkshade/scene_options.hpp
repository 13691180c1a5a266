// Options shared by the commands that render: model, camera, light, shading, image.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "inkshade/camera.hpp"
#include "inkshade/renderer.hpp"
#include "inkshade/style.hpp"

namespace inkshade::cli {

struct SceneOptions {
    std::string model;
    std::string style;    // --style NAME|FILE
    std::string shading;  // --shading NAME (the model's built-in style)
    std::vector<std::string> sets;  // --set [model.]param=value or TYPE.param=value (line types)
    std::string size = "1024x1024";
    std::optional<float> azimuth, elevation, distance;
    std::string eye, target, up;
    float fov = 30.0f;
    bool ortho = false;
    std::optional<float> near, far, ortho_height;  // unset: fitted to the model
    std::string light_pos, light_target, light_type = "directional", light_color, ambient, base_color;
    std::string background;  // empty: the style's
    int samples = 4;
    bool srgb = false;
    // A three.js scene (render --scene, scene_file.hpp): its material, lines, light colours and
    // background when neither --style nor --shading is given. With one of them, the scene still
    // gives that style its light colours, background and light parameters (light-intensity, ...).
    std::optional<Style> scene_style;

    // MODEL is a required positional unless model_required is false (`view` opens a default).
    void add_to(CLI::App& cmd, bool model_required = true);

    // Resolved values; each throws InputError naming the option on a bad value.
    // The style named by --style or --shading (default lambert) with --set, --base-color
    // and --background applied.
    Style resolved_style() const;
    // The two steps of resolved_style, for commands that choose the style's line types in
    // between (`inkshade lines --lines ...`): the style as named, then the overrides. A --set
    // TYPE.param=value applies to line type TYPE, which the style must draw.
    Style loaded_style() const;
    void apply_overrides(Style& style) const;
    glm::ivec2 image_size() const;  // --size
    RenderOptions render_options(const Style& style) const;
    CameraOptions camera_options() const;  // checked camera options, before framing
    Camera camera(const BoundingBox& box, float aspect) const;
    Light light(const BoundingBox& box, const Camera& camera, const Style& style) const;
};

glm::vec3 parse_vec3(const std::string& option, const std::string& text);

}  // namespace inkshade::cli
