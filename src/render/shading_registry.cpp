// The registry behind --shading, --set, style files and `inkshade styles`. Models register
// themselves from their own file (src/render/shading/NAME.cpp), so adding one touches
// nothing else.
#include "core/registry.hpp"
#include "inkshade/shading.hpp"

namespace inkshade {

namespace {

// Shading models alphabetically, then debug views.
bool listed_before(const ShadingModel& a, const ShadingModel& b) {
    return a.debug_view != b.debug_view ? !a.debug_view : a.name < b.name;
}

Registry<ShadingModel>& registry() {
    static Registry<ShadingModel> models("shading model", listed_before);
    return models;
}

}  // namespace

const ParamSpec* ShadingModel::param(const std::string& param_name) const { return find_param(params, param_name); }

ShadingModelRegistration::ShadingModelRegistration(ShadingModel model) { registry().add(std::move(model)); }

std::vector<const ShadingModel*> shading_models() { return registry().list(); }

const ShadingModel& shading_model(const std::string& name) { return registry().at(name); }

}  // namespace inkshade
