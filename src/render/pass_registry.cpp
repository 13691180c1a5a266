// The registry of pass types: each registers itself from its own file (PassRegistration).
#include <algorithm>
#include <deque>
#include <stdexcept>

#include "render/pass.hpp"

namespace inkshade::render {

namespace {

std::deque<PassType>& registry() {  // a deque: registered types never move
    static std::deque<PassType> types;
    return types;
}

}  // namespace

PassRegistration::PassRegistration(PassType type) {
    if (!type.plan || !type.create) throw std::logic_error("pass " + type.name + " registered without plan or create");
    registry().push_back(std::move(type));
}

std::vector<const PassType*> pass_types() {
    std::vector<const PassType*> out;
    for (const PassType& t : registry()) out.push_back(&t);
    // Registration order is that of static initialisation, which differs between builds.
    std::sort(out.begin(), out.end(), [](const PassType* a, const PassType* b) {
        return a->stage != b->stage ? a->stage < b->stage : a->name < b->name;
    });
    return out;
}

}  // namespace inkshade::render
