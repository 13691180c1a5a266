// The Python module `inkshade` (pybind11): load meshes, render styles into numpy arrays, extract
// object-space lines as lists, list styles and models. docs/python.md shows its use.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <optional>
#include <tuple>

#include "inkshade/batch.hpp"
#include "inkshade/error.hpp"
#include "inkshade/io.hpp"
#include "inkshade/line_drawing.hpp"
#include "inkshade/renderer.hpp"
#include "inkshade/style.hpp"

namespace py = pybind11;
using namespace inkshade;

namespace {

using Vec3 = std::optional<std::array<float, 3>>;

std::optional<glm::vec3> to_vec3(const Vec3& v) {
    if (!v) return std::nullopt;
    return glm::vec3((*v)[0], (*v)[1], (*v)[2]);
}

// The keyword arguments every call that looks at the mesh takes, as the CLI's options.
struct View {
    int width = 512, height = 512;
    CameraOptions camera;
    std::optional<glm::vec3> light_pos;
    bool point_light = false;

    // Keyword arguments: size=(w, h), azimuth, elevation, distance, eye, target, up, fov, ortho,
    // light_pos, light_type; any other keyword is an error (a typo must not pass silently).
    explicit View(const py::kwargs& kwargs) {
        static const std::vector<std::string> known = {"size", "azimuth", "elevation", "distance", "eye", "target",
                                                       "up", "fov", "ortho", "light_pos", "light_type"};
        for (const auto& item : kwargs) {
            const std::string key = py::str(item.first);
            if (std::find(known.begin(), known.end(), key) == known.end())
                throw InputError("unknown keyword '" + key +
                                 "' (expected size, azimuth, elevation, distance, eye, target, up, fov, ortho, "
                                 "light_pos, light_type)");
        }
        auto get = [&](const char* key, auto fallback) {
            using T = decltype(fallback);
            return kwargs.contains(key) && !kwargs[key].is_none() ? kwargs[key].template cast<T>() : fallback;
        };
        std::tie(width, height) = get("size", std::pair<int, int>(512, 512));
        if (width < 1 || height < 1 || width > 16384 || height > 16384)
            throw InputError("size: expected 1..16384 pixels per side");
        camera.azimuth_degrees = get("azimuth", std::optional<float>());
        camera.elevation_degrees = get("elevation", std::optional<float>());
        camera.distance = get("distance", std::optional<float>());
        camera.eye = to_vec3(get("eye", Vec3()));
        camera.target = to_vec3(get("target", Vec3()));
        camera.up = to_vec3(get("up", Vec3()));
        camera.fov_degrees = get("fov", 30.0f);
        camera.orthographic = get("ortho", false);
        light_pos = to_vec3(get("light_pos", Vec3()));
        const std::string light_type = get("light_type", std::string("directional"));
        if (light_type != "directional" && light_type != "point")
            throw InputError("light_type: expected directional or point, got '" + light_type + "'");
        point_light = light_type == "point";
    }
    Camera framed(const Mesh& mesh) const { return frame_camera(mesh.bounds(), camera, float(width) / float(height)); }
    Light light(const Mesh& mesh, const Camera& cam, const Style& style) const {
        Light l = default_light(mesh.bounds(), cam);
        if (point_light) l.type = LightType::Point;
        if (light_pos) l.position = *light_pos;
        apply_style_light(style, l);
        return l;
    }
};

Style resolved_style(const std::string& name, const std::vector<std::string>& sets,
                     const std::optional<std::vector<std::string>>& lines) {
    Style style = load_style(name);
    if (lines) {
        style.lines.clear();
        for (const auto& type : *lines) style.lines.push_back(LineSettings{.type = type});
    }
    for (const auto& s : sets) apply_override(style, s);
    return style;
}

py::array_t<uint8_t> to_array(Image&& image) {
    auto* owned = new Image(std::move(image));
    py::capsule free_image(owned, [](void* p) { delete static_cast<Image*>(p); });
    return py::array_t<uint8_t>({owned->height, owned->width, 4}, owned->rgba.data(), free_image);
}

py::list to_python(const LineDrawing& drawing) {
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
        d["points"] = points;
        d["depth"] = py::array_t<float>(py::ssize_t(path.depth.size()), path.depth.data());
        d["strength"] = py::array_t<float>(py::ssize_t(path.strength.size()), path.strength.data());
        d["closed"] = path.closed;
        d["hidden"] = hidden;
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
    void set_mesh(const Mesh& mesh) {
        mesh_ = mesh;
        renderer_.set_mesh(mesh_);
        extractor_ = std::make_unique<LineExtractor>(mesh_);
    }
    py::array_t<uint8_t> render(const Style& style, const View& view, int samples,
                                std::optional<std::array<float, 4>> background) {
        need_mesh();
        if (samples < 1 || samples > 16) throw InputError("samples: expected 1..16");
        RenderOptions options{.width = view.width, .height = view.height, .samples = samples,
                              .background = style.background};
        if (background) options.background = glm::vec4((*background)[0], (*background)[1], (*background)[2], (*background)[3]);
        const Camera camera = view.framed(mesh_);
        const Light light = view.light(mesh_, camera, style);
        Image image;
        {
            py::gil_scoped_release release;
            image = renderer_.render(camera, light, style.shading, style.lines, options);
        }
        return to_array(std::move(image));
    }
    LineDrawing lines(const Style& style, const View& view) {
        need_mesh();
        py::gil_scoped_release release;
        return extractor_->draw(view.framed(mesh_), view.width, view.height, style.lines);
    }
    std::string gl_renderer() const { return renderer_.gl_renderer(); }

private:
    void need_mesh() const {
        if (!extractor_) throw InputError("no mesh: call set_mesh(load_mesh(path)) first");
    }
    Renderer renderer_;
    Mesh mesh_;
    std::unique_ptr<LineExtractor> extractor_;
};

}  // namespace

