// The one path from a request to a scene. Every front end — `inkshade render`, `lines`, `view`
// and `demo`, the viewer, `batch`, the Python module and library users — fills a SceneRequest
// and calls make_scene, so one option means the same thing, with the same checks and the same
// error messages, wherever it is given.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "inkshade/aov.hpp"
#include "inkshade/camera.hpp"
#include "inkshade/image.hpp"
#include "inkshade/io.hpp"
#include "inkshade/line_drawing.hpp"
#include "inkshade/renderer.hpp"
#include "inkshade/section_plane.hpp"
#include "inkshade/style.hpp"

namespace inkshade {

// How errors name a request's fields: "--light-pos: ..." on the command line, "light_pos: ..."
// for Python keywords, "light-pos: ..." for a batch manifest's columns.
enum class OptionNames { Cli, Keywords, Columns };

// What the caller will make of the scene: the style's overrides are checked against what is
// drawn (a line drawing draws only the object-space types it selects).
struct SceneOutputs {
    bool image = true;          // Renderer::render: the style's shading and all its line types
    bool line_drawing = false;  // LineExtractor::draw: object-space lines (SVG, JSON, Python)
};

// Occlusion levels a line drawing draws (quantitative invisibility: how many surfaces lie in
// front of a line; 0 = visible), from `min` to `max`.
struct OcclusionLevels {
    int min = 0, max = 0;
    bool operator==(const OcclusionLevels&) const = default;
};
// "A-B" (0 ≤ A ≤ B ≤ kMaxOcclusionLevel), "A" (A only) or "A-" (A and every deeper level).
// InputError else.
OcclusionLevels parse_occlusion_levels(const std::string& text);

// The style a request without a look takes for `model`: "vrm" (three-vrm's look) for a glTF,
// GLB or VRM file with MToon materials (VRMC_vrm, VRM 0.x or VRMC_materials_mtoon), read from
// the file's JSON; "lambert" for everything else.
std::string default_style_name(const std::string& model);

struct SceneRequest {
    std::string model;  // mesh file or builtin:NAME (load_mesh)
    // The look: a style (built-in name or .toml file) or a shading model with its default
    // parameters; at most one of the two. Neither: `style_data` when given, else the model's
    // default_style_name.
    std::string style;
    std::string shading;
    // A style given as data (a three.js scene's material, lights and background). With `style`
    // or `shading` it still gives that style its light colours, background and light parameters.
    std::optional<Style> style_data;
    std::vector<std::string> sets;  // [model.]param=value or TYPE.param=value, applied in order
    // The object-space line types of the line drawing, in order; unset: the style's, or
    // default_vector_lines() when the style draws none.
    std::optional<std::vector<std::string>> vector_lines;
    bool hidden = false;  // the line drawing also has the hidden parts (dashed layers)
    // Every line type of the line drawing draws these levels (its min-level and max-level).
    std::optional<OcclusionLevels> occlusion_levels;
    // Line types added to an image's style (raster or object-space; `render --lines`), in
    // order after the style's; a type the style draws keeps its parameters.
    std::vector<std::string> added_lines;

