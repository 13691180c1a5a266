// Styles: a shading model with its parameters, light colours, background and line types
// (inkshade/lines.hpp), read from human-editable TOML preset files. The built-in styles are
// such files embedded in the binary (src/styles/presets/), plus one per shading model.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "inkshade/camera.hpp"
#include "inkshade/lines.hpp"
#include "inkshade/shading.hpp"

namespace inkshade {

struct Style {
    std::string name;
    std::string description;
    ShadingSelection shading;              // model, parameters, base colour C
    std::optional<glm::vec3> light_color;  // E; unset = the renderer's default
    std::optional<glm::vec3> ambient;      // A; unset = the renderer's default
    // [light] intensity, decay, distance (Light::intensity, decay, range); unset: 1, 2, 0. A
    // model with light-intensity, light-decay, light-distance parameters (threejs-*) holds
    // them there instead (set_light_value).
    std::optional<float> light_intensity, light_decay, light_distance;
    glm::vec4 background{1.0f, 1.0f, 1.0f, 1.0f};
    std::vector<LineSettings> lines;  // drawn in this order, each type at most once
    // Auto-smooth angle for models without normals (`smooth-angle`, degrees); unset: 30.
    std::optional<float> smooth_angle;
    // The models' up axis (`up-axis`, CameraOptions::up_axis) when the request gives none.
    std::optional<UpAxis> up_axis;
    // `line-unit = "mm"`: the widths and dash lengths of `lines` are millimetres on paper
    // (apply_drawing_sheet turns them into pixels); otherwise pixels of the output image.
    bool lines_in_mm = false;
};

// Sets the light colour, ambient, intensity, decay and distance the style asks for (others
// stay as they are).
void apply_style_light(const Style& style, Light& light);

// A light's strength and reach, as three.js's lights hold them.
enum class LightValue { Intensity, Decay, Distance };
// "light-intensity", "light-decay", "light-distance": the parameter names of the threejs-* models.
const char* light_value_param(LightValue which);
// Sets one: the style's shading-model parameter of that name when the model has it (the
// threejs-* models carry three.js's light values as parameters), else the style's [light]
// value. Throws InputError for a value out of range (negative, not finite).
void set_light_value(Style& style, LightValue which, float value);
// The value set_light_value stores, where the style has one.
std::optional<float> light_value(const Style& style, LightValue which);

// Applies one override "param=value" or "MODEL.param=value" (a parameter of the style's shading
// model) or "LINETYPE.param=value" (a parameter of a line type the style draws), as --set and the
// viewer's scripts give them. Throws InputError naming the problem; the style is then unchanged.
void apply_override(Style& style, const std::string& text);

// Parses a style file's text. `source` names it in errors: InputError("SOURCE: problem").
// Every key is checked: unknown keys, models, parameters and out-of-range values are errors.
Style parse_style(std::string_view toml_text, const std::string& source);

// A built-in style name (see builtin_style_names) or a path to a .toml file.
Style load_style(const std::string& name_or_path);

// TOML text that parse_style reads back to the same style (all parameters written out).
std::string format_style(const Style& style);

// Writes format_style(style) atomically. Throws RuntimeError on failure.
void save_style(const std::string& path, const Style& style);

// The style of a shading model with its default parameters (`--shading NAME`), also where a
// preset has the model's name (the `mtoon` preset picks colours; the `mtoon` model's defaults
// are three-vrm MToonMaterial's). Throws InputError for an unknown model, with the closest name.
Style shading_model_style(const std::string& model_name);

// Built-in style names: every preset file, and every shading model (default parameters).
std::vector<std::string> builtin_style_names();

}  // namespace inkshade
