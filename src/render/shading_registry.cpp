// The registry behind --shading, --set and `inkshade styles`. Models register themselves
// from their own file (src/render/shading/NAME.cpp), so adding one touches nothing else.
#include <algorithm>
#include <charconv>
#include <cmath>

#include "inkshade/color.hpp"
#include "inkshade/error.hpp"
#include "inkshade/shading.hpp"

namespace inkshade {

namespace {

std::vector<ShadingModel>& registry() {
    static std::vector<ShadingModel> models;
    return models;
}

std::string range_text(const ParamSpec& s) {
    auto num = [](float v) {
        std::string t = std::to_string(v);
        t.erase(t.find_last_not_of('0') + 1);
        if (!t.empty() && t.back() == '.') t.pop_back();
        return t;
    };
    return "[" + num(s.min) + ", " + num(s.max) + "]";
}

}  // namespace

ShadingModelRegistration::ShadingModelRegistration(ShadingModel model) {
    registry().push_back(std::move(model));
}

std::vector<const ShadingModel*> shading_models() {
    std::vector<const ShadingModel*> out;
    for (const auto& m : registry()) out.push_back(&m);
    std::sort(out.begin(), out.end(), [](auto* a, auto* b) {
        return a->debug_view != b->debug_view ? !a->debug_view : a->name < b->name;
    });
    return out;
}

const ShadingModel& shading_model(const std::string& name) {
    for (const auto& m : registry())
        if (m.name == name) return m;
    std::string names;
    for (const auto* m : shading_models()) names += (names.empty() ? "" : ", ") + m->name;
    throw InputError("unknown shading model '" + name + "' (choose " + names + ")");
}

glm::vec4 parse_param_value(const ParamSpec& spec, const std::string& text) {
    auto fail = [&](const std::string& why) -> glm::vec4 {
        throw InputError("parameter " + spec.name + ": " + why);
    };
    if (spec.type == ParamType::Color) {
        glm::vec4 c;
        try {
            c = parse_color(text);
        } catch (const InputError& e) {
            return fail(e.what());
        }
        return c;
    }
    if (spec.type == ParamType::Bool) {
        if (text == "true" || text == "1" || text == "on" || text == "yes") return glm::vec4(1, 0, 0, 0);
        if (text == "false" || text == "0" || text == "off" || text == "no") return glm::vec4(0);
        return fail("'" + text + "' is not a boolean (true/false)");
    }
    double v = 0;
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || ec != std::errc() || ptr != text.data() + text.size() || !std::isfinite(v))
        return fail("'" + text + "' is not a number");
    if (spec.type == ParamType::Int && v != std::floor(v)) return fail("'" + text + "' is not an integer");
    if (v < spec.min || v > spec.max) return fail(text + " is outside " + range_text(spec));
    return glm::vec4(float(v), 0, 0, 0);
}

}  // namespace inkshade
