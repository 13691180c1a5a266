// Shading models: a registry of named models, each one GLSL file plus a parameter table
// (inkshade/params.hpp).
#pragma once
#include <string>
#include <vector>

#include "inkshade/params.hpp"

namespace inkshade {

struct ShadingModel {
    std::string name;      // as selected by --shading
    std::string summary;   // one line with the formula
    std::string fragment;  // shader file under shaders/, e.g. "shading/phong.frag"
    std::string vertex = "mesh.vert";
    bool debug_view = false;  // debug views (normal, view, w, ndotv)
    // Casts shadows from a shadow map when its compile-time bool parameter "shadows" is on:
    // the renderer then runs a depth pass from the light and binds it
    // (shaders/common/shadow.glsl).
    bool shadow_map = false;
    // Reads the per-vertex radial curvature κr of the current view (attribute 6, v_kr, under
    // INKSHADE_RADIAL_CURVATURE), computed on the CPU from Rusinkiewicz 2004 curvatures.
    bool radial_curvature = false;
    std::vector<ParamSpec> params;

    const ParamSpec* param(const std::string& name) const;
};

// All registered models: shading models alphabetically, then debug views.
std::vector<const ShadingModel*> shading_models();
// Throws InputError("unknown shading model 'x' (choose ...)") when absent.
const ShadingModel& shading_model(const std::string& name);

// The shading of a render: a model by name with overrides of its parameters (what a style
// holds, inkshade/style.hpp, and Renderer::render takes).
struct ShadingSelection {
    std::string model = "lambert";
    ParamValues params;          // overrides of the model's defaults
    glm::vec3 base_color{1.0f};  // multiplies vertex/material colours (C)
};

// Registration helper: `static const ShadingModelRegistration reg{{...}};` in the model's file.
struct ShadingModelRegistration {
    explicit ShadingModelRegistration(ShadingModel model);
};

}  // namespace inkshade
