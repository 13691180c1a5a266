#include "param_widgets.hpp"

#include <algorithm>
#include <string>

#include <imgui.h>

namespace inkshade::viewer {

namespace {

bool widget(const ParamSpec& spec, ParamValue& v) {
    const char* label = spec.name.c_str();
    bool changed = false;
    switch (spec.type) {
        case ParamType::Float: changed = ImGui::SliderFloat(label, &v[0], spec.min, spec.max, "%.3f"); break;
        case ParamType::Int: {
            int i = int(v[0]);
            changed = ImGui::SliderInt(label, &i, int(spec.min), int(spec.max));
            v[0] = float(i);
            break;
        }
        case ParamType::Bool: {
            bool b = v[0] != 0.0f;
            changed = ImGui::Checkbox(label, &b);
            v[0] = b ? 1.0f : 0.0f;
            break;
        }
        case ParamType::Color: changed = ImGui::ColorEdit3(label, v.data()); break;
        case ParamType::Choice: {
            int i = std::clamp(int(v[0]), 0, int(spec.choices.size()) - 1);
            if (ImGui::BeginCombo(label, spec.choices.at(size_t(i)).c_str())) {
                for (int c = 0; c < int(spec.choices.size()); ++c)
                    if (ImGui::Selectable(spec.choices[size_t(c)].c_str(), c == i)) i = c, changed = true;
                ImGui::EndCombo();
            }
            v[0] = float(i);
            break;
        }
        case ParamType::FloatList: {
            // One slider per value, with buttons to add and remove values.
            ImGui::PushID(label);
            ImGui::TextUnformatted(label);
            for (size_t k = 0; k < v.size(); ++k) {
                ImGui::PushID(int(k));
                changed |= ImGui::SliderFloat("##v", &v[k], spec.min, spec.max, "%.3f");
                ImGui::PopID();
            }
            if (int(v.size()) < spec.max_count && ImGui::SmallButton("+")) v.push_back(v.back()), changed = true;
            if (v.size() > 1) {
                ImGui::SameLine();
                if (ImGui::SmallButton("-")) v.pop_back(), changed = true;
            }
            ImGui::PopID();
            break;
        }
    }
    if (ImGui::IsItemHovered() && !spec.doc.empty()) ImGui::SetTooltip("%s", spec.doc.c_str());
    return changed;
}

}  // namespace

bool param_widgets(const std::vector<ParamSpec>& params, ParamValues& values) {
    bool changed = false;
    for (const ParamSpec& spec : params) {
        ParamValue v = value_or_default(spec, values);
        if (v.empty()) continue;
        if (widget(spec, v)) {
            for (float& x : v) x = std::clamp(x, spec.min, spec.max);
            values[spec.name] = v;
            changed = true;
        }
    }
    return changed;
}

}  // namespace inkshade::viewer
