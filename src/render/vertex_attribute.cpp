// The registry of vertex-attribute providers (render/vertex_attribute.hpp).
#include "render/vertex_attribute.hpp"

#include "core/registry.hpp"
#include "inkshade/error.hpp"  // RuntimeError: a model declares what no file registers

namespace inkshade::render {

namespace {

Registry<VertexAttributeProvider>& registry() {
    static Registry<VertexAttributeProvider> providers("vertex attribute");
    return providers;
}

}  // namespace

VertexAttributeRegistration::VertexAttributeRegistration(VertexAttributeProvider provider) {
    registry().add(std::move(provider));
}

const VertexAttributeProvider& vertex_attribute_provider(const std::string& name) {
    if (const VertexAttributeProvider* p = registry().find(name)) return *p;
    std::string names;
    for (const VertexAttributeProvider* p : registry().list()) names += (names.empty() ? "" : ", ") + p->name;
    throw RuntimeError("unknown vertex attribute '" + name + "' (registered: " + names + ")");
}

}  // namespace inkshade::render
