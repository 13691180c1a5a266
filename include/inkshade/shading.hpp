// Shading models: a registry of named models, each one GLSL file plus a parameter table
// (inkshade/params.hpp).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "inkshade/params.hpp"

namespace inkshade {

// What a model reads besides the mesh's positions, normals, colours and uvs, the camera and the
// light: declared once in its registration, provided by the renderer for every model alike
// (render/shading_inputs.hpp), as the render passes declare what they read (render/pass.hpp).
enum class ShadingInputKind : uint8_t {
    // A per-vertex attribute computed by the registered provider `name`
    // (render/vertex_attribute.hpp: "radial-curvature", "multiscale-normals"): uploaded to the
    // vertex attribute locations from 6 on, in declaration order, and declared in the GLSL from
    // the same declaration (v_GLSL in the fragment stage, #define INKSHADE_NAME).
    VertexAttribute,
    // Depth from the light (common/shadow.glsl): the renderer runs a depth pass from the light
    // and binds the map. Its `when` is a compile-time Bool parameter (INKSHADE_SHADOWS: a
    // program variant, so the taps cost nothing when off).
    ShadowMap,
    // Shades in the linear convention whatever --srgb (docs/shading.md, "Colour conventions"):
    // textures decoded from sRGB, output sRGB-encoded (the three.js models).
    LinearLight,
};

struct ShadingInput {
    ShadingInputKind kind = ShadingInputKind::VertexAttribute;
    std::string name;  // VertexAttribute: its provider
    // The parameter that switches the input on (empty: always on): a Bool one that is on, or a
    // Choice one at `when_choice`.
    std::string when;
    std::string when_choice;
};

ShadingInput vertex_attribute_input(std::string provider);
ShadingInput shadow_map_input(std::string when);
ShadingInput linear_light_input(std::string when = {}, std::string when_choice = {});

struct ShadingModel {
    std::string name;      // as selected by --shading
    std::string summary;   // one line with the formula
    std::string fragment;  // shader file under shaders/, e.g. "shading/phong.frag"
    std::string vertex = "mesh.vert";
    // What the model is rather than what it reads: a view of the geometry (normal, view, w,
    // ndotv, kr), listed apart from the shading models, drawn without the mesh's textures,
    // material rules or colour encoding.
    bool debug_view = false;
    // An object-space line type the model draws over its fill with the GPU strokes (hatching:
    // `hatch`): its parameters are the model's of the same names, its light the render's.
    std::string strokes;
    std::vector<ShadingInput> inputs;
    std::vector<ParamSpec> params;

    const ParamSpec* param(const std::string& name) const;
    // Whether `input` is on with `values` (its `when` parameter's value there, else its default).
    bool input_on(const ShadingInput& input, const ParamValues& values) const;
    // Whether an input of `kind` is on with `values`.
    bool reads(ShadingInputKind kind, const ParamValues& values) const;
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