    glm::ivec2 size{1024, 1024};
    CameraOptions camera;  // what is unset is auto-framed (frame_camera)
    // A camera of the model file instead of the camera options, which are then left unset: its
    // name, or its index in the order `inkshade info` lists the file's cameras. Empty: none.
    std::string file_camera;
    // With a file camera, the image takes the camera's aspect ratio (perspective aspectRatio,
    // orthographic xmag / ymag), its longer side that of `size`; front ends turn this on when
    // no size is given. Off, or a camera without one: `size` as it is, the camera's vertical
    // extent kept.
    bool size_from_camera = false;
    LightSource lights = LightSource::Style;  // File: the light options are left unset
    LightType light_type = LightType::Directional;
    std::optional<glm::vec3> light_position;  // default: above-left of the camera (default_light)
    std::optional<glm::vec3> light_target;    // default: the model centre
    std::optional<glm::vec3> light_color, ambient, base_color;
    // three.js's light values (set_light_value): E = colour x intensity in every model; decay
    // and distance shape a point light's falloff where the model takes light in physical units
    // (the threejs-* models, mtoon's threejs convention). Unset: the style's, else 1, 2, 0.
    std::optional<float> light_intensity, light_decay, light_distance;
    std::optional<glm::vec4> background;  // default: the style's
    int samples = 4;                      // MSAA, 1..16
    bool srgb = false;                    // decode textures, sRGB-encode the output
    // Auto-smooth angle in degrees, 0..180, for files without normals (LoadOptions::smooth_angle);
    // unset: the style's, else 30.
    std::optional<float> smooth_angle;
    std::optional<float> time;  // seconds (--time): glTF animations and MToon UV animation
    // The pose of a glTF/VRM model (LoadOptions::pose): an animation sampled at `time` (its name
    // or index; empty: none), VRM expressions (weights in [0, 1]) and morph target weights by
    // name, in order.
    std::string animation;
    std::vector<NamedWeight> expressions, morphs;
    bool spring_bones = true;  // VRM spring bones simulated to `time` (Pose::spring_bones)
    // A plane cutting the model, "X,Y,Z,NX,NY,NZ" (parse_section_plane); empty: none.
    std::string section_plane;
    // A drawing sheet (apply_drawing_sheet): the paper, "A0".."A5" (landscape; "-portrait" for
    // upright) or "WxH" in mm, and the scale "PAPER:MODEL" (model units in mm). Empty: none.
    std::string paper, drawing_scale;
    bool svg_fill = false;  // the line drawing's SVG fills the visible faces (LineExtractor::fills)
    // What --lines-json writes of each point; Full keeps each point's surface location.
    LinesJsonDetail lines_json_detail = LinesJsonDetail::Basic;
    int bit_depth = 8;  // bits a channel of the image: 8 or 16
    // AOVs beside the image (aov_names(): depth, normal, id, material, mask, lines, lineset-ids,
    // camera; any case), for render_scene's AovImages overload and write_aov_files.
    std::vector<std::string> aovs;
    // `--lineset-ids`: the lineset-ids AOV besides `aovs` (unset: only when aovs names it).
    std::optional<bool> lineset_ids;
    // `--export-mesh`: the mesh as loaded and framed, written as FILE.obj or FILE.ply (write_mesh);
    // in batch the format alone, `obj` or `ply`: OUTPUT_DIR/NAME.mesh.EXT once per model. Empty: none.
    std::string export_mesh;

    SceneOutputs outputs;
    OptionNames names = OptionNames::Cli;
};

// A checked request: what the renderer and the line extractor take.
struct Scene {
    std::string model;
    Style style;  // overrides applied; style.lines is what an image draws
    // The line drawing's line types with their parameters (hidden and overrides applied).
    std::vector<LineSettings> vector_lines;
    RenderOptions options;  // size, samples, background, colour convention
    CameraOptions camera;
    LightType light_type = LightType::Directional;
    std::optional<glm::vec3> light_position, light_target;
    float smooth_angle = LoadOptions{}.smooth_angle;
    float time = 0.0f;
    std::string animation;  // the model's pose (load_options), as the request gives it
    std::vector<NamedWeight> expressions, morphs;
    bool spring_bones = true;
    // Area in the three.js convention (a scene file, a threejs-* model, mtoon's threejs
    // convention): normals computed for a file without them as three.js computes them.
    NormalWeighting normal_weighting = NormalWeighting::Angle;
    OptionNames names = OptionNames::Cli;  // for the light's error
    std::string file_camera;               // as requested; apply_file_scene makes it `camera`
    bool size_from_camera = false;
    LightSource lights = LightSource::Style;
    std::optional<FileLight> file_light;  // the file's light in use (apply_file_scene)
    AovSet aovs;                          // the request's; options.aovs holds the renderer's part
    // The section plane of the line drawing's `clip-boundary` (--section-plane; not the image's).
    std::optional<SectionPlane> section_plane;
    // The drawing sheet's size in mm (SceneRequest::paper); the SVG is sized in mm. Unset: none.
    std::optional<glm::vec2> paper_mm;
    bool svg_fill = false;  // draw_scene_lines adds the visible faces' fills (SceneRequest::svg_fill)
    // SceneRequest::lines_json_detail; with Full draw_scene_lines keeps each point's surface location.
    LinesJsonDetail lines_json_detail = LinesJsonDetail::Basic;

    // Takes what the request asks of the loaded model file: its camera becomes the camera
    // options (placement, projection, near and far; the image's aspect with size_from_camera)
    // and its first light replaces the key light. Call it once the model is loaded, before
    // frame and light; it does nothing for a request that asks neither. Returns warnings for the
    // user ("FILE: ..."). Throws InputError naming the option: a camera the file does not have
    // (with the file's cameras), a file without cameras or without lights.
    std::vector<std::string> apply_file_scene(const Mesh& mesh);

    // How to load the scene's model: load_mesh(scene.model, scene.load_options()): the smooth
    // angle, the normals' weighting and the pose.
    LoadOptions load_options() const;

