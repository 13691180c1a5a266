#include "render/shading_inputs.hpp"

#include <cctype>

#include "inkshade/error.hpp"
#include "render/frame.hpp"

namespace inkshade::render {

namespace {

std::string glsl_type(int components) { return components == 1 ? "float" : "vec" + std::to_string(components); }

// "multiscale-normals" -> INKSHADE_MULTISCALE_NORMALS
std::string macro_of(const std::string& name) {
    std::string macro = "INKSHADE_" + name;
    for (char& c : macro) c = c == '-' ? '_' : char(std::toupper(static_cast<unsigned char>(c)));
    return macro;
}

// "[7]" for an array attribute, "" for a single one.
std::string array_of(const GpuMesh::AttributeLayout& layout) {
    return layout.count > 1 ? "[" + std::to_string(layout.count) + "]" : "";
}

}  // namespace

std::vector<DeclaredAttribute> declared_attributes(const ShadingModel& model, const ParamValues& values) {
    std::vector<DeclaredAttribute> out;
    GLuint location = GpuMesh::kFirstDeclaredLocation;
    for (const ShadingInput& input : model.inputs) {
        if (input.kind != ShadingInputKind::VertexAttribute || !model.input_on(input, values)) continue;
        const VertexAttributeProvider& provider = vertex_attribute_provider(input.name);
        const int count = provider.count ? provider.count(model, values) : 1;
        if (count < 1 || location + GLuint(count) > GpuMesh::kLocationCount)
            throw RuntimeError("shading model '" + model.name + "': vertex attribute '" + input.name +
                               "' does not fit in locations " + std::to_string(location) + "-" +
                               std::to_string(GpuMesh::kLocationCount - 1));
        out.push_back({&provider, {input.name, location, provider.components, count}});
        location += GLuint(count);
    }
    return out;
}

std::string attribute_defines(const std::vector<DeclaredAttribute>& attributes) {
    if (attributes.empty()) return "";
    std::string defines, declarations, copies;
    for (const DeclaredAttribute& a : attributes) {
        const VertexAttributeProvider& p = *a.provider;
        const std::string type = glsl_type(p.components), array = array_of(a.layout);
        defines += "#define " + macro_of(p.name) + " 1\n";
        declarations += "layout(location = " + std::to_string(a.layout.location) + ") in " + type + " a_" + p.glsl +
                        array + "; out " + type + " v_" + p.glsl + array + "; ";
        const std::string turn = p.direction ? "u_normal_matrix * " : "";
        if (a.layout.count > 1)
            copies += "for (int i = 0; i < " + std::to_string(a.layout.count) + "; ++i) v_" + p.glsl + "[i] = " + turn +
                      "a_" + p.glsl + "[i]; ";
        else
            copies += "v_" + p.glsl + " = " + turn + "a_" + p.glsl + "; ";
    }
    return defines + "#define INKSHADE_VERTEX_ATTRIBUTES " + declarations +
           "\n#define INKSHADE_PASS_VERTEX_ATTRIBUTES " + copies + "\n";
}

std::string attribute_fragment_inputs(const std::vector<DeclaredAttribute>& attributes) {
    std::string inputs;
    for (const DeclaredAttribute& a : attributes)
        inputs += "in " + glsl_type(a.provider->components) + " v_" + a.provider->glsl + array_of(a.layout) + ";\n";
    return inputs;
}

void provide_attributes(const Frame& frame, const std::vector<DeclaredAttribute>& attributes) {
    GpuMesh& mesh = *frame.mesh;
    std::vector<GpuMesh::AttributeLayout> layouts;
    for (const DeclaredAttribute& a : attributes) {
        const VertexAttributeProvider& p = *a.provider;
        const size_t floats = size_t(p.components) * size_t(a.layout.count);
        if (p.per_view) {
            const auto it = frame.view_attributes.find(p.name);
            mesh.set_attribute(p.name, it == frame.view_attributes.end() ? std::vector<float>{} : it->second, floats,
                               {});
        } else {
            std::vector<float> key = p.key ? p.key(frame) : std::vector<float>{};
            key.push_back(float(floats));  // a new count is a new layout
            const std::vector<float>* uploaded = mesh.attribute_key(p.name);
            if (!uploaded || *uploaded != key) mesh.set_attribute(p.name, p.compute(frame), floats, std::move(key));
        }
        layouts.push_back(a.layout);
    }
    mesh.bind_attributes(layouts);
}

bool reads_view_attributes(const ShadingModel& model, const ParamValues& values) {
    for (const DeclaredAttribute& a : declared_attributes(model, values))
        if (a.provider->per_view) return true;
    return false;
}

bool reads_attribute(const Frame& frame, const std::string& provider) {
    for (const DeclaredAttribute& a : declared_attributes(frame.model, frame.shading.params))
        if (a.provider->name == provider) return true;
    return false;
}

}  // namespace inkshade::render
