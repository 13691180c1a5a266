#include "viewer.hpp"

#include <epoxy/gl.h>
// GLFW after epoxy: epoxy provides the GL declarations, GLFW must not include its own.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "inkshade/error.hpp"
#include "inkshade/io.hpp"
#include "inkshade/mesh_stats.hpp"
#include "inkshade/orbit_controls.hpp"
#include "inkshade/renderer.hpp"
#include "param_widgets.hpp"
#include "viewer_script.hpp"

namespace inkshade::viewer {

namespace {

std::string g_glfw_error;  // the last GLFW error, for the one-line message when a window fails

void glfw_error(int, const char* description) { g_glfw_error = description ? description : "unknown error"; }

// The window's pixels (back buffer, after the GUI is drawn) as an Image, top row first.
Image read_window(int width, int height) {
    Image image(width, height);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    flip_vertically(image);
    return image;
}

class Viewer {
public:
    explicit Viewer(const ViewerOptions& options);
    ~Viewer();
    int run();

private:
    // State changes, shared by the GUI, the keys and the script.
    bool open_model(const std::string& path);
    void set_style(Style style);
    void cycle_shading_model();
    void toggle_line_type(size_t index);
    void reset_camera();
    void save_frame(const std::string& path);
    void save_style_file(const std::string& path);
    void report(const std::string& message, bool error);
    void handle_key(int key);

    void render_if_needed();
    void draw_gui();
    void run_script_command(const ScriptCommand& command);

    static Viewer& of(GLFWwindow* w) { return *static_cast<Viewer*>(glfwGetWindowUserPointer(w)); }

    ViewerOptions options_;
    GLFWwindow* window_ = nullptr;
    std::unique_ptr<Renderer> renderer_;
    Mesh mesh_;
    BoundingBox box_;
    std::string model_path_, model_field_;
    std::string mesh_facts_;
    Scene scene_;  // the style, light and image options; the light follows the camera until moved
    // The frames drawn so far as one sequence: layers with `coherence` keep their dashes and
    // brush marks on the surface while the camera orbits (docs/lines.md, "Temporal coherence").
    StrokeSequence strokes_;
    Camera camera_;
    Light light_;  // the light of the last frame
    bool gui_ = true;
    bool dirty_ = true;
    int fb_width_ = 0, fb_height_ = 0;
    Image image_;
    GLuint texture_ = 0;
    std::vector<PassTiming> timings_;
    double frame_ms_ = 0.0;
    std::string message_;
    bool message_is_error_ = false;
    std::string frame_path_ = "frame.png", style_path_ = "style.toml";
    // Mouse drag state.
    bool dragging_ = false;
    int drag_button_ = -1;
    double last_x_ = 0.0, last_y_ = 0.0;
    // Script.
    std::vector<ScriptCommand> script_;
    size_t script_pos_ = 0;
    int wait_frames_ = 0;
    bool quit_ = false;
};

Viewer::Viewer(const ViewerOptions& options) : options_(options), scene_(options.scene), gui_(options.gui) {
    if (!options_.script.empty()) script_ = read_script(options_.script);  // bad scripts fail first

    glfwSetErrorCallback(glfw_error);
    if (!glfwInit())
        throw RuntimeError("cannot open a window (" + g_glfw_error +
                           "): no display; use `inkshade render` for images without a window, or run under xvfb-run");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);  // HiDPI: the window keeps its apparent size
    window_ =
        glfwCreateWindow(options_.scene.options.width, options_.scene.options.height, "inkshade", nullptr, nullptr);
    if (!window_) {
        glfwTerminate();
        throw RuntimeError("cannot open an OpenGL 4.5 window (" + g_glfw_error + "); use `inkshade render` instead");
    }
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(script_.empty() && options_.frames == 0 ? 1 : 0);  // vsync, except when scripted
    glfwSetWindowUserPointer(window_, this);

