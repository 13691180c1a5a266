// Shading models: a registry of named models, each one GLSL file plus a parameter table
// (name, type, default, range, doc) that drives uniforms, --set, `inkshade styles` and docs.
#pragma once
#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace inkshade {

enum class ParamType { Float, Int, Bool, Color };

struct ParamSpec {
    std::string name;           // e.g. "shininess"; uniform is "u_" + name with '-' -> '_'
    ParamType type = ParamType::Float;
    glm::vec4 default_value{0.0f};  // Float/Int/Bool in .x; Color in .rgb
    float min = 0.0f, max = 1.0f;   // allowed range (per component for colours)
    std::string doc;
};

struct ShadingModel {
    std::string name;          // as selected by --shading
    std::string summary;       // one line with the formula
    std::string fragment;      // shader file under shaders/, e.g. "shading/phong.frag"
    std::string vertex = "mesh.vert";
    bool debug_view = false;   // debug views (normal, view, w, ndotv)
    std::vector<ParamSpec> params;
};

// Parameter values by name; missing names take the model's defaults.
using ParamValues = std::map<std::string, glm::vec4>;

// All registered models in registration-independent (alphabetical) order.
std::vector<const ShadingModel*> shading_models();
// Throws InputError("unknown shading model 'x' (choose ...)") when absent.
const ShadingModel& shading_model(const std::string& name);

// Parses "value" for a parameter ("0.5", "3", "true", "#ff8800", "1,0.5,0"); range-checked.
// Throws InputError naming the parameter and the problem.
glm::vec4 parse_param_value(const ParamSpec& spec, const std::string& text);

// Registration helper: `static const ShadingModelRegistration reg{{...}};` in the model's file.
struct ShadingModelRegistration {
    explicit ShadingModelRegistration(ShadingModel model);
};

}  // namespace inkshade
