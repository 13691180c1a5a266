// Options shared by the commands that render: model, camera, light, shading, image.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "inkshade/camera.hpp"
#include "inkshade/renderer.hpp"

namespace inkshade::cli {

struct SceneOptions {
    std::string model;
    std::string shading = "lambert";
    std::vector<std::string> sets;  // --set [model.]param=value
    std::string size = "1024x1024";
    std::optional<float> azimuth, elevation, distance;
    std::string eye, target, up;
    float fov = 30.0f;
    bool ortho = false;
    std::string light_pos, light_type = "directional", light_color, ambient, base_color;
    std::string background = "white";
    int samples = 4;
    bool srgb = false;

    void add_to(CLI::App& cmd);

    // Resolved values; each throws InputError naming the option on a bad value.
    RenderOptions render_options() const;
    ShadingSelection shading_selection() const;
    Camera camera(const BoundingBox& box, float aspect) const;
    Light light(const BoundingBox& box, const Camera& camera) const;
};

glm::vec3 parse_vec3(const std::string& option, const std::string& text);

}  // namespace inkshade::cli
