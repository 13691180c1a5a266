// The registry behind --shading, --set, style files and `inkshade styles`. Models register
// themselves from their own file (src/render/shading/NAME.cpp), so adding one touches
// nothing else.
#include <algorithm>

#include "core/name_suggestion.hpp"
#include "inkshade/error.hpp"
#include "inkshade/shading.hpp"

namespace inkshade {

namespace {

std::vector<ShadingModel>& registry() {
    static std::vector<ShadingModel> models;
    return models;
}

}  // namespace

const ParamSpec* ShadingModel::param(const std::string& param_name) const { return find_param(params, param_name); }

ShadingModelRegistration::ShadingModelRegistration(ShadingModel model) { registry().push_back(std::move(model)); }

std::vector<const ShadingModel*> shading_models() {
    std::vector<const ShadingModel*> out;
    for (const auto& m : registry()) out.push_back(&m);
    std::sort(out.begin(), out.end(),
              [](auto* a, auto* b) { return a->debug_view != b->debug_view ? !a->debug_view : a->name < b->name; });
    return out;
}

const ShadingModel& shading_model(const std::string& name) {
    for (const auto& m : registry())
        if (m.name == name) return m;
    for (const auto& m : registry())  // names are lower case; what users type may not be
        if (equal_ignoring_case(m.name, name)) return m;
    std::string names;
    std::vector<std::string> candidates;
    for (const auto* m : shading_models()) {
        names += (names.empty() ? "" : ", ") + m->name;
        candidates.push_back(m->name);
    }
    throw InputError("unknown shading model '" + name + "' (choose " + names + ")" + did_you_mean(name, candidates));
}

}  // namespace inkshade
