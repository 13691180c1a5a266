// Per-vertex attributes that shading models declare (ShadingInputKind::VertexAttribute). Each
// is computed by a provider registered from its own file in render/vertex_attributes/ (as
// shading models and passes register themselves); the shading pass uploads what the frame's
// model declares and generates its GLSL (render/shading_inputs.hpp), so a model names a
// provider and reads v_GLSL.
#pragma once
#include <string>
#include <vector>

#include "inkshade/shading.hpp"

namespace inkshade::render {

struct Frame;

struct VertexAttributeProvider {
    std::string name;        // what a model declares (ShadingInput::name)
    std::string glsl;        // a_GLSL in the vertex stage, v_GLSL in the fragment stage
    int components = 1;      // 1 to 4: float, vec2, vec3, vec4
    bool direction = false;  // a normal: the vertex stage turns it by u_normal_matrix
    // Elements per vertex (an array attribute when above 1), from the model's parameter values;
    // null: 1.
    int (*count)(const ShadingModel& model, const ParamValues& values) = nullptr;
    // Per view: a pass registered beside the provider computes the values each frame into
    // Frame::view_attributes (it may read MeshLineData, which a MeshUse::OneFrame mesh frees
    // before the upload), and the shading pass reads Resource::ViewAttributes. Otherwise the
    // shading pass computes them when `key` changes, once per mesh and key.
    bool per_view = false;
    // The values: per mesh vertex, count x components floats, element after element.
    std::vector<float> (*compute)(const Frame& frame) = nullptr;
    // What the values depend on besides the mesh (not per view); null: nothing.
    std::vector<float> (*key)(const Frame& frame) = nullptr;
};

// `static const VertexAttributeRegistration reg{{...}};` in the provider's file.
struct VertexAttributeRegistration {
    explicit VertexAttributeRegistration(VertexAttributeProvider provider);
};

// Throws RuntimeError("unknown vertex attribute 'x' ...") when absent (a model's mistake).
const VertexAttributeProvider& vertex_attribute_provider(const std::string& name);

}  // namespace inkshade::render
