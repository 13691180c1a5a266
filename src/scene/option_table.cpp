// The scene option table (inkshade/options.hpp): every option of a request declared once. Its
// order is --help's and the job hash's (batch/job_hash.cpp), so an option that enters the hash
// keeps its place; a new one goes anywhere with HashUse::None or at the end of its hash line.
// Defaults are SceneRequest's (scene.hpp, camera.hpp): the table reads them, never repeats them.
#include <limits>

#include "inkshade/options.hpp"

namespace inkshade {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr unsigned kScene = kRender | kLines | kView;  // the commands that draw one scene

// What a request field holds, as an OptionValue of the option's kind (std::monostate: unset).
OptionValue to_value(OptionKind kind, float v) { return kind == OptionKind::Number ? OptionValue(v) : OptionValue(); }
OptionValue to_value(OptionKind, int v) { return v; }
OptionValue to_value(OptionKind, bool v) { return v; }
OptionValue to_value(OptionKind, const std::string& v) { return v.empty() ? OptionValue() : OptionValue(v); }
OptionValue to_value(OptionKind, const glm::ivec2& v) { return v; }
OptionValue to_value(OptionKind, const std::vector<std::string>& v) { return v.empty() ? OptionValue() : v; }
OptionValue to_value(OptionKind, const std::vector<NamedWeight>& v) { return v.empty() ? OptionValue() : v; }
OptionValue to_value(OptionKind kind, const glm::vec3& v) {
    return kind == OptionKind::Color ? OptionValue(glm::vec4(v, 1.0f)) : OptionValue(v);
}
OptionValue to_value(OptionKind, const glm::vec4& v) { return v; }
OptionValue to_value(OptionKind, const OcclusionLevels& v) { return v; }
template <class T>
OptionValue to_value(OptionKind kind, const std::optional<T>& v) {
    return v ? to_value(kind, *v) : OptionValue();
}

// The value stored back into the field's type.
template <class T>
void from_value(T& field, const OptionValue& v) {
    if constexpr (std::is_same_v<T, glm::vec3>)
        field = std::holds_alternative<glm::vec4>(v) ? glm::vec3(std::get<glm::vec4>(v)) : std::get<glm::vec3>(v);
    else
        field = std::get<T>(v);
}
template <class T>
void from_value(std::optional<T>& field, const OptionValue& v) {
    T value{};
    from_value(value, v);
    field = value;
}
// Repeatable options append (`--morph a=1 --morph b=1`); a manifest cell or keyword gives
// the whole list at once, into an empty one.
void from_value(std::vector<NamedWeight>& field, const OptionValue& v) {
    const auto& items = std::get<std::vector<NamedWeight>>(v);
    field.insert(field.end(), items.begin(), items.end());
}
void from_value(std::vector<std::string>& field, const OptionValue& v) {
    const auto& items = std::get<std::vector<std::string>>(v);
    field.insert(field.end(), items.begin(), items.end());
}

// An option bound to the request field `ref` returns (a lambda taking SceneRequest& or const&).
template <class Ref>
OptionSpec bind(OptionSpec spec, Ref ref) {
    const OptionKind kind = spec.kind;
    spec.get = [kind, ref](const SceneRequest& r) { return to_value(kind, ref(r)); };
    spec.put = [ref](SceneRequest& r, const OptionValue& v) {
        const SceneRequest defaults;
        if (std::holds_alternative<std::monostate>(v))
            ref(r) = ref(defaults);
        else
            from_value(ref(r), v);
    };
    return spec;
}

// An enum field spelled by its choices: `names[i]` is the value `values[i]`.
template <class Ref, class Enum>
OptionSpec bind_choice(OptionSpec spec, Ref ref, std::vector<Enum> values) {
    std::vector<std::string> names = spec.choices;
    spec.get = [ref, values, names](const SceneRequest& r) -> OptionValue {
        const auto& field = ref(r);
        if constexpr (requires { field.has_value(); }) {
            if (!field) return {};
            for (size_t i = 0; i < values.size(); ++i)
                if (values[i] == *field) return names[i];
        } else {
            for (size_t i = 0; i < values.size(); ++i)
                if (values[i] == field) return names[i];
        }
        return {};
    };
    spec.put = [ref, values, names](SceneRequest& r, const OptionValue& v) {
        const SceneRequest defaults;
        if (std::holds_alternative<std::monostate>(v)) ref(r) = ref(defaults);
        if (std::holds_alternative<std::monostate>(v)) return;
        for (size_t i = 0; i < names.size(); ++i)
            if (names[i] == std::get<std::string>(v)) ref(r) = values[i];
    };
    return spec;
}

// The look: style, shading model, overrides.
void add_look(std::vector<OptionSpec>& t) {
    using K = OptionKind;
    t.push_back(bind({.name = "style", .kind = K::Text, .value = "NAME|FILE",
                      .help = "built-in style name or style file (.toml); see `inkshade styles`; default vrm for a file "
                              "with MToon materials (VRM), else lambert",
                      .fronts = kScene},
                     [](auto& r) -> auto& { return r.style; }));
    t.push_back(bind({.name = "shading", .kind = K::Text, .value = "NAME",
                      .help = "shading model with its default parameters", .fronts = kScene},
                     [](auto& r) -> auto& { return r.shading; }));
    t.push_back(bind({.name = "set", .kind = K::Overrides, .value = "[MODEL.]PARAM=VALUE",
                      .help = "parameter override [model.]param=value, or TYPE.param=value for a line type "
                              "(repeatable)",
                      .fronts = kScene},
                     [](auto& r) -> auto& { return r.sets; }));
}

// The image: size, samples, bit depth, colour convention, background.
void add_image(std::vector<OptionSpec>& t) {
    using K = OptionKind;
    t.push_back(bind({.name = "size", .kind = K::Size, .value = "WxH", .help = "image size",
                      .fronts = kScene | kBatch | kPython},
                     [](auto& r) -> auto& { return r.size; }));
    t.push_back(bind({.name = "samples", .kind = K::Integer, .value = "N", .help = "MSAA samples (1 = off)",
                      .fronts = kScene | kBatch, .min = 1, .max = 16},
                     [](auto& r) -> auto& { return r.samples; }));
    t.push_back(bind({.name = "bit-depth", .kind = K::Integer, .value = "8|16",
                      .help = "PNG bits a channel: 16 renders into RGBA16 targets (PNG only)",
                      .fronts = kRender | kLines | kBatch | kPython, .choices = {"8", "16"},
                      .hash = HashUse::ImageWhenSet, .metadata = "bit_depth"},
                     [](auto& r) -> auto& { return r.bit_depth; }));
    t.push_back(bind({.name = "srgb", .kind = K::Flag,
                      .help = "decode textures from sRGB, sRGB-encode the output (default: as they are)",
                      .fronts = kScene | kPython},
                     [](auto& r) -> auto& { return r.srgb; }));
    t.push_back(bind({.name = "background", .kind = K::Color, .value = "COLOR|transparent",
                      .help = "background colour or 'transparent' (default: the style's, white)", .fronts = kScene},
                     [](auto& r) -> auto& { return r.background; }));
}

// Where the camera stands.
void add_placement(std::vector<OptionSpec>& t) {
    using K = OptionKind;
    t.push_back(bind({.name = "azimuth", .kind = K::Number, .value = "DEG",
                      .help = "camera azimuth in degrees about the up axis (0 = from +z)", .fronts = kScene | kPython},
                     [](auto& r) -> auto& { return r.camera.azimuth_degrees; }));
    t.push_back(bind({.name = "elevation", .kind = K::Number, .value = "DEG", .help = "camera elevation in degrees",
                      .fronts = kScene | kPython},
                     [](auto& r) -> auto& { return r.camera.elevation_degrees; }));
    t.push_back(bind({.name = "distance", .kind = K::Number, .value = "D",
                      .help = "camera distance from the target (world units)", .fronts = kScene | kPython},
                     [](auto& r) -> auto& { return r.camera.distance; }));
    t.push_back(bind({.name = "eye", .kind = K::Vector, .value = "x,y,z", .help = "camera position",
                      .fronts = kScene | kPython},
                     [](auto& r) -> auto& { return r.camera.eye; }));
    t.push_back(bind({.name = "target", .kind = K::Vector, .value = "x,y,z",
                      .help = "camera target (default: the model centre)", .fronts = kScene | kPython},
                     [](auto& r) -> auto& { return r.camera.target; }));
    t.push_back(bind({.name = "up", .kind = K::Vector, .value = "x,y,z", .help = "camera up vector",
                      .fronts = kScene | kPython},
                     [](auto& r) -> auto& { return r.camera.up; }));
}

// How the camera projects and frames, and what it is: the job hash's view line, in its order, through light-intensity (add_light).
void add_projection(std::vector<OptionSpec>& t) {
    using K = OptionKind;
    const std::vector<UpAxis> axes = {UpAxis::PosX, UpAxis::PosY, UpAxis::PosZ,
                                      UpAxis::NegX, UpAxis::NegY, UpAxis::NegZ};
    t.push_back(bind({.name = "fov", .kind = K::Number, .value = "DEG", .help = "vertical field of view in degrees",
                      .fronts = kScene | kBatch | kPython, .min = 0, .max = 180, .min_open = true,
                      .max_open = true, .unit = "degrees", .hash = HashUse::ViewAlways},
                     [](auto& r) -> auto& { return r.camera.fov_degrees; }));
    OptionSpec ortho = bind({.name = "ortho", .kind = K::Flag, .help = "orthographic projection",
                             .fronts = kScene | kBatch | kPython, .hash = HashUse::ViewAlways},
                            [](auto& r) -> auto& { return r.camera.orthographic; });
    ortho.hash_text = [](const OptionValue& v) { return std::string(std::get<bool>(v) ? "1" : "0"); };
    t.push_back(ortho);
    t.push_back(bind({.name = "ortho-height", .kind = K::Number, .value = "H",
                      .help = "orthographic view height in world units (default: framed to the model)",
                      .fronts = kScene | kPython},
                     [](auto& r) -> auto& { return r.camera.ortho_height; }));
    t.push_back(bind({.name = "margin", .kind = K::Number, .value = "F",
                      .help = "auto-framing: fraction of the image's width or height left free on each side of "
                              "the model, on the limiting axis",
                      .fronts = kScene | kBatch | kPython, .min = 0, .max = 0.5, .max_open = true,
                      .unit = "a fraction of the image", .hash = HashUse::ViewAlways, .metadata = "view.margin"},
                     [](auto& r) -> auto& { return r.camera.margin; }));
    t.push_back(bind({.name = "near", .kind = K::Number, .value = "D",
                      .help = "near clipping plane distance (default: fitted to the model)",
                      .fronts = kScene | kPython},
                     [](auto& r) -> auto& { return r.camera.near_plane; }));
    t.push_back(bind({.name = "far", .kind = K::Number, .value = "D",
                      .help = "far clipping plane distance (default: fitted to the model)", .fronts = kScene | kPython},
                     [](auto& r) -> auto& { return r.camera.far_plane; }));
    t.push_back(bind({.name = "section-plane", .kind = K::Text, .value = "X,Y,Z,NX,NY,NZ",
                      .help = "a plane through point X,Y,Z with normal NX,NY,NZ: the line drawing drops what lies "
                              "on the normal's side and clip-boundary draws the cut (not the render; docs/lines.md)",
                      .fronts = kScene | kBatch | kPython, .hash = HashUse::ImageWhenSet},
                     [](auto& r) -> auto& { return r.section_plane; }));
    t.push_back(bind({.name = "paper", .kind = K::Text, .value = "A0..A5[-portrait]|WxH",
                      .help = "lay the drawing out on a sheet (ISO 216, landscape unless -portrait; or WxH in mm): "
                              "the image takes its aspect, the SVG its size in mm (docs/lines.md)",
                      .fronts = kScene | kBatch | kPython, .hash = HashUse::ImageWhenSet},
                     [](auto& r) -> auto& { return r.paper; }));
    t.push_back(bind({.name = "scale", .kind = K::Text, .value = "PAPER:MODEL",
                      .help = "draw to scale on the --paper sheet, e.g. 1:2 (model units in mm): an orthographic "
                              "view whose extent the scale gives",
                      .fronts = kScene | kBatch | kPython, .hash = HashUse::ImageWhenSet},
                     [](auto& r) -> auto& { return r.drawing_scale; }));
    t.push_back(bind({.name = "svg-fill", .kind = K::Flag,
                      .help = "the SVG fills the visible faces with their material's colour under the strokes, "
                              "computed exactly from the visible polygons (docs/lines.md)",
                      .fronts = kScene | kBatch | kPython, .hash = HashUse::ImageWhenSet},
                     [](auto& r) -> auto& { return r.svg_fill; }));
    OptionSpec up_axis = bind_choice(
        {.name = "up-axis", .kind = K::Choice, .value = "AXIS",
         .help = "the model's up axis: y (glTF, three.js, most OBJ), z (many CAD and Blender exports), x, -x, -y or "
                 "-z; azimuth turns about it (default: the style's up-axis, else y)",
         .fronts = kScene | kBatch | kPython, .choices = {"x", "y", "z", "-x", "-y", "-z"},
         .hash = HashUse::ViewWhenSet},
        [](auto& r) -> auto& { return r.camera.up_axis; }, axes);
    // The hash has always written the enum's number, and nothing for y.
    up_axis.hash_text = [axes](const OptionValue& v) {
        static const std::vector<std::string> names = {"x", "y", "z", "-x", "-y", "-z"};
        for (size_t i = 0; i < names.size(); ++i)
            if (names[i] == std::get<std::string>(v))
                return axes[i] == UpAxis::PosY ? std::string() : std::to_string(int(axes[i]));
        return std::string();
    };
    t.push_back(up_axis);
    t.push_back(bind({.name = "smooth-angle", .kind = K::Number, .value = "DEG",
                      .help = "auto-smooth for files without normals: shading normals split at edges sharper than "
                              "this many degrees (default: the style's, else 30; 180 = all smooth)",
                      .fronts = kScene | kBatch, .min = 0, .max = 180, .unit = "degrees",
                      .hash = HashUse::ViewWhenSet},
                     [](auto& r) -> auto& { return r.smooth_angle; }));
    // A batch job's file camera comes from its view (camera=NAME), so it is no batch option,
    // but it enters the hash here.
    t.push_back(bind({.name = "camera", .kind = K::Text, .value = "NAME|INDEX",
                      .help = "view through a camera of the model file (glTF), by name or index (`inkshade info` "
                              "lists them); without --size the image takes its aspect ratio",
                      .fronts = kScene | kPython, .hash = HashUse::ViewWhenSet},
                     [](auto& r) -> auto& { return r.file_camera; }));
}

// The light.
void add_light(std::vector<OptionSpec>& t) {
    using K = OptionKind;
    t.push_back(bind_choice({.name = "lights", .kind = K::Choice, .value = "style|file",
                             .help = "style (the style's key light, placed by the light options) or file (the model "
                                     "file's first glTF KHR_lights_punctual light)",
                             .fronts = kScene | kBatch | kPython, .choices = {"style", "file"},
                             .hash = HashUse::ViewWhenSet, .metadata = "lights"},
                            [](auto& r) -> auto& { return r.lights; },
                            std::vector<LightSource>{LightSource::Style, LightSource::File}));
    t.push_back(bind({.name = "light-intensity", .kind = K::Number, .value = "I",
                      .help = "light intensity: E = light colour x intensity (three.js Light.intensity; default the "
                              "style's, else 1)",
                      .fronts = kScene | kBatch | kPython, .min = 0, .max = 1e6,
                      .hash = HashUse::ViewWhenSet, .metadata = "light_intensity"},
                     [](auto& r) -> auto& { return r.light_intensity; }));
    t.push_back(bind({.name = "light-pos", .kind = K::Vector, .value = "x,y,z",
                      .help = "light position (world; default above-left of the camera)", .fronts = kScene | kPython},
                     [](auto& r) -> auto& { return r.light_position; }));
    t.push_back(bind({.name = "light-target", .kind = K::Vector, .value = "x,y,z",
                      .help = "point a directional light shines towards (default: the model centre)",
                      .fronts = kScene | kPython},
                     [](auto& r) -> auto& { return r.light_target; }));
    t.push_back(bind_choice({.name = "light-type", .kind = K::Choice, .value = "directional|point",
                             .help = "directional (from position to the model centre) or point",
                             .fronts = kScene | kPython, .choices = {"directional", "point"}},
                            [](auto& r) -> auto& { return r.light_type; },
                            std::vector<LightType>{LightType::Directional, LightType::Point}));
    t.push_back(bind({.name = "light-color", .kind = K::Color, .value = "COLOR",
                      .help = "light colour E (default 0.9 grey)", .fronts = kScene | kPython},
                     [](auto& r) -> auto& { return r.light_color; }));
    t.push_back(bind({.name = "light-decay", .kind = K::Number, .value = "K",
                      .help = "point light decay: E / max(d^decay, 0.01) where the model takes physical light "
                              "units (threejs-*, mtoon convention=threejs; three.js PointLight.decay, default 2)",
                      .fronts = kScene | kPython},
                     [](auto& r) -> auto& { return r.light_decay; }));
    t.push_back(bind({.name = "light-distance", .kind = K::Number, .value = "D",
                      .help = "point light distance: its light fades to zero there, in physical units (three.js "
                              "PointLight.distance; default 0 = no limit)",
                      .fronts = kScene | kPython},
                     [](auto& r) -> auto& { return r.light_distance; }));
    t.push_back(bind({.name = "ambient", .kind = K::Color, .value = "COLOR", .help = "ambient colour A (default 0.1 grey)",
                      .fronts = kScene | kPython},
                     [](auto& r) -> auto& { return r.ambient; }));
    t.push_back(bind({.name = "base-color", .kind = K::Color, .value = "COLOR",
                      .help = "base colour C, multiplies mesh colours (default white)", .fronts = kScene | kPython},
                     [](auto& r) -> auto& { return r.base_color; }));
}

// What else a job writes, then its pose: the job hash's image line in its order.
void add_outputs_and_pose(std::vector<OptionSpec>& t) {
    using K = OptionKind;
    OptionSpec aov = bind(
        {.name = "aov",
         .kind = K::Names,
         .value = "NAME,...",
         .help = "AOVs beside the image: depth, normal, id, material, mask, lines (a mask per line "
                 "type), lineset-ids (a mask per line set), the surface fields ndotv, kr, dwkr, k1, k2, "
                 "pdir1, pdir2 (float EXR) and shading-scales, camera (docs/aov.md)",
         .fronts = kRender | kBatch,
         .hash = HashUse::ImageWhenSet},
        [](auto& r) -> auto& { return r.aovs; });
    // The hash spells the set (known names, each once, in a fixed order), not the names as given.
    aov.hash_text = [](const OptionValue& v) {
        return format_aov_set(aov_set("aov", std::get<std::vector<std::string>>(v)));
    };
    t.push_back(aov);
    t.push_back(bind({.name = "occlusion-levels", .kind = K::Levels, .value = "A-B",
                      .help = "occlusion levels of the line drawing, A-B (how many surfaces lie in front; default "
                              "0-0 = visible only; 0-: all); levels above 0 are dashed layers TYPE-hidden-N (SVG)",
                      .fronts = kLines | kBatch, .hash = HashUse::ImageWhenSet, .metadata = "occlusion_levels"},
                     [](auto& r) -> auto& { return r.occlusion_levels; }));
    t.push_back(bind({.name = "time", .kind = K::Number, .value = "SECONDS",
                      .help = "the moment drawn: the time --animation is sampled at (clamped to its keyframes) and "
                              "mtoon's UV animation scrolled and turned by speed x time (default 0)",
                      .fronts = kScene | kBatch | kPython, .min = 0, .max = kInf, .unit = "seconds",
                      .hash = HashUse::ImageWhenSet, .metadata = "time"},
                     [](auto& r) -> auto& { return r.time; }));
    t.push_back(bind({.name = "animation", .kind = K::Text, .value = "NAME|INDEX|FILE.vrma",
                      .help = "pose a glTF/VRM model by one of its animations (name or index), or a VRM avatar by a "
                              "VRM animation file (.vrma), at --time (default: none, the file's pose)",
                      .fronts = kScene | kBatch | kPython, .hash = HashUse::ImageWhenSet, .metadata = "animation"},
                     [](auto& r) -> auto& { return r.animation; }));
    t.push_back(bind({.name = "expression", .kind = K::Weights, .value = "NAME=W",
                      .help = "VRM expression weight, W in [0, 1] (happy, angry, sad, relaxed, surprised, aa, blink, "
                              "... or the file's custom names; repeatable)",
                      .fronts = kScene | kBatch | kPython, .hash = HashUse::ImageWhenSet,
                      .metadata = "expressions"},
                     [](auto& r) -> auto& { return r.expressions; }));
    t.push_back(bind({.name = "morph", .kind = K::Weights, .value = "NAME=W",
                      .help = "morph target weight of a glTF/VRM model (names from mesh.extras.targetNames; "
                              "repeatable)",
                      .fronts = kScene | kBatch | kPython, .hash = HashUse::ImageWhenSet, .metadata = "morphs"},
                     [](auto& r) -> auto& { return r.morphs; }));
    t.push_back(bind_choice({.name = "spring-bones", .kind = K::Choice, .value = "on|off",
                             .help = "on: a VRM model's spring bones (hair, cloth) swing from its pose at time 0 "
                                     "to --time under gravity and --animation, in 1/60 s steps as three-vrm moves "
                                     "them; off: they keep the file's pose",
                             .fronts = kScene | kBatch | kPython, .choices = {"on", "off"},
                             .hash = HashUse::ImageWhenSet, .metadata = "spring_bones"},
                            [](auto& r) -> auto& { return r.spring_bones; }, std::vector<bool>{true, false}));
    t.push_back(bind({.name = "lineset-ids", .kind = K::Flag,
                      .help = "beside the image, one mask per line set, its lines together (.lineset-NAME.png; as "
                              "the AOV lineset-ids, docs/aov.md)",
                      .fronts = kRender | kBatch | kPython, .hash = HashUse::ImageWhenSet},
                     [](auto& r) -> auto& { return r.lineset_ids; }));
    t.push_back(bind({.name = "export-mesh", .kind = K::Text, .value = "FILE.obj|FILE.ply",
                      .help = "also write the mesh in the world coordinates of the camera files (re-projects onto "
                              "the image); batch: obj or ply, DIR/NAME.mesh.EXT once per model (docs/cli.md)",
                      .fronts = kRender | kLines | kBatch},
                     [](auto& r) -> auto& { return r.export_mesh; }));
    t.push_back(bind_choice(
        {.name = "lines-json-detail", .kind = K::Choice, .value = "basic|full",
         .help = "what the lines JSON holds of each point: basic (image point, depth, strength) or full (also the "
                 "world position, triangle and barycentric weights, image tangent and normal; docs/lines.md)",
         .fronts = kLines | kBatch | kPython, .choices = {"basic", "full"}, .hash = HashUse::ImageWhenSet,
         .metadata = "lines_json_detail"},
        [](auto& r) -> auto& { return r.lines_json_detail; },
        std::vector<LinesJsonDetail>{LinesJsonDetail::Basic, LinesJsonDetail::Full}));
}

std::vector<OptionSpec> make_table() {
    std::vector<OptionSpec> t;
    for (auto add : {add_look, add_image, add_placement, add_projection, add_light, add_outputs_and_pose}) add(t);
    return t;
}

}  // namespace

const std::vector<OptionSpec>& scene_options() {
    static const std::vector<OptionSpec> table = make_table();
    return table;
}

}  // namespace inkshade