    // Input callbacks first: ImGui's GLFW backend chains to them when it installs its own.
    glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int button, int action, int) {
        Viewer& v = of(w);
        if (ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureMouse && action == GLFW_PRESS) return;
        v.dragging_ = action == GLFW_PRESS;
        v.drag_button_ = button;
        glfwGetCursorPos(w, &v.last_x_, &v.last_y_);
    });
    glfwSetCursorPosCallback(window_, [](GLFWwindow* w, double x, double y) {
        Viewer& v = of(w);
        if (!v.dragging_) return;
        const double dx = x - v.last_x_, dy = y - v.last_y_;
        v.last_x_ = x, v.last_y_ = y;
        if (v.drag_button_ == GLFW_MOUSE_BUTTON_LEFT) {
            orbit(v.camera_, float(-0.4 * dx), float(0.4 * dy), v.scene_.camera.up_axis.value_or(UpAxis::PosY));
        } else {
            int ww = 1, wh = 1;
            glfwGetWindowSize(w, &ww, &wh);
            pan(v.camera_, float(dx), float(dy), std::max(wh, 1));
        }
        fit_clip_planes(v.camera_, v.box_);
        v.dirty_ = true;
    });
    glfwSetScrollCallback(window_, [](GLFWwindow* w, double, double yoff) {
        Viewer& v = of(w);
        if (ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureMouse) return;
        zoom(v.camera_, float(std::pow(0.9, yoff)), v.box_);
        v.dirty_ = true;
    });
    glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int) {
        if (action != GLFW_PRESS) return;
        if (ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureKeyboard) return;
        of(w).handle_key(key);
    });
    glfwSetDropCallback(window_, [](GLFWwindow* w, int count, const char** paths) {
        if (count > 0) of(w).open_model(paths[0]);
    });

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // no imgui.ini next to the user's files
    float sx = 1.0f, sy = 1.0f;
    glfwGetWindowContentScale(window_, &sx, &sy);
    io.FontGlobalScale = std::max(1.0f, sx);
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window_, true);
    ImGui_ImplOpenGL3_Init("#version 450 core");

    // The renderer draws with the window's context (one context: no sharing or switching).
    renderer_ = std::make_unique<Renderer>([w = window_] { glfwMakeContextCurrent(w); });
    glGenTextures(1, &texture_);
    if (!open_model(options_.scene.model.empty() ? "builtin:teapot" : options_.scene.model)) throw InputError(message_);
}

Viewer::~Viewer() {
    if (!window_) return;
    glfwMakeContextCurrent(window_);
    renderer_.reset();
    if (texture_) glDeleteTextures(1, &texture_);
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window_);
    glfwTerminate();
}

void Viewer::report(const std::string& message, bool error) {
    message_ = message;
    message_is_error_ = error;
    // Also on stderr: the GUI may be hidden, and scripted runs are read from the log.
    std::cerr << "inkshade view: " << message << "\n";
}

bool Viewer::open_model(const std::string& path) {
    try {
        Mesh mesh = load_mesh(path, scene_.load_options());
        // The file's camera and light as --camera and --lights ask, for each model opened.
        Scene placed = scene_;
        const std::vector<std::string> warnings = placed.apply_file_scene(mesh);
        renderer_->set_mesh(mesh);
        strokes_.reset();  // a new model starts a new sequence
        scene_ = std::move(placed);
        for (const std::string& w : warnings) report(w, false);
        mesh_ = std::move(mesh);
        box_ = mesh_.bounds();
        model_path_ = model_field_ = path;
        const MeshStats s = mesh_stats(mesh_);
        char facts[512];
        std::snprintf(facts, sizeof facts,
                      "%zu vertices, %zu triangles\nsize %.3g x %.3g x %.3g\n%zu boundary, %zu non-manifold edges\n"
                      "%zu components, %zu materials",
                      s.vertices, s.triangles, box_.max.x - box_.min.x, box_.max.y - box_.min.y,
                      box_.max.z - box_.min.z, s.boundary_edges, s.non_manifold_edges, s.components,
                      mesh_.materials.size());
        mesh_facts_ = facts;
        reset_camera();
        message_.clear();
        return true;
    } catch (const std::exception& e) {
        // The previous model (if any) stays loaded and shown.
        report(e.what(), true);
        return false;
    }
}

void Viewer::reset_camera() {
    glfwGetFramebufferSize(window_, &fb_width_, &fb_height_);
    const float aspect = float(std::max(fb_width_, 1)) / float(std::max(fb_height_, 1));
    camera_ = scene_.frame(mesh_, aspect);
    scene_.light_position = options_.scene.light_position;  // a moved light goes back too
    dirty_ = true;
}

void Viewer::set_style(Style style) {
    scene_.style = std::move(style);
    dirty_ = true;
}

