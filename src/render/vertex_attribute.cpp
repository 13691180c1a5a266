// The registry of vertex-attribute providers (render/vertex_attribute.hpp).
#include "render/vertex_attribute.hpp"

#include "inkshade/error.hpp"  // RuntimeError: a model declares what no file registers

namespace inkshade::render {

namespace {

std::vector<VertexAttributeProvider>& registry() {
    static std::vector<VertexAttributeProvider> providers;
    return providers;
}

}  // namespace

VertexAttributeRegistration::VertexAttributeRegistration(VertexAttributeProvider provider) {
    registry().push_back(std::move(provider));
}

const VertexAttributeProvider& vertex_attribute_provider(const std::string& name) {
    std::string names;
    for (const VertexAttributeProvider& p : registry()) {
        if (p.name == name) return p;
        names += (names.empty() ? "" : ", ") + p.name;
    }
    throw RuntimeError("unknown vertex attribute '" + name + "' (registered: " + names + ")");
}

}  // namespace inkshade::render
