// What the shading pass provides for the vertex attributes a model declares
// (ShadingInputKind::VertexAttribute), every model alike: the values from the registered
// provider (render/vertex_attribute.hpp), uploaded to locations from 6 on in declaration order,
// and the GLSL declarations made from the same declaration. The other inputs (the shadow map,
// linear light) are read where they apply: render/shading_pass.cpp and
// render/color_convention.hpp.
#pragma once
#include <string>
#include <vector>

#include "render/gpu_mesh.hpp"
#include "render/vertex_attribute.hpp"

namespace inkshade::render {

struct Frame;

struct DeclaredAttribute {
    const VertexAttributeProvider* provider = nullptr;
    GpuMesh::AttributeLayout layout;
};

// The model's vertex attributes that are on with `values`, each at the locations after the
// previous one's. Throws RuntimeError for an unknown provider or past the last location.
std::vector<DeclaredAttribute> declared_attributes(const ShadingModel& model, const ParamValues& values);

// GLSL for both stages: #define INKSHADE_NAME 1 per attribute, and the two macros mesh.vert
// expands, INKSHADE_VERTEX_ATTRIBUTES (`layout(location = L) in T a_GLSL; out T v_GLSL;`) and
// INKSHADE_PASS_VERTEX_ATTRIBUTES (v_GLSL = a_GLSL, a direction turned by u_normal_matrix).
std::string attribute_defines(const std::vector<DeclaredAttribute>& attributes);
// GLSL for the fragment stage: `in T v_GLSL;` per attribute.
std::string attribute_fragment_inputs(const std::vector<DeclaredAttribute>& attributes);

// Uploads the attributes that are out of date (per-view ones from Frame::view_attributes,
// the others computed when their key changed) and binds them at their locations.
void provide_attributes(const Frame& frame, const std::vector<DeclaredAttribute>& attributes);

// The model reads a per-view attribute (Resource::ViewAttributes).
bool reads_view_attributes(const ShadingModel& model, const ParamValues& values);
// The frame's model reads attribute `provider` (a per-view provider's pass runs only then).
bool reads_attribute(const Frame& frame, const std::string& provider);

}  // namespace inkshade::render