void Viewer::cycle_shading_model() {
    // The F key: the next shading model (debug views are in their own panel).
    std::vector<const ShadingModel*> models;
    for (const ShadingModel* m : shading_models())
        if (!m->debug_view) models.push_back(m);
    size_t i = 0;
    while (i < models.size() && models[i]->name != scene_.style.shading.model) ++i;
    const ShadingModel* next = models[(i + 1) % models.size()];
    // The model as `--shading NAME` gives it (its defaults, light and background), keeping the
    // line types, so F shows each model as `inkshade render --shading NAME` would.
    Style style = shading_model_style(next->name);
    style.lines = scene_.style.lines;
    scene_.style = std::move(style);
    report("shading model " + next->name, false);
    dirty_ = true;
}

void Viewer::toggle_line_type(size_t index) {
    const std::vector<const LineType*> types = line_types();
    if (index >= types.size()) return;
    auto it = std::find_if(scene_.style.lines.begin(), scene_.style.lines.end(),
                           [&](const LineSettings& l) { return l.type == types[index]->name; });
    if (it != scene_.style.lines.end())
        scene_.style.lines.erase(it);
    else
        scene_.style.lines.push_back({types[index]->name, {}});
    dirty_ = true;
}

void Viewer::save_frame(const std::string& path) {
    try {
        render_if_needed();
        write_png(path, image_);
        report("saved frame " + path, false);
    } catch (const std::exception& e) {
        report(e.what(), true);
    }
}

void Viewer::save_style_file(const std::string& path) {
    try {
        Style s = scene_.style;
        s.light_color = scene_.style.light_color.value_or(light_.color);
        s.ambient = scene_.style.ambient.value_or(light_.ambient);
        save_style(path, s);
        report("saved style " + path, false);
    } catch (const std::exception& e) {
        report(e.what(), true);
    }
}

void Viewer::handle_key(int key) {
    switch (key) {
        case GLFW_KEY_F: cycle_shading_model(); break;
        case GLFW_KEY_H: gui_ = !gui_; break;
        case GLFW_KEY_S: save_frame(frame_path_); break;
        case GLFW_KEY_R: reset_camera(); break;
        case GLFW_KEY_O:
            camera_.orthographic = !camera_.orthographic;
            fit_clip_planes(camera_, box_);
            dirty_ = true;
            break;
        case GLFW_KEY_ESCAPE: glfwSetWindowShouldClose(window_, GLFW_TRUE); break;
        default:
            if (key >= GLFW_KEY_1 && key <= GLFW_KEY_9) toggle_line_type(size_t(key - GLFW_KEY_1));
            break;
    }
}

void Viewer::render_if_needed() {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    if (w <= 0 || h <= 0) return;  // minimised
    if (w != fb_width_ || h != fb_height_) dirty_ = true;
    if (!dirty_ && image_.width == w && image_.height == h) return;
    fb_width_ = w, fb_height_ = h;
    scene_.options.width = w, scene_.options.height = h;
    scene_.options.background = scene_.style.background;  // the panel edits the style's
    const auto start = std::chrono::steady_clock::now();
    timings_.clear();
    try {
        light_ = scene_.light(box_, camera_);
        scene_.options.stroke_sequence = &strokes_;
        image_ = render_scene(*renderer_, scene_, camera_, light_, &timings_);
    } catch (const std::exception& e) {
        report(e.what(), true);
        image_ = Image(w, h);
    }
    frame_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    glfwMakeContextCurrent(window_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, image_.rgba.data());
    dirty_ = false;
}

