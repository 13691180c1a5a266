// What the viewer shows and edits: the model, the scene (style, light, image options), the camera
// and the frame rendered from them. The panels, the mouse and keys, and the script change it
// through here; render() draws a new frame only when something changed.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "inkshade/scene.hpp"
#include "inkshade/window_canvas.hpp"
#include "window.hpp"

namespace inkshade::viewer {

class ViewerSession {
public:
    // Opens the scene's model (builtin:teapot when it names none) in the window, whose OpenGL
    // context it renders with. Throws InputError when that model cannot be opened.
    ViewerSession(const Scene& scene, Window& window, bool gui);
    ~ViewerSession();

    // State changes. One that fails is reported (report) and changes nothing.
    bool open_model(const std::string& path);
    void set_style(Style style);
    void load_style_named(const std::string& name_or_path);
    void apply_set(const std::string& text);  // a script's `set NAME=VALUE`
    void cycle_shading_model();               // F
    void toggle_line_type(size_t index);      // 1-9: the index-th of line_types()
    void reset_camera();                      // R
    void toggle_orthographic();               // O
    void orbit_camera(float yaw_degrees, float pitch_degrees);
    void pan_camera(float dx, float dy, int window_height);
    void zoom_camera(float factor);
    void move_light(const glm::vec3& position);  // replaces a file's light by the key light
    void save_frame(const std::string& path);
    void save_style_file(const std::string& path);
    // F, H, S, R, O, 1-9 as upper-case ASCII; other keys do nothing.
    void handle_key(int key);
    // Shows the message in the panels, in red when `error`, and on stderr.
    void report(const std::string& message, bool error);
    void changed() { dirty_ = true; }

    // Renders a frame of `size` pixels when something changed since the last one, or the size.
    void render(glm::ivec2 size);
    const WindowCanvas& canvas() const { return *canvas_; }
    std::string gl_renderer() const;

    // What the panels show and edit; an edit that changes the picture calls changed().
    Scene scene;  // the style, light and image options; the light follows the camera until moved
    Camera camera;
    Light light;  // the light of the last frame
    BoundingBox box;
    std::string model_path, model_field, mesh_facts;
    std::vector<PassTiming> timings;
    double frame_ms = 0.0;
    glm::ivec2 frame_size{0};
    std::string message;
    bool message_is_error = false;
    std::string frame_path = "frame.png", style_path = "style.toml";
    bool gui = true;

private:
    Window& window_;
    std::optional<glm::vec3> start_light_position_;  // where R puts a moved light back
    std::unique_ptr<Renderer> renderer_;
    std::unique_ptr<WindowCanvas> canvas_;
    Mesh mesh_;
    // The frames drawn so far as one sequence: layers with `coherence` keep their dashes and
    // brush marks on the surface while the camera orbits (docs/lines.md, "Temporal coherence").
    StrokeSequence strokes_;
    Image image_;
    bool dirty_ = true;
};

}  // namespace inkshade::viewer
