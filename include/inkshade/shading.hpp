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
    // Reads the mesh's vertex normals smoothed at several scales (attributes 7 on, one per scale,
    // v_scale_normal[] under INKSHADE_MULTISCALE_NORMALS; geometry/multiscale_normals.hpp): the
    // model's parameters "scales" (compile-time) and "sigma" choose them (exaggerated shading).
    bool multiscale_normals = false;
    // Shades in the linear convention whatever --srgb (docs/shading.md, "Colour conventions"):
    // textures decoded from sRGB, output sRGB-encoded (the three.js models). A model with a
    // Choice parameter "convention" is in it when that is "threejs" (mtoon).
    bool linear_light = false;
    // An object-space line type the model draws over its fill with the GPU strokes (hatching:
    // `hatch`): its parameters are the model's of the same names, its light the render's.
    std::string strokes;
    std::vector<ParamSpec> params;

    const ParamSpec* param(const std::string& name) const;
};

// All registered models: shading models alphabetically, then debug views.
std::vector<const ShadingModel*> shading_models();
// Throws InputError("unknown shading model 'x' (choose ...)") when absent.
const ShadingModel& shading_model(const std::string& name);

// How the base colour meets a mesh's own colours: vertex colours, material colours other than
// white, base-colour textures (docs/shading.md, "Base colour").
enum class BaseColorUse {
    Multiply,  // C = base x vertex/material colour x texture (--base-color)
    Fallback,  // a style's colour: C = base for a mesh without colours of its own, else as
               // Multiply with base 1 (a preset's tint does not darken a textured model)
    Only,      // C = base; the mesh's colours and textures are not used (`ink`'s white fill)
};

// The shading of a render: a model by name with overrides of its parameters (what a style
// holds, inkshade/style.hpp, and Renderer::render takes).
struct ShadingSelection {
    std::string model = "lambert";
    ParamValues params;          // overrides of the model's defaults
    glm::vec3 base_color{1.0f};  // C, with the mesh's colours as base_color_use says
    BaseColorUse base_color_use = BaseColorUse::Multiply;
};

// Registration helper: `static const ShadingModelRegistration reg{{...}};` in the model's file.
struct ShadingModelRegistration {
    explicit ShadingModelRegistration(ShadingModel model);
};

}  // namespace inkshade
