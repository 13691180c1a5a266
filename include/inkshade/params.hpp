// Typed parameters (name, type, default, range, doc) shared by shading models and line types:
// one declaration drives uniforms, --set, style files, `inkshade styles` and the docs.
#pragma once
#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace inkshade {

enum class ParamType {
    Float,      // one value in [min, max]                    -> uniform float u_NAME
    Int,        // one integer in [min, max]                  -> uniform int u_NAME
    Bool,       // 0 or 1                                     -> uniform int u_NAME
    Color,      // r, g, b in [0, 1]                          -> uniform vec3 u_NAME
    Choice,     // index into `choices`, written by name      -> uniform int u_NAME
    FloatList,  // 1..max_count values in [min, max]          -> uniform float u_NAME[max_count]
                //                                               and int u_NAME_count
};

// A parameter's value: its components (1 for scalars, 3 for colours, n for lists).
using ParamValue = std::vector<float>;
// Values by parameter name; missing names take the model's defaults.
using ParamValues = std::map<std::string, ParamValue>;

struct ParamSpec {
    std::string name;  // e.g. "shininess"; the uniform is "u_" + name with '-' -> '_'
    ParamType type = ParamType::Float;
    ParamValue default_value;
    float min = 0.0f, max = 1.0f;      // allowed range of every component
    std::string doc;                   // one line: meaning and source of the default
    std::vector<std::string> choices;  // Choice: the names (value = index)
    int max_count = 1;                 // FloatList: uniform array size
    // Bool/Choice that switches a code path (or Int, a loop count): compiled into the shader as
    // `#define INKSHADE_NAME value` (NAME upper-case, '-' -> '_') instead of a uniform, since
    // llvmpipe runs a switched-off branch anyway. Each value used gets its own program.
    bool compile_time = false;
    // Color typed as sRGB-encoded components, as three.js users write colours (0xff8800): the
    // uniform receives the linear value (decoded once on the CPU, not per pixel).
    bool srgb = false;
};

// Marks a Bool, Choice or Int parameter as compile-time (see ParamSpec::compile_time).
ParamSpec compile_time(ParamSpec spec);

// Concise constructors for model files.
ParamSpec float_param(std::string name, float value, float min, float max, std::string doc);
ParamSpec int_param(std::string name, int value, int min, int max, std::string doc);
ParamSpec bool_param(std::string name, bool value, std::string doc);
ParamSpec color_param(std::string name, glm::vec3 value, std::string doc);
// A Color whose value is sRGB-encoded (ParamSpec::srgb).
ParamSpec srgb_color_param(std::string name, glm::vec3 value, std::string doc);
ParamSpec choice_param(std::string name, std::vector<std::string> choices, int value, std::string doc);
ParamSpec list_param(std::string name, std::vector<float> values, int max_count, float min, float max, std::string doc);

// The parameter called `name` in `params`, or nullptr.
const ParamSpec* find_param(const std::vector<ParamSpec>& params, const std::string& name);

// The value given for `spec` in `values`, else its default.
const ParamValue& value_or_default(const ParamSpec& spec, const ParamValues& values);

// Parses "value" for a parameter ("0.5", "3", "true", "#ff8800", "1,0.5,0", a choice name,
// "0.8,0.6,0.4" for lists); range-checked. Throws InputError naming the parameter.
ParamValue parse_param_value(const ParamSpec& spec, const std::string& text);
// Checks a value given as numbers (style files); throws InputError like parse_param_value.
ParamValue check_param_value(const ParamSpec& spec, const ParamValue& value);
// The text parse_param_value reads back ("0.5", "true", "half-lambert", "1,0.5,0").
std::string format_param_value(const ParamSpec& spec, const ParamValue& value);

// The shortest decimal text that reads back as exactly v ("0.33", "1e-05").
std::string format_number(float v);

}  // namespace inkshade
