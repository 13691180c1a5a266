// The registry of pass types: each registers itself from its own file (PassRegistration).
#include <stdexcept>

#include "core/registry.hpp"
#include "render/pass.hpp"

namespace inkshade::render {

namespace {

// By stage, then name.
bool runs_before(const PassType& a, const PassType& b) {
    return a.stage != b.stage ? a.stage < b.stage : a.name < b.name;
}

Registry<PassType>& registry() {
    static Registry<PassType> types("pass", runs_before);
    return types;
}

}  // namespace

PassRegistration::PassRegistration(PassType type) {
    if (!type.plan || !type.create) throw std::logic_error("pass " + type.name + " registered without plan or create");
    registry().add(std::move(type));
}

std::vector<const PassType*> pass_types() { return registry().list(); }

}  // namespace inkshade::render
