#include "viewer_session.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>

#include "inkshade/error.hpp"
#include "inkshade/io.hpp"
#include "inkshade/mesh_stats.hpp"
#include "inkshade/orbit_controls.hpp"
#include "inkshade/renderer.hpp"
#include "style_keys.hpp"
#include "viewer_script.hpp"

namespace inkshade::viewer {

namespace {

// The facts `inkshade info` prints, for the Model panel.
std::string describe_mesh(const Mesh& mesh, const BoundingBox& box) {
    const MeshStats s = mesh_stats(mesh);
    char facts[512];
    std::snprintf(facts, sizeof facts,
                  "%zu vertices, %zu triangles\nsize %.3g x %.3g x %.3g\n%zu boundary, %zu non-manifold edges\n"
                  "%zu components, %zu materials",
                  s.vertices, s.triangles, box.max.x - box.min.x, box.max.y - box.min.y, box.max.z - box.min.z,
                  s.boundary_edges, s.non_manifold_edges, s.components, mesh.materials.size());
    return facts;
}

}  // namespace

ViewerSession::ViewerSession(const Scene& start, Window& window, bool show_gui)
    : scene(start), gui(show_gui), window_(window), start_light_position_(start.light_position) {
    // The renderer draws with the window's context (one context: no sharing or switching).
    renderer_ = std::make_unique<Renderer>([&window] { window.make_current(); });
    canvas_ = std::make_unique<WindowCanvas>();
    if (!open_model(start.model.empty() ? "builtin:teapot" : start.model)) throw InputError(message);
}

ViewerSession::~ViewerSession() {
    window_.make_current();  // the GL objects go with the context they were made in
    canvas_.reset();
    renderer_.reset();
}

void ViewerSession::report(const std::string& text, bool error) {
    message = text;
    message_is_error = error;
    // Also on stderr: the GUI may be hidden, and scripted runs are read from the log.
    std::cerr << "inkshade view: " << text << "\n";
}

bool ViewerSession::open_model(const std::string& path) {
    try {
        Mesh mesh = load_mesh(path, scene.load_options());
        // The file's camera and light as --camera and --lights ask, for each model opened.
        Scene placed = scene;
        const std::vector<std::string> warnings = placed.apply_file_scene(mesh);
        renderer_->set_mesh(mesh);
        strokes_.reset();  // a new model starts a new sequence
        scene = std::move(placed);
        for (const std::string& w : warnings) report(w, false);
        mesh_ = std::move(mesh);
        box = mesh_.bounds();
        model_path = model_field = path;
        mesh_facts = describe_mesh(mesh_, box);
        reset_camera();
        message.clear();
        return true;
    } catch (const std::exception& e) {
        // The previous model (if any) stays loaded and shown.
        report(e.what(), true);
        return false;
    }
}

void ViewerSession::reset_camera() {
    const glm::ivec2 size = window_.framebuffer_size();
    camera = scene.frame(mesh_, float(std::max(size.x, 1)) / float(std::max(size.y, 1)));
    scene.light_position = start_light_position_;  // a moved light goes back too
    dirty_ = true;
}

void ViewerSession::set_style(Style style) {
    scene.style = std::move(style);
    dirty_ = true;
}

void ViewerSession::load_style_named(const std::string& name_or_path) {
    try {
        set_style(load_style(name_or_path));
    } catch (const std::exception& e) {
        report(e.what(), true);
    }
}

void ViewerSession::apply_set(const std::string& text) {
    try {
        viewer::apply_set(scene.style, text);
        dirty_ = true;
    } catch (const InputError& e) {
        report(e.what(), true);
    }
}

void ViewerSession::cycle_shading_model() {
    scene.style = next_shading_model_style(scene.style);
    report("shading model " + scene.style.shading.model, false);
    dirty_ = true;
}

void ViewerSession::toggle_line_type(size_t index) {
    viewer::toggle_line_type(scene.style, index);
    dirty_ = true;
}

void ViewerSession::toggle_orthographic() {
    camera.orthographic = !camera.orthographic;
    fit_clip_planes(camera, box);
    dirty_ = true;
}

void ViewerSession::orbit_camera(float yaw_degrees, float pitch_degrees) {
    orbit(camera, yaw_degrees, pitch_degrees, scene.camera.up_axis.value_or(UpAxis::PosY));
    fit_clip_planes(camera, box);
    dirty_ = true;
}

void ViewerSession::pan_camera(float dx, float dy, int window_height) {
    pan(camera, dx, dy, std::max(window_height, 1));
    fit_clip_planes(camera, box);
    dirty_ = true;
}

void ViewerSession::zoom_camera(float factor) {
    zoom(camera, factor, box);
    dirty_ = true;
}

void ViewerSession::move_light(const glm::vec3& position) {
    scene.light_position = position;
    scene.file_light.reset();
    dirty_ = true;
}

void ViewerSession::save_frame(const std::string& path) {
    try {
        render(window_.framebuffer_size());
        write_png(path, image_);
        report("saved frame " + path, false);
    } catch (const std::exception& e) {
        report(e.what(), true);
    }
}

void ViewerSession::save_style_file(const std::string& path) {
    try {
        Style s = scene.style;
        s.light_color = scene.style.light_color.value_or(light.color);
        s.ambient = scene.style.ambient.value_or(light.ambient);
        save_style(path, s);
        report("saved style " + path, false);
    } catch (const std::exception& e) {
        report(e.what(), true);
    }
}

void ViewerSession::handle_key(int key) {
    switch (key) {
        case 'F': cycle_shading_model(); break;
        case 'H': gui = !gui; break;
        case 'S': save_frame(frame_path); break;
        case 'R': reset_camera(); break;
        case 'O': toggle_orthographic(); break;
        default:
            if (key >= '1' && key <= '9') toggle_line_type(size_t(key - '1'));
            break;
    }
}

void ViewerSession::render(glm::ivec2 size) {
    if (size.x <= 0 || size.y <= 0) return;  // minimised
    if (size != frame_size) dirty_ = true;
    if (!dirty_ && image_.width == size.x && image_.height == size.y) return;
    frame_size = size;
    scene.options.width = size.x, scene.options.height = size.y;
    scene.options.background = scene.style.background;  // the panel edits the style's
    const auto start = std::chrono::steady_clock::now();
    timings.clear();
    try {
        light = scene.light(box, camera);
        scene.options.stroke_sequence = &strokes_;
        image_ = render_scene(*renderer_, scene, camera, light, &timings);
    } catch (const std::exception& e) {
        report(e.what(), true);
        image_ = Image(size.x, size.y);
    }
    frame_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    window_.make_current();
    canvas_->show(image_);
    dirty_ = false;
}

std::string ViewerSession::gl_renderer() const { return renderer_->gl_renderer(); }

}  // namespace inkshade::viewer
