#include "panels.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <string>
#include <vector>

#include "inkshade/lines.hpp"
#include "inkshade/shading.hpp"
#include "param_widgets.hpp"

namespace inkshade::viewer {

namespace {

void timings_panel(ViewerSession& s) {
    if (!ImGui::CollapsingHeader("Timings", ImGuiTreeNodeFlags_DefaultOpen)) return;
    ImGui::Text("%.1f FPS, last render %.1f ms at %dx%d", double(ImGui::GetIO().Framerate), s.frame_ms, s.frame_size.x,
                s.frame_size.y);
    ImGui::TextDisabled("  pass           wall ms   GPU ms");
    for (const PassTiming& t : s.timings)
        ImGui::Text("  %-12s %8.2f %8.2f", t.pass.c_str(), t.milliseconds, t.gpu_milliseconds);
    ImGui::TextDisabled("%s", s.gl_renderer().c_str());
    ImGui::TextDisabled("F: next model  1-9: lines  S: save  H: hide  R: reset  O: ortho");
}

void model_panel(ViewerSession& s) {
    if (!ImGui::CollapsingHeader("Model", ImGuiTreeNodeFlags_DefaultOpen)) return;
    ImGui::InputText("path", &s.model_field);
    if (ImGui::Button("Open")) s.open_model(s.model_field);
    ImGui::SameLine();
    ImGui::TextDisabled("(or drop a file on the window)");
    // Files without normals split their shading normals at this angle (load_mesh): the model is
    // loaded again when the slider is let go.
    ImGui::SliderFloat("smooth angle", &s.scene.smooth_angle, 0.0f, 180.0f, "%.0f deg");
    if (ImGui::IsItemDeactivatedAfterEdit()) s.open_model(s.model_path);
    ImGui::TextUnformatted(s.mesh_facts.c_str());
}

void style_combos(ViewerSession& s) {
    Style& style = s.scene.style;
    if (ImGui::BeginCombo("preset", style.name.c_str())) {
        for (const std::string& name : builtin_style_names())
            if (ImGui::Selectable(name.c_str(), name == style.name)) s.load_style_named(name);
        ImGui::EndCombo();
    }
    if (ImGui::BeginCombo("shading", style.shading.model.c_str())) {
        for (const ShadingModel* m : shading_models())
            if (ImGui::Selectable((m->name + (m->debug_view ? " (debug view)" : "")).c_str(),
                                  m->name == style.shading.model)) {
                style.shading.model = m->name;
                style.shading.params.clear();
                s.changed();
            }
        ImGui::EndCombo();
    }
}

void style_panel(ViewerSession& s) {
    if (!ImGui::CollapsingHeader("Style", ImGuiTreeNodeFlags_DefaultOpen)) return;
    style_combos(s);
    Style& style = s.scene.style;
    const ShadingModel& model = shading_model(style.shading.model);
    ImGui::TextWrapped("%s", model.summary.c_str());
    // A colour picked here multiplies the model's own colours and textures, as --base-color
    // does (a style's base colour only tints meshes without them).
    if (ImGui::ColorEdit3("base colour", &style.shading.base_color.x)) {
        style.shading.base_color_use = BaseColorUse::Multiply;
        s.changed();
    }
    if (param_widgets(model.params, style.shading.params)) s.changed();
    if (ImGui::ColorEdit4("background", &style.background.x)) s.changed();
}

// What a line set selects, in the style file's words.
std::string selection_text(const FaceSelection& f) {
    std::string out;
    const auto list = [&](const char* key, const std::vector<std::string>& names) {
        if (names.empty()) return;
        out += std::string(out.empty() ? "" : ", ") + key + " ";
        for (size_t i = 0; i < names.size(); ++i) out += (i ? "|" : "") + names[i];
    };
    list("objects", f.objects);
    list("materials", f.materials);
    if (f.face_mark)
        out += std::string(out.empty() ? "" : ", ") + "face-mark " +
               (*f.face_mark < 0 ? "any" : std::to_string(*f.face_mark));
    if (out.empty()) out = "every face";
    return f.invert ? "not (" + out + ")" : out;
}

// The style's line sets (docs/styles.md), each with its selection and its lines' parameters.
void line_sets_panel(ViewerSession& s) {
    std::vector<LineSettings>& lines = s.scene.style.lines;
    for (const std::string& set : line_set_names(lines)) {
        if (set.empty()) continue;
        const auto first =
            std::find_if(lines.begin(), lines.end(), [&](const LineSettings& l) { return l.lineset == set; });
        if (!ImGui::TreeNode(("line set " + set).c_str())) continue;
        ImGui::TextWrapped("%s", selection_text(first->faces).c_str());
        for (LineSettings& l : lines) {
            if (l.lineset != set || !ImGui::TreeNode((set + "/" + l.type).c_str(), "%s", l.type.c_str())) continue;
            if (param_widgets(line_type(l.type).params, l.params)) s.changed();
            ImGui::TreePop();
        }
        ImGui::TreePop();
    }
}

void lines_panel(ViewerSession& s) {
    if (!ImGui::CollapsingHeader("Lines", ImGuiTreeNodeFlags_DefaultOpen)) return;
    std::vector<LineSettings>& lines = s.scene.style.lines;
    const std::vector<const LineType*> types = line_types();
    for (size_t i = 0; i < types.size(); ++i) {
        auto it = std::find_if(lines.begin(), lines.end(),
                               [&](const LineSettings& l) { return l.type == types[i]->name && l.lineset.empty(); });
        bool on = it != lines.end();
        const std::string label = (i < 9 ? std::to_string(i + 1) + "  " : "   ") + types[i]->name;
        if (ImGui::Checkbox(label.c_str(), &on)) s.toggle_line_type(i);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", types[i]->summary.c_str());
        if (on && it != lines.end()) {
            ImGui::PushID(types[i]->name.c_str());
            ImGui::Indent();
            if (param_widgets(types[i]->params, it->params)) s.changed();
            ImGui::Unindent();
            ImGui::PopID();
        }
    }
    line_sets_panel(s);
}

void light_widgets(ViewerSession& s) {
    Scene& scene = s.scene;
    const float r = std::max(s.box.diagonal(), 1e-6f) * 2.0f;
    const glm::vec3 c = s.box.center();
    glm::vec3 p = s.light.position;
    bool moved = ImGui::SliderFloat("light x", &p.x, c.x - r, c.x + r);
    moved |= ImGui::SliderFloat("light y", &p.y, c.y - r, c.y + r);
    moved |= ImGui::SliderFloat("light z", &p.z, c.z - r, c.z + r);
    // Moving the light or changing its type turns a file's light (--lights file) into the key light.
    if (moved) s.move_light(p);
    bool point = scene.light_type == LightType::Point;
    if (ImGui::Checkbox("point light", &point)) {
        scene.light_type = point ? LightType::Point : LightType::Directional;
        scene.file_light.reset();
        s.changed();
    }
    glm::vec3 lc = scene.style.light_color.value_or(s.light.color), amb = scene.style.ambient.value_or(s.light.ambient);
    if (ImGui::ColorEdit3("light colour", &lc.x)) scene.style.light_color = lc, s.changed();
    if (ImGui::ColorEdit3("ambient", &amb.x)) scene.style.ambient = amb, s.changed();
    // The style's [light] intensity, or a threejs-* model's light-intensity (set_light_value).
    float intensity = light_value(scene.style, LightValue::Intensity).value_or(1.0f);
    if (ImGui::SliderFloat("light intensity", &intensity, 0.0f, 10.0f))
        set_light_value(scene.style, LightValue::Intensity, std::max(intensity, 0.0f)), s.changed();
}

void light_camera_panel(ViewerSession& s) {
    if (!ImGui::CollapsingHeader("Light and camera")) return;
    light_widgets(s);
    bool orthographic = s.camera.orthographic;
    if (ImGui::Checkbox("orthographic (O)", &orthographic)) s.toggle_orthographic();
    if (!s.camera.orthographic && ImGui::SliderFloat("field of view", &s.camera.fov_degrees, 5.0f, 120.0f)) s.changed();
    if (ImGui::Button("Reset camera (R)")) s.reset_camera();
}

void save_panel(ViewerSession& s) {
    if (!ImGui::CollapsingHeader("Save", ImGuiTreeNodeFlags_DefaultOpen)) return;
    ImGui::InputText("frame", &s.frame_path);
    ImGui::SameLine();
    if (ImGui::Button("Save frame (S)")) s.save_frame(s.frame_path);
    ImGui::InputText("style", &s.style_path);
    ImGui::SameLine();
    if (ImGui::Button("Save style")) s.save_style_file(s.style_path);
}

}  // namespace

void draw_panels(ViewerSession& s) {
    // On the right, where auto-framed models leave room; the user can move and resize it.
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(std::max(8.0f, display.x - 348.0f), 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(340, std::min(display.y - 16.0f, 620.0f)), ImGuiCond_FirstUseEver);
    ImGui::Begin("inkshade");
    if (!s.message.empty())
        ImGui::TextColored(s.message_is_error ? ImVec4(1, 0.35f, 0.3f, 1) : ImVec4(0.5f, 1, 0.5f, 1), "%s",
                           s.message.c_str());
    timings_panel(s);
    model_panel(s);
    style_panel(s);
    lines_panel(s);
    light_camera_panel(s);
    save_panel(s);
    ImGui::End();
}

}  // namespace inkshade::viewer