PYBIND11_MODULE(inkshade, m) {
    m.doc() = "Inkshade: toon/NPR shading and line drawing for triangle meshes (headless OpenGL).";
    // InputError (bad files, names, values) arrives as ValueError, RuntimeError as RuntimeError.
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const InputError& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        }
    });

    py::class_<Mesh>(m, "Mesh")
        .def_property_readonly("vertex_count", &Mesh::vertex_count)
        .def_property_readonly("triangle_count", &Mesh::triangle_count)
        .def_property_readonly("bounds", [](const Mesh& mesh) {
            const BoundingBox b = mesh.bounds();
            return std::make_pair(std::array<float, 3>{b.min.x, b.min.y, b.min.z},
                                  std::array<float, 3>{b.max.x, b.max.y, b.max.z});
        })
        .def_readonly("warnings", &Mesh::warnings)
        .def("__repr__", [](const Mesh& mesh) {
            return "<inkshade.Mesh " + std::to_string(mesh.vertex_count()) + " vertices, " +
                   std::to_string(mesh.triangle_count()) + " triangles>";
        });
    m.def("load_mesh", [](const std::string& path) { return load_mesh(path); }, py::arg("path"),
          "Loads OBJ/STL/PLY/OFF/glTF/GLB/VRM or builtin:NAME (sphere, torus, torus-knot, teapot).");
    m.def("styles", &builtin_style_names, "Built-in style names (presets and shading models).");
    m.def("line_types", [] {
        std::vector<std::string> names;
        for (const LineType* t : line_types()) names.push_back(t->name);
        return names;
    });
    m.def("shading_models", [] {
        py::dict models;
        for (const ShadingModel* model : shading_models()) {
            py::dict params;
            for (const ParamSpec& p : model->params) params[py::str(p.name)] = p.doc;
            models[py::str(model->name)] = py::dict(py::arg("summary") = model->summary, py::arg("params") = params);
        }
        return models;
    }, "{model name: {summary, params: {name: description}}}");

    // Batch rendering: a manifest (CSV/JSON Lines) or models x views x styles, as `inkshade
    // batch`; progress(event_dict) is called after each job with the GIL held.
    m.def(
        "batch",
        [](const std::string& output_dir, std::optional<std::string> manifest, std::optional<std::string> models,
           const std::string& views, const std::vector<std::string>& styles, std::pair<int, int> size,
           const std::vector<std::string>& formats, bool force, std::optional<std::pair<int, int>> shard_of,
           int samples, std::optional<py::function> progress) {
            BatchDefaults defaults;
            defaults.views = views;
            defaults.styles.clear();
            for (const auto& s : styles) defaults.styles += (defaults.styles.empty() ? "" : ",") + s;
            std::tie(defaults.width, defaults.height) = size;
            defaults.outputs = {};
            defaults.outputs.png = false;
            for (const auto& f : formats) {
                if (f == "png") defaults.outputs.png = true;
                else if (f == "svg") defaults.outputs.svg = true;
                else throw InputError("formats: expected png and/or svg, got '" + f + "'");
            }
            if (manifest.has_value() == models.has_value())
                throw InputError("batch: give exactly one of manifest= or models=");
            std::vector<BatchJob> jobs = manifest ? load_manifest(*manifest, defaults)
                                                  : expand_jobs(find_models(*models), defaults);
            if (shard_of) jobs = shard(jobs, shard_of->first, shard_of->second);
            BatchOptions options{.output_dir = output_dir, .force = force, .samples = samples};
            BatchProgress report;
            if (progress)
                report = [&](const BatchEvent& e) {
                    py::gil_scoped_acquire gil;
                    const char* status = e.status == BatchStatus::Done ? "done"
                                         : e.status == BatchStatus::Skipped ? "skipped" : "failed";
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
                failures.append(py::dict(py::arg("stem") = f.stem, py::arg("model") = f.model, py::arg("reason") = f.reason));
            return py::dict(py::arg("total") = summary.total, py::arg("done") = summary.done,
                            py::arg("skipped") = summary.skipped, py::arg("failed") = summary.failed,
                            py::arg("seconds") = summary.seconds, py::arg("failures") = failures);
        },
        py::arg("output_dir"), py::kw_only(), py::arg("manifest") = py::none(), py::arg("models") = py::none(),
        py::arg("views") = "35:20", py::arg("styles") = std::vector<std::string>{"lambert"},
        py::arg("size") = std::pair<int, int>(512, 512), py::arg("formats") = std::vector<std::string>{"png"},
        py::arg("force") = false, py::arg("shard") = py::none(), py::arg("samples") = 4,
        py::arg("progress") = py::none(),
        "Renders a dataset as `inkshade batch` does; returns {total, done, skipped, failed, seconds, failures}.");

    py::class_<PyRenderer>(m, "Renderer", "A headless OpenGL 4.5 renderer (EGL) holding one mesh.")
        .def(py::init<>())
        .def("set_mesh", &PyRenderer::set_mesh, py::arg("mesh"))
        .def_property_readonly("gl_renderer", &PyRenderer::gl_renderer)
        .def(
            "render",
            [](PyRenderer& r, const std::string& style, const std::vector<std::string>& set, int samples,
               std::optional<std::array<float, 4>> background, const py::kwargs& view) {
                return r.render(resolved_style(style, set, std::nullopt), View(view), samples,
                                background);
            },
            py::arg("style") = "lambert", py::arg("set") = std::vector<std::string>{}, py::arg("samples") = 4,
            py::arg("background") = py::none(),
            "RGBA uint8 array (height, width, 4), top row first, as `inkshade render` writes it.")
        .def(
            "lines",
            [](PyRenderer& r, std::optional<std::vector<std::string>> types, const std::string& style,
               const std::vector<std::string>& set, const py::kwargs& view) {
                return to_python(r.lines(resolved_style(style, set, types), View(view)));
            },
            py::arg("types") = py::none(), py::arg("style") = "ink-vector", py::arg("set") = std::vector<std::string>{},
            "Object-space polylines: a list of {type, points (n,2) pixels, depth, strength, closed, hidden}.")
        .def(
            "svg",
            [](PyRenderer& r, std::optional<std::vector<std::string>> types, const std::string& style,
               const std::vector<std::string>& set, const py::kwargs& view) {
                const Style s = resolved_style(style, set, types);
                return format_svg(r.lines(s, View(view)), s.background);
            },
            py::arg("types") = py::none(), py::arg("style") = "ink-vector", py::arg("set") = std::vector<std::string>{}, "The SVG text `inkshade lines` writes.");
}
