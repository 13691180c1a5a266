// The Python module `inkshade` (pybind11): load meshes, render styles into numpy arrays, extract
// object-space lines as lists, list styles and models. docs/python.md shows its use.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <optional>
#include <tuple>
#include <vector>

#include "inkshade/batch.hpp"
#include "inkshade/error.hpp"
#include "inkshade/io.hpp"
#include "inkshade/options.hpp"
#include "inkshade/line_drawing.hpp"
#include "inkshade/scene.hpp"
#include "inkshade/version.hpp"

namespace py = pybind11;
using namespace inkshade;

namespace {

// morph= and expression=: {name: weight}, or a list of "NAME=W" strings as the CLI takes them.
std::vector<NamedWeight> to_named_weights(const std::string& key, const py::handle& value) {
    std::vector<NamedWeight> out;
    if (py::isinstance<py::dict>(value)) {
        for (const auto& [name, weight] : value.cast<py::dict>())
            out.push_back({py::str(name).cast<std::string>(), weight.cast<float>()});
    } else if (py::isinstance<py::str>(value)) {
        out = parse_named_weights(key, value.cast<std::string>());
    } else {
        for (const std::string& item : value.cast<std::vector<std::string>>())
            out.push_back(parse_named_weight(key, item));
    }
    return out;
}

// A mesh with where it came from, so that a Renderer can load it again in another pose
// (render(animation=..., time=...)).
struct PyMesh : Mesh {
    std::string path;
    LoadOptions load;
};

// Whether the time moves a mesh loaded in `pose`: by its animation or its spring bones.
bool time_moves(const Pose& pose, const Mesh& mesh) {
    return !pose.animation.empty() || (pose.spring_bones && mesh.pose_names.spring_joints > 0);
}

// Whether two poses give the same mesh (`mesh` loaded in `b`).
bool same_pose(const Pose& a, const Pose& b, const Mesh& mesh) {
    return a.animation == b.animation && a.expressions == b.expressions && a.morphs == b.morphs &&
           a.spring_bones == b.spring_bones && (!time_moves(a, mesh) || a.time == b.time);
}

// A colour keyword: a string as the CLI takes it ("#ff8800", "0.2,0.4,0.6", "white") or a
// sequence of 3 (or, for 4-component colours, 4) numbers.
glm::vec4 to_color(const std::string& key, const py::handle& value, bool alpha) {
    if (py::isinstance<py::str>(value)) return parse_color(key, value.cast<std::string>());
    const auto v = value.cast<std::vector<float>>();
    if (v.size() != 3 && !(alpha && v.size() == 4))
        throw InputError(key + ": expected " + (alpha ? "3 or 4" : "3") + " components, got " +
                         std::to_string(v.size()));
    return glm::vec4(v[0], v[1], v[2], v.size() == 4 ? v[3] : 1.0f);
}

glm::vec3 to_vec3(const std::string& key, const py::handle& value) {
    const auto v = value.cast<std::vector<float>>();
    if (v.size() != 3) throw InputError(key + ": expected x, y, z");
    return {v[0], v[1], v[2]};
}

// A keyword's Python value as the option's kind of value: numbers, booleans and strings as they
// are, sequences for vectors, colours and sizes, {name: weight} or ["NAME=W", ...] for weights, a
// string where the command line takes text (an index may be an int).
OptionValue option_value(const OptionSpec& spec, const std::string& key, const py::handle& value) {
    switch (spec.kind) {
        case OptionKind::Number: return value.cast<float>();
        case OptionKind::Integer: return value.cast<int>();
        case OptionKind::Flag: return value.cast<bool>();
        case OptionKind::Vector: return to_vec3(key, value);
        case OptionKind::Color: return to_color(key, value, false);
        case OptionKind::Size: {
            const auto [w, h] = value.cast<std::pair<int, int>>();
            return glm::ivec2(w, h);
        }
        case OptionKind::Weights: return to_named_weights(key, value);
        case OptionKind::Names:
        case OptionKind::Overrides:
            if (py::isinstance<py::str>(value))
                return parse_option(spec, value.cast<std::string>(), OptionNames::Keywords);
            return value.cast<std::vector<std::string>>();
        default:
            if (py::isinstance<py::int_>(value) && !py::isinstance<py::bool_>(value))
                return parse_option(spec, std::to_string(value.cast<long long>()), OptionNames::Keywords);
            return parse_option(spec, value.cast<std::string>(), OptionNames::Keywords);
    }
}

// The keyword names of the options `front` takes (render/lines/svg: kPython; batch: kBatch).
std::vector<std::string> keyword_names(unsigned front) {
    std::vector<std::string> names;
    for (const OptionSpec& s : scene_options())
        if (s.takes(front)) names.push_back(option_label(s, OptionNames::Keywords));
    return names;
}

// The keywords into the request, each checked as the option table says; None leaves an option
// unset. Any other keyword is an error (a typo must not pass silently).
void apply_keywords(SceneRequest& r, const py::kwargs& kwargs, unsigned front) {
    for (const auto& item : kwargs) {
        const std::string key = py::str(item.first);
        const OptionSpec* spec = find_option(key);
        if (!spec || !spec->takes(front) || option_label(*spec, OptionNames::Keywords) != key) {
            std::string names;
            for (const auto& k : keyword_names(front)) names += (names.empty() ? "" : ", ") + k;
            throw InputError("unknown keyword '" + key + "' (expected " + names + ")");
        }
        if (item.second.is_none()) continue;
        const OptionValue value = option_value(*spec, key, item.second);
        check_option_value(*spec, value, OptionNames::Keywords);
        spec->put(r, std::monostate{});
        spec->put(r, value);
    }
}

// "size=WxH (default 512x512): image size; ..." for a docstring.
std::string keyword_doc(unsigned front) {
    std::string doc;
    for (const OptionSpec& s : scene_options()) {
        if (!s.takes(front)) continue;
        const std::string d = option_default(s, front);
        doc +=
            "\n  " + option_label(s, OptionNames::Keywords) + (d.empty() ? "" : " (default " + d + ")") + ": " + s.help;
    }
    return doc;
}

// The request of one call: the look (style, overrides) and the keywords; make_scene checks it.
SceneRequest request_of(const std::string& style, const std::vector<std::string>& set, const py::kwargs& kwargs,
                        SceneOutputs outputs) {
    SceneRequest r = default_request(kPython);
    r.names = OptionNames::Keywords;
    r.outputs = outputs;
    r.style = style;
    r.sets = set;
    apply_keywords(r, kwargs, kPython);
    // Without a size, the image takes a file camera's aspect (as the CLI without --size).
    r.size_from_camera = !kwargs.contains("size") || kwargs["size"].is_none();
    return r;
}

// uint8, or uint16 when the image has 16-bit pixels (bit_depth=16).
py::array to_array(Image&& image) {
    auto* owned = new Image(std::move(image));
    py::capsule free_image(owned, [](void* p) { delete static_cast<Image*>(p); });
    if (!owned->rgba16.empty())
        return py::array_t<uint16_t>({owned->height, owned->width, 4}, owned->rgba16.data(), free_image);
    return py::array_t<uint8_t>({owned->height, owned->width, 4}, owned->rgba.data(), free_image);
}

// A vector as an array of `shape` that owns it: no copy of the pixels.
template <class T>
py::array owning_array(std::vector<T>&& values, std::vector<py::ssize_t> shape) {
    auto* owned = new std::vector<T>(std::move(values));
    py::capsule free_values(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
    return py::array_t<T>(std::move(shape), owned->data(), free_values);
}

// render(aov=[...]): {"image": ..., "depth": float32 (h, w), "normal": float32 (h, w, 3), "id" and
// "material": uint32 (h, w), "mask", "lines-TYPE" (or "lines-SET-TYPE") and "lineset-SET": uint8 (h, w),
// the surface fields "ndotv", "kr", "dwkr", "k1", "k2": float32 (h, w), "pdir1", "pdir2": float32
// (h, w, 2), "shading-s0" ...: float32 (h, w), "camera": the camera file's dict (with "fields")}.
py::dict aov_dict(Image&& image, AovImages&& aovs, AovSet set, const CameraRecord& camera) {
    const py::ssize_t h = aovs.height, w = aovs.width;
    py::dict out;
    out["image"] = to_array(std::move(image));
    if (set.contains(Aov::Depth)) out["depth"] = owning_array(std::move(aovs.depth), {h, w});
    if (set.contains(Aov::Normal)) out["normal"] = owning_array(std::move(aovs.normal), {h, w, 3});
    if (set.contains(Aov::Id)) out["id"] = owning_array(std::move(aovs.id), {h, w});
    if (set.contains(Aov::Material)) out["material"] = owning_array(std::move(aovs.material), {h, w});
    if (set.contains(Aov::Mask)) out["mask"] = owning_array(std::move(aovs.mask), {h, w});
    for (LineMask& m : aovs.lines)
        out[py::str(line_mask_name(m.lineset, m.type))] = owning_array(std::move(m.pixels), {h, w});
    for (LineSetMask& m : aovs.linesets)
        out[py::str("lineset-" + m.lineset)] = owning_array(std::move(m.pixels), {h, w});
    for (Aov a : {Aov::Ndotv, Aov::Kr, Aov::Dwkr, Aov::K1, Aov::K2, Aov::Pdir1, Aov::Pdir2}) {
        if (!set.contains(a)) continue;
        const int channels = field_channels(a);
        out[aov_name(a)] = channels == 1 ? owning_array(std::move(field_buffer(aovs, a)), {h, w})
                                         : owning_array(std::move(field_buffer(aovs, a)), {h, w, channels});
    }
    for (size_t k = 0; k < aovs.shading.size(); ++k)
        out[py::str("shading-s" + std::to_string(k))] = owning_array(std::move(aovs.shading[k]), {h, w});
    CameraRecord record = camera;
    if (!set.fields().empty()) record.fields = aovs.field_scales;
    out["camera"] = py::module_::import("json").attr("loads")(format_camera_json(record));
    return out;
}

// With `detail` (lines_json_detail='full'), each path's surface location, tangent and normal too,
// as --lines-json-detail full writes them.
py::dict point_detail(const LinePath& path) {
    const auto n = py::ssize_t(path.points.size());
    py::array_t<float> world({n, py::ssize_t(3)}), barycentric({n, py::ssize_t(3)}), tangent({n, py::ssize_t(2)}),
        normal({n, py::ssize_t(2)});
    py::array_t<int32_t> face(n);
    auto w = world.mutable_unchecked<2>(), b = barycentric.mutable_unchecked<2>();
    auto f = face.mutable_unchecked<1>();
    for (py::ssize_t i = 0; i < n; ++i) {
        const SurfacePoint s = size_t(i) < path.surface.size() ? path.surface[size_t(i)] : SurfacePoint{};
        for (int k = 0; k < 3; ++k) w(i, k) = s.world[k], b(i, k) = s.barycentric[k];
        f(i) = s.face;
    }
    const std::vector<glm::vec2> tangents = path_tangents(path);
    auto t = tangent.mutable_unchecked<2>(), m = normal.mutable_unchecked<2>();
    for (py::ssize_t i = 0; i < n; ++i) {
        const glm::vec2 nv = path_normal(tangents[size_t(i)]);
        t(i, 0) = tangents[size_t(i)].x, t(i, 1) = tangents[size_t(i)].y, m(i, 0) = nv.x, m(i, 1) = nv.y;
    }
    py::dict d;
    d["world"] = world;
    d["face"] = face;
    d["barycentric"] = barycentric;
    d["tangent"] = tangent;
    d["normal"] = normal;
    return d;
}

py::list to_python(const LineDrawing& drawing, LinesJsonDetail detail) {
    py::list out;
    auto add = [&](const LineLayer& layer, const LinePath& path, bool hidden) {
        py::array_t<float> points({py::ssize_t(path.points.size()), py::ssize_t(2)});
        auto p = points.mutable_unchecked<2>();
        for (size_t i = 0; i < path.points.size(); ++i) {
            p(i, 0) = path.points[i].x;
            p(i, 1) = path.points[i].y;
        }
        py::dict d;
        d["type"] = layer.settings.type;
        d["lineset"] = layer.settings.lineset;
        d["points"] = points;
        d["depth"] = py::array_t<float>(py::ssize_t(path.depth.size()), path.depth.data());
        d["strength"] = py::array_t<float>(py::ssize_t(path.strength.size()), path.strength.data());
        d["closed"] = path.closed;
        d["hidden"] = hidden;
        d["level"] = path.level;
        if (detail == LinesJsonDetail::Full)
            for (const auto& item : point_detail(path)) d[item.first] = item.second;
        out.append(d);
    };
    for (const auto& layer : drawing.layers) {
        for (const auto& path : layer.visible) add(layer, path, false);
        for (const auto& path : layer.hidden) add(layer, path, true);
    }
    return out;
}

// One renderer (one OpenGL context) and the line extractor of the current mesh.
class PyRenderer {
public:
    void set_mesh(const PyMesh& mesh) {
        mesh_ = mesh;
        renderer_.set_mesh(mesh_);
        extractor_ = std::make_unique<LineExtractor>(mesh_);
    }
    // The request's scene, with the pose of the mesh where the request gives none; a mesh loaded
    // in another pose is loaded again in this one (and keeps it).
    Scene posed(SceneRequest request) {
        const Pose& loaded = mesh_.load.pose;
        if (request.animation.empty()) request.animation = loaded.animation;
        if (!request.time && time_moves(loaded, mesh_)) request.time = loaded.time;
        if (request.expressions.empty()) request.expressions = loaded.expressions;
        if (request.morphs.empty()) request.morphs = loaded.morphs;
        // Without a look, the mesh file's default (vrm for MToon files), as the CLI's.
        if (request.style.empty() && request.shading.empty() && !request.style_data)
            request.style = default_style_name(mesh_.path);
        Scene scene = make_scene(request);
        const Pose pose = scene.load_options().pose;
        if (extractor_ && !same_pose(pose, loaded, mesh_)) {
            if (mesh_.path.empty()) throw InputError("this mesh cannot be posed: load it with load_mesh(path)");
            PyMesh again;
            again.load = mesh_.load;
            again.load.pose = pose;
            again.path = mesh_.path;
            static_cast<Mesh&>(again) = load_mesh(again.path, again.load);
            set_mesh(again);
        }
        return scene;
    }
    py::object render(Scene scene) {
        need_mesh();
        place(scene);
        const Camera camera = scene.frame(mesh_);
        const Light light = scene.light(mesh_.bounds(), camera);
        Image image;
        AovImages aovs;
        {
            py::gil_scoped_release release;
            image = scene.aovs.empty() ? render_scene(renderer_, scene, camera, light)
                                       : render_scene(renderer_, scene, camera, light, aovs);
        }
        if (scene.aovs.empty()) return to_array(std::move(image));
        return aov_dict(std::move(image), std::move(aovs), scene.aovs, camera_record(scene, camera, mesh_.bounds()));
    }
    LineDrawing lines(Scene scene) {
        need_mesh();
        place(scene);
        py::gil_scoped_release release;
        return draw_scene_lines(*extractor_, scene, scene.frame(mesh_));
    }
    std::string gl_renderer() const { return renderer_.gl_renderer(); }

private:
    // The mesh's camera and light as camera= and lights= ask; warnings as Python warnings.
    void place(Scene& scene) const {
        for (const std::string& w : scene.apply_file_scene(mesh_))
            if (PyErr_WarnEx(PyExc_UserWarning, w.c_str(), 1) != 0) throw py::error_already_set();
    }
    void need_mesh() const {
        if (!extractor_) throw InputError("no mesh: call set_mesh(load_mesh(path)) first");
    }
    Renderer renderer_;
    PyMesh mesh_;
    std::unique_ptr<LineExtractor> extractor_;
};

// The scene of lines() and svg(): the object-space types given, else the style's.
Scene line_scene(PyRenderer& renderer, std::optional<std::vector<std::string>> types, const std::string& style,
                 const std::vector<std::string>& set, bool hidden, const std::optional<std::string>& levels,
                 const py::kwargs& kwargs) {
    SceneRequest r = request_of(style, set, kwargs, {.image = false, .line_drawing = true});
    r.vector_lines = std::move(types);
    r.hidden = hidden;
    if (levels) r.occlusion_levels = parse_occlusion_levels(*levels);
    return renderer.posed(r);
}

// Mesh and load_mesh.
void def_mesh(py::module_& m) {
    py::class_<PyMesh>(m, "Mesh")
        .def_property_readonly("vertex_count", &Mesh::vertex_count)
        .def_property_readonly("triangle_count", &Mesh::triangle_count)
        .def_property_readonly(
            "bounds",
            [](const PyMesh& mesh) {
        const BoundingBox b = mesh.bounds();
        return std::make_pair(std::array<float, 3>{b.min.x, b.min.y, b.min.z},
                              std::array<float, 3>{b.max.x, b.max.y, b.max.z});
            })
        .def_readonly("warnings", &Mesh::warnings)
        .def_property_readonly(
            "cameras",
            [](const PyMesh& mesh) {
        std::vector<std::string> names;
        for (const FileCamera& c : mesh.cameras) names.push_back(c.name);
        return names;
            },
            "The file's camera names, in the order camera=INDEX counts them (glTF cameras).")
        .def_property_readonly(
            "lights",
            [](const PyMesh& mesh) {
        std::vector<std::string> names;
        for (const FileLight& l : mesh.lights) names.push_back(l.name);
        return names;
            },
            "The file's light names (glTF KHR_lights_punctual); lights=\"file\" uses the first.")
        .def("__repr__", [](const PyMesh& mesh) {
            return "<inkshade.Mesh " + std::to_string(mesh.vertex_count()) + " vertices, " +
                   std::to_string(mesh.triangle_count()) + " triangles>";
        });
    m.def(
        "load_mesh",
        [](const std::string& path, float smooth_angle, const py::kwargs& kwargs) {
        for (const auto& item : kwargs) {
            const std::string key = py::str(item.first);
            if (key != "time" && key != "animation" && key != "morph" && key != "expression" && key != "spring_bones")
                throw InputError("unknown keyword '" + key +
                                 "' (expected smooth_angle, time, animation, morph, expression, spring_bones)");
        }
        SceneRequest request = request_of("", {}, kwargs, {});  // checked as every front end checks it
        request.smooth_angle = smooth_angle;
        PyMesh mesh;
        mesh.path = path;
        mesh.load = make_scene(request).load_options();
        static_cast<Mesh&>(mesh) = load_mesh(path, mesh.load);
        return mesh;
        },
        py::arg("path"), py::arg("smooth_angle") = LoadOptions{}.smooth_angle,
        "Loads OBJ/STL/PLY/OFF/glTF/GLB/VRM or builtin:NAME (sphere, torus, torus-knot, teapot). A file "
        "without normals gets hard edges where faces meet at more than smooth_angle degrees (180: all smooth). "
        "A glTF/VRM file is posed by animation= (name or index) at time= seconds, expression= and morph= "
        "({name: weight} or ['NAME=W', ...]), as the CLI's --animation, --time, --expression, --morph; "
        "spring_bones='off' keeps a VRM's spring bones in the file's pose.");
}

// The names of styles, line types and shading models.
void def_listings(py::module_& m) {
    m.def("styles", &builtin_style_names, "Built-in style names (presets and shading models).");
    m.def("line_types", [] {
        std::vector<std::string> names;
        for (const LineType* t : line_types()) names.push_back(t->name);
        return names;
    });
    m.def(
        "shading_models",
        [] {
        py::dict models;
        for (const ShadingModel* model : shading_models()) {
            py::dict params;
            for (const ParamSpec& p : model->params) params[py::str(p.name)] = p.doc;
            models[py::str(model->name)] = py::dict(py::arg("summary") = model->summary, py::arg("params") = params);
        }
        return models;
        },
        "{model name: {summary, params: {name: description}}}");
}

// batch(): datasets as `inkshade batch` renders them.
void def_batch(py::module_& m) {
    // Batch rendering: a manifest (CSV/JSON Lines) or models x views x styles, as `inkshade
    // batch`; progress(event_dict) is called after each job with the GIL held.
    m.def(
        "batch",
        [](const std::string& output_dir, std::optional<std::string> manifest, std::optional<std::string> models,
           const std::string& views, const std::vector<std::string>& styles, const std::vector<std::string>& formats,
           bool force, std::optional<std::pair<int, int>> shard_of, const std::string& layout,
           const std::string& shard_size, const std::string& shard_prefix, bool transforms_json,
           std::optional<py::function> progress, const py::kwargs& kwargs) {
        BatchDefaults defaults;
        defaults.views = views;
        defaults.styles.clear();
        for (const auto& s : styles) defaults.styles += (defaults.styles.empty() ? "" : ",") + s;
        defaults.options.names = OptionNames::Keywords;  // the options every job shares, checked as render's
        apply_keywords(defaults.options, kwargs, kBatch);
        check_request(defaults.options);
        defaults.outputs = {};
        defaults.outputs.png = false;
        for (const auto& f : formats) {
            if (f == "png")
                defaults.outputs.png = true;
            else if (f == "svg")
                defaults.outputs.svg = true;
            else if (f == "lines-json")
                defaults.outputs.lines_json = true;
            else
                throw InputError("formats: expected png, svg and/or lines-json, got '" + f + "'");
        }
        if (manifest.has_value() == models.has_value())
            throw InputError("batch: give exactly one of manifest= or models=");
        std::vector<BatchJob> jobs =
            manifest ? load_manifest(*manifest, defaults) : expand_jobs(find_models(*models), defaults);
        // Where the jobs go, as batch's --layout, --shard-size, --shard-prefix, --transforms-json.
        BatchOptions options{.output_dir = output_dir, .force = force};
        options.layout = parse_layout(layout);
        options.transforms_json = transforms_json;
        if (options.layout == BatchLayout::WebDataset) {
            if (transforms_json) throw InputError("transforms_json: only with layout='folder'");
            options.shard_size = parse_shard_size(shard_size);
            options.shard_prefix =
                webdataset_shard_prefix(shard_prefix, shard_of ? shard_of->first : 0, shard_of ? shard_of->second : 0);
            check_webdataset_keys(jobs);  // across every shard's jobs
        }
        if (shard_of) jobs = shard(jobs, shard_of->first, shard_of->second);
        BatchProgress report;
        if (progress)
            report = [&](const BatchEvent& e) {
                py::gil_scoped_acquire gil;
                const char* status = e.status == BatchStatus::Done      ? "done"
                                     : e.status == BatchStatus::Skipped ? "skipped"
                                                                        : "failed";
                (*progress)(py::dict(py::arg("status") = status, py::arg("stem") = e.job ? e.job->stem : "",
                                     py::arg("reason") = e.reason, py::arg("finished") = e.finished,
                                     py::arg("total") = e.total, py::arg("seconds") = e.seconds));
            };
        BatchSummary summary;
        {
            py::gil_scoped_release release;
            summary = run_batch(jobs, options, report);
        }
        py::list failures;
        for (const auto& f : summary.failures)
            failures.append(
                py::dict(py::arg("stem") = f.stem, py::arg("model") = f.model, py::arg("reason") = f.reason));
        return py::dict(py::arg("total") = summary.total, py::arg("done") = summary.done,
                        py::arg("skipped") = summary.skipped, py::arg("failed") = summary.failed,
                        py::arg("seconds") = summary.seconds, py::arg("failures") = failures);
        },
        py::arg("output_dir"), py::kw_only(), py::arg("manifest") = py::none(), py::arg("models") = py::none(),
        py::arg("views") = BatchDefaults{}.views, py::arg("styles") = std::vector<std::string>{},
        py::arg("formats") = std::vector<std::string>{"png"}, py::arg("force") = false, py::arg("shard") = py::none(),
        py::arg("layout") = "folder", py::arg("shard_size") = "1GB", py::arg("shard_prefix") = "shard",
        py::arg("transforms_json") = false, py::arg("progress") = py::none(),
        ("Renders a dataset as `inkshade batch` does; returns {total, done, skipped, failed, seconds, failures}. "
         "The option keywords are the defaults of the manifest's columns of those names:" +
         keyword_doc(kBatch))
            .c_str());
}

// Renderer: render, lines and svg of one mesh.
void def_renderer(py::module_& m) {
    py::class_<PyRenderer>(m, "Renderer", "A headless OpenGL 4.5 renderer (EGL) holding one mesh.")
        .def(py::init<>())
        .def("set_mesh", &PyRenderer::set_mesh, py::arg("mesh"))
        .def_property_readonly("gl_renderer", &PyRenderer::gl_renderer)
        .def(
            "render",
            [](PyRenderer& r, const std::string& style, const std::vector<std::string>& set, int samples,
               const py::object& background, const std::vector<std::string>& lines, const std::vector<std::string>& aov,
               const py::kwargs& kwargs) {
        SceneRequest request = request_of(style, set, kwargs, {.image = true, .line_drawing = false});
        request.samples = samples;
        request.added_lines = lines;
        request.aovs = aov;
        if (!background.is_none()) request.background = to_color("background", background, true);
        return r.render(r.posed(request));
            },
            py::arg("style") = "", py::arg("set") = std::vector<std::string>{}, py::arg("samples") = 4,
            py::arg("background") = py::none(), py::arg("lines") = std::vector<std::string>{},
            py::arg("aov") = std::vector<std::string>{},
            ("RGBA uint8 array (height, width, 4), top row first, uint16 with bit_depth=16: the PNG `inkshade "
             "render` writes for the same options (style '': the mesh file's default, vrm for a file with MToon "
             "materials, else lambert); `lines` adds line types to the style, as `inkshade render "
             "--lines`. With aov=[names] (depth, normal, id, material, mask, lines, ndotv, kr, dwkr, k1, k2, pdir1, "
             "pdir2, shading-scales, camera) a dict instead: "
             "'image', one array per AOV ('lines-TYPE' per line type) and 'camera' (docs/aov.md). Keywords:" +
             keyword_doc(kPython))
                .c_str())
        .def(
            "lines",
            [](PyRenderer& r, std::optional<std::vector<std::string>> types, const std::string& style,
               const std::vector<std::string>& set, bool hidden, const std::optional<std::string>& levels,
               const py::kwargs& kwargs) {
        const Scene scene = line_scene(r, std::move(types), style, set, hidden, levels, kwargs);
        return to_python(r.lines(scene), scene.lines_json_detail);
            },
            py::arg("types") = py::none(), py::arg("style") = "ink-vector", py::arg("set") = std::vector<std::string>{},
            py::arg("hidden") = false, py::arg("occlusion_levels") = py::none(),
            ("Object-space polylines, as `inkshade lines` draws them: a list of {type, lineset, points (n,2) pixels, "
             "depth, strength, closed, hidden, level}; occlusion_levels='A-B' as --occlusion-levels; with "
             "lines_json_detail='full' also world (n,3), face (n,) int32, barycentric (n,3), tangent (n,2) and "
             "normal (n,2), as --lines-json-detail full. Keywords:" +
             keyword_doc(kPython))
                .c_str())
        .def(
            "svg",
            [](PyRenderer& r, std::optional<std::vector<std::string>> types, const std::string& style,
               const std::vector<std::string>& set, bool hidden, const std::optional<std::string>& levels,
               const py::kwargs& kwargs) {
        const Scene scene = line_scene(r, std::move(types), style, set, hidden, levels, kwargs);
        return format_svg(r.lines(scene), scene.style.background);
            },
            py::arg("types") = py::none(), py::arg("style") = "ink-vector", py::arg("set") = std::vector<std::string>{},
            py::arg("hidden") = false, py::arg("occlusion_levels") = py::none(),
            ("The SVG text `inkshade lines` writes. Keywords:" + keyword_doc(kPython)).c_str());
}

}  // namespace

PYBIND11_MODULE(_inkshade, m) {  // the extension inside the package python/inkshade
    m.doc() = "Inkshade: toon/NPR shading and line drawing for triangle meshes (headless OpenGL).";
    m.attr("__version__") = kVersion;
    // InputError (bad files, names, values) arrives as ValueError, RuntimeError as RuntimeError.
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const InputError& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        }
    });

    def_mesh(m);
    def_listings(m);
    def_batch(m);
    def_renderer(m);
}