void Viewer::draw_gui() {
    // On the right, where auto-framed models leave room; the user can move and resize it.
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(std::max(8.0f, display.x - 348.0f), 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(340, std::min(display.y - 16.0f, 620.0f)), ImGuiCond_FirstUseEver);
    ImGui::Begin("inkshade");
    if (!message_.empty())
        ImGui::TextColored(message_is_error_ ? ImVec4(1, 0.35f, 0.3f, 1) : ImVec4(0.5f, 1, 0.5f, 1), "%s",
                           message_.c_str());

    if (ImGui::CollapsingHeader("Timings", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::Text("%.1f FPS, last render %.1f ms at %dx%d", double(ImGui::GetIO().Framerate), frame_ms_, fb_width_,
                    fb_height_);
        ImGui::TextDisabled("  pass           wall ms   GPU ms");
        for (const PassTiming& t : timings_)
            ImGui::Text("  %-12s %8.2f %8.2f", t.pass.c_str(), t.milliseconds, t.gpu_milliseconds);
        ImGui::TextDisabled("%s", renderer_->gl_renderer().c_str());
        ImGui::TextDisabled("F: next model  1-9: lines  S: save  H: hide  R: reset  O: ortho");
    }
    if (ImGui::CollapsingHeader("Model", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::InputText("path", &model_field_);
        if (ImGui::Button("Open")) open_model(model_field_);
        ImGui::SameLine();
        ImGui::TextDisabled("(or drop a file on the window)");
        // Files without normals split their shading normals at this angle (load_mesh): the
        // model is loaded again when the slider is let go.
        ImGui::SliderFloat("smooth angle", &scene_.smooth_angle, 0.0f, 180.0f, "%.0f deg");
        if (ImGui::IsItemDeactivatedAfterEdit()) open_model(model_path_);
        ImGui::TextUnformatted(mesh_facts_.c_str());
    }

    if (ImGui::CollapsingHeader("Style", ImGuiTreeNodeFlags_DefaultOpen)) {
        if (ImGui::BeginCombo("preset", scene_.style.name.c_str())) {
            for (const std::string& name : builtin_style_names())
                if (ImGui::Selectable(name.c_str(), name == scene_.style.name)) {
                    try {
                        set_style(load_style(name));
                    } catch (const std::exception& e) {
                        report(e.what(), true);
                    }
                }
            ImGui::EndCombo();
        }
        if (ImGui::BeginCombo("shading", scene_.style.shading.model.c_str())) {
            for (const ShadingModel* m : shading_models())
                if (ImGui::Selectable((m->name + (m->debug_view ? " (debug view)" : "")).c_str(),
                                      m->name == scene_.style.shading.model)) {
                    scene_.style.shading.model = m->name;
                    scene_.style.shading.params.clear();
                    dirty_ = true;
                }
            ImGui::EndCombo();
        }
        const ShadingModel& model = shading_model(scene_.style.shading.model);
        ImGui::TextWrapped("%s", model.summary.c_str());
        // A colour picked here multiplies the model's own colours and textures, as --base-color
        // does (a style's base colour only tints meshes without them).
        if (ImGui::ColorEdit3("base colour", &scene_.style.shading.base_color.x)) {
            scene_.style.shading.base_color_use = BaseColorUse::Multiply;
            dirty_ = true;
        }
        dirty_ |= param_widgets(model.params, scene_.style.shading.params);
        dirty_ |= ImGui::ColorEdit4("background", &scene_.style.background.x);
    }

    if (ImGui::CollapsingHeader("Lines", ImGuiTreeNodeFlags_DefaultOpen)) {
        const std::vector<const LineType*> types = line_types();
        for (size_t i = 0; i < types.size(); ++i) {
            auto it = std::find_if(scene_.style.lines.begin(), scene_.style.lines.end(),
                                   [&](const LineSettings& l) { return l.type == types[i]->name; });
            bool on = it != scene_.style.lines.end();
            std::string label = (i < 9 ? std::to_string(i + 1) + "  " : "   ") + types[i]->name;
            if (ImGui::Checkbox(label.c_str(), &on)) toggle_line_type(i);
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", types[i]->summary.c_str());
            if (on && it != scene_.style.lines.end()) {
                ImGui::PushID(types[i]->name.c_str());
                ImGui::Indent();
                dirty_ |= param_widgets(types[i]->params, it->params);
                ImGui::Unindent();
                ImGui::PopID();
            }
        }
    }

    if (ImGui::CollapsingHeader("Light and camera")) {
        const float r = std::max(box_.diagonal(), 1e-6f) * 2.0f;
        const glm::vec3 c = box_.center();
        glm::vec3 p = light_.position;
        bool moved = ImGui::SliderFloat("light x", &p.x, c.x - r, c.x + r);
        moved |= ImGui::SliderFloat("light y", &p.y, c.y - r, c.y + r);
        moved |= ImGui::SliderFloat("light z", &p.z, c.z - r, c.z + r);
        // Moving the light or changing its type turns a file's light (--lights file) into the key light.
        if (moved) scene_.light_position = p, scene_.file_light.reset(), dirty_ = true;
        bool point = scene_.light_type == LightType::Point;
        if (ImGui::Checkbox("point light", &point))
            scene_.light_type = point ? LightType::Point : LightType::Directional, scene_.file_light.reset(),
            dirty_ = true;
        glm::vec3 lc = scene_.style.light_color.value_or(light_.color),
                  amb = scene_.style.ambient.value_or(light_.ambient);
        if (ImGui::ColorEdit3("light colour", &lc.x)) scene_.style.light_color = lc, dirty_ = true;
        if (ImGui::ColorEdit3("ambient", &amb.x)) scene_.style.ambient = amb, dirty_ = true;
        // The style's [light] intensity, or a threejs-* model's light-intensity (set_light_value).
        float intensity = light_value(scene_.style, LightValue::Intensity).value_or(1.0f);
        if (ImGui::SliderFloat("light intensity", &intensity, 0.0f, 10.0f))
            set_light_value(scene_.style, LightValue::Intensity, std::max(intensity, 0.0f)), dirty_ = true;
        if (ImGui::Checkbox("orthographic (O)", &camera_.orthographic)) fit_clip_planes(camera_, box_), dirty_ = true;
        if (!camera_.orthographic) dirty_ |= ImGui::SliderFloat("field of view", &camera_.fov_degrees, 5.0f, 120.0f);
        if (ImGui::Button("Reset camera (R)")) reset_camera();
    }

    if (ImGui::CollapsingHeader("Save", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::InputText("frame", &frame_path_);
        ImGui::SameLine();
        if (ImGui::Button("Save frame (S)")) save_frame(frame_path_);
        ImGui::InputText("style", &style_path_);
        ImGui::SameLine();
        if (ImGui::Button("Save style")) save_style_file(style_path_);
    }

    ImGui::End();
}

void Viewer::run_script_command(const ScriptCommand& c) {
    const std::string& a = c.argument;
    switch (c.kind) {
        case ScriptCommand::Frames: wait_frames_ = c.count; break;
        case ScriptCommand::Key: handle_key(c.count); break;
        case ScriptCommand::Set:
            try {
                apply_set(scene_.style, a);
                dirty_ = true;
            } catch (const InputError& e) {
                report(e.what(), true);
            }
            break;
        case ScriptCommand::StyleName: try { set_style(load_style(a));
            } catch (const std::exception& e) {
                report(e.what(), true);
            }
            break;
        case ScriptCommand::LightPos: scene_.light_position = c.vector, scene_.file_light.reset(), dirty_ = true; break;
        case ScriptCommand::Orbit:
            orbit(camera_, c.vector.x, c.vector.y, scene_.camera.up_axis.value_or(UpAxis::PosY)),
                fit_clip_planes(camera_, box_), dirty_ = true;
            break;
        case ScriptCommand::Zoom: zoom(camera_, c.vector.x, box_), dirty_ = true; break;
        case ScriptCommand::Open: open_model(a); break;
        case ScriptCommand::Screenshot: break;  // after the frame is drawn (run loop)
        case ScriptCommand::SaveFrame: save_frame(a); break;
        case ScriptCommand::SaveStyle: save_style_file(a); break;
        case ScriptCommand::Gui: gui_ = c.count != 0; break;
        case ScriptCommand::Quit: quit_ = true; break;
    }
}

int Viewer::run() {
    int frame = 0;
    while (!glfwWindowShouldClose(window_) && !quit_) {
        // Interactive: sleep until input arrives; scripted: poll and run one command per frame.
        const bool scripted = !script_.empty() || options_.frames > 0;
        if (scripted)
            glfwPollEvents();
        else
            glfwWaitEventsTimeout(0.25);

        std::string screenshot;
        if (wait_frames_ > 0) {
            --wait_frames_;
        } else if (script_pos_ < script_.size()) {
            const ScriptCommand& c = script_[script_pos_++];
            if (c.kind == ScriptCommand::Screenshot)
                screenshot = c.argument;
            else
                run_script_command(c);
        } else if (!script_.empty() && options_.frames == 0) {
            break;  // the script has ended
        }

        render_if_needed();
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        const ImVec2 size = ImGui::GetIO().DisplaySize;
        ImGui::GetBackgroundDrawList()->AddImage(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(texture_)),
                                                 ImVec2(0, 0), size);
        if (gui_) draw_gui();
        ImGui::Render();
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, fb_width_, fb_height_);
        glDisable(GL_SCISSOR_TEST);
        glClearColor(0.5f, 0.5f, 0.5f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        ++frame;
        const bool last = options_.frames > 0 && frame >= options_.frames;
        if (last && !options_.screenshot.empty()) screenshot = options_.screenshot;
        if (!screenshot.empty()) {
            try {
                write_png(screenshot, read_window(fb_width_, fb_height_));
                std::cerr << "inkshade view: screenshot " << screenshot << "\n";
            } catch (const std::exception& e) {
                report(e.what(), true);
            }
        }
        glfwSwapBuffers(window_);
        if (last) break;
    }
    return 0;
}

}  // namespace

int run_viewer(const ViewerOptions& options) {
    Viewer viewer(options);
    return viewer.run();
}

}  // namespace inkshade::viewer