    // The camera for a model with these bounds: auto-framed for the image's aspect, or another
    // (a window's).
    Camera frame(const BoundingBox& box) const;
    Camera frame(const BoundingBox& box, float aspect) const;
    // The same, framing the mesh's vertices rather than the corners of its bounding box, so the
    // model itself reaches the margin: what the front ends use.
    Camera frame(const Mesh& mesh) const;
    Camera frame(const Mesh& mesh, float aspect) const;
    // The light for that camera: the default key light with the request's type, position and
    // target, and the style's colours; or the file's light (apply_file_scene) as the shading
    // model takes it (docs/inputs.md, "Cameras and lights").
    Light light(const BoundingBox& box, const Camera& camera) const;
    // The style's shading, with a file light's intensity, range and decay in the parameters of
    // a model that takes them (the threejs-* models' light-intensity, light-distance, light-decay).
    ShadingSelection shading() const;
};

// Checks every value of the request and resolves its style. Throws InputError naming the
// option ("--fov: expected degrees in (0, 180)"); nothing is loaded but the style.
Scene make_scene(const SceneRequest& request);

// Fills in what the three.js scene file at `path` gives (docs/threejs.md): its mesh, its
// material, lights and background as `style_data`, size, antialias, camera and light — except
// the options for which `given(option)` is true (command-line names without dashes: "model",
// "size", "fov", "eye", ...), which the caller set itself. Throws InputError for a bad file.
void apply_threejs_scene(const std::string& path, SceneRequest& request,
                         const std::function<bool(const std::string& option)>& given);

// The checks of make_scene on the request's values alone (ranges, colours, the pose's weights,
// alternatives), without resolving its style: for front ends that take options before they
// have a whole request (batch manifests and defaults). Throws InputError naming the option.
void check_request(const SceneRequest& request);

// What a line drawing draws when neither the request nor the style names an object-space type.
const std::vector<std::string>& default_vector_lines();

// The scene's image of the renderer's mesh (Renderer::set_mesh with the scene's model).
Image render_scene(Renderer& renderer, const Scene& scene, const Camera& camera, const Light& light,
                   std::vector<PassTiming>* timings = nullptr);

// The same image, and the AOVs scene.aovs asks for into `aovs`: depth, normal, ids and mask
// from the image's frame; each line mask from one more frame, drawing only that line type in
// white over a black surface and background (so it is the line's antialiased coverage). Line
// masks with object-space types want MeshUse::ManyFrames (each frame extracts them again).
Image render_scene(Renderer& renderer, const Scene& scene, const Camera& camera, const Light& light, AovImages& aovs,
                   std::vector<PassTiming>* timings = nullptr);

// What the camera file of a scene's image records (write_aov_files).
CameraRecord camera_record(const Scene& scene, const Camera& camera, const BoundingBox& bounds);

// The scene's line drawing of the extractor's mesh; with `sequence`, the next frame of that
// sequence (LineExtractor::draw: the `coherence` layers follow its previous frame).
LineDrawing draw_scene_lines(LineExtractor& extractor, const Scene& scene, const Camera& camera,
                             std::vector<LineTiming>* timings = nullptr, StrokeSequence* sequence = nullptr);

// The values of command-line options and manifest columns as text; each throws InputError
// naming `option`. Python and the library pass typed values instead.
glm::ivec2 parse_image_size(const std::string& option, const std::string& text);     // "WxH"
glm::vec3 parse_vec3(const std::string& option, const std::string& text);            // "x,y,z"
glm::vec4 parse_color(const std::string& option, const std::string& text);           // parse_color
LightType parse_light_type(const std::string& option, const std::string& text);      // directional|point
SectionPlane parse_section_plane(const std::string& option, const std::string& text);  // X,Y,Z,NX,NY,NZ
glm::vec2 parse_paper(const std::string& option, const std::string& text);  // A0..A5[-portrait], WxH mm
float parse_drawing_scale(const std::string& option, const std::string& text);  // "1:2" -> 0.5
// The request's drawing sheet applied to a scene make_scene built: the image takes the paper's
// aspect (its longer side the request's), a scale makes the camera orthographic with the extent
// the scale gives, and a style whose line widths are in mm (Style::lines_in_mm) gets them in
// pixels of this image (of 96 per inch without a sheet). Throws InputError naming the option.
void apply_drawing_sheet(const SceneRequest& r, Scene& scene);
NamedWeight parse_named_weight(const std::string& option, const std::string& text);  // NAME=W
// "NAME=W" items separated by ',' or ';' (a manifest's morph and expression columns).
std::vector<NamedWeight> parse_named_weights(const std::string& option, const std::string& text);
// The AOV names (any case), each once; InputError naming `option`, with the closest name.
AovSet aov_set(const std::string& option, const std::vector<std::string>& names);

}  // namespace inkshade
