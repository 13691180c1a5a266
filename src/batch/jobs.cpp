// Batch jobs from models x views x styles (inkshade/batch.hpp): names, stems, shared values.
#include "batch/jobs.hpp"

#include <filesystem>
#include <map>
#include <sstream>

#include "inkshade/error.hpp"
#include "inkshade/scene.hpp"
#include "io/text_scanner.hpp"

namespace inkshade {

namespace batch {

namespace {

// Characters kept in names derived from model and style names; others become '-', so a stem
// is a portable file name whatever the model path holds.
std::string file_safe(std::string_view text) {
    std::string out;
    for (char c : text) {
        const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
                          c == '_' || c == '-' || c == '=' || c == '+';
        out += keep ? c : '-';
    }
    return out;
}

// A style file is named by its file name without ".toml"; a built-in style by its name.
std::string style_stem_name(const std::string& style) {
    const std::filesystem::path p(style);
    if (style.find('/') != std::string::npos || p.extension() == ".toml") return file_safe(p.stem().string());
    return file_safe(style);
}

// Whether two jobs' meshes are the same: one model in one pose (export-mesh writes it once).
bool same_mesh(const BatchJob& a, const BatchJob& b) {
    const SceneRequest &x = a.options, &y = b.options;
    return a.model == b.model && x.animation == y.animation && x.time == y.time && x.expressions == y.expressions &&
           x.morphs == y.morphs && x.spring_bones == y.spring_bones;
}

}  // namespace

std::string mesh_file_stem(const BatchJob& job) {
    return job.options.export_mesh.empty() ? std::string() : job.name + ".mesh." + job.options.export_mesh;
}

std::string trim(std::string_view text) {
    const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
    while (!text.empty() && space(text.front())) text.remove_prefix(1);
    while (!text.empty() && space(text.back())) text.remove_suffix(1);
    return std::string(text);
}

std::vector<std::string> split_list(std::string_view text, std::string_view separators) {
    std::vector<std::string> items;
    size_t start = 0;
    for (size_t i = 0; i <= text.size(); ++i) {
        if (i < text.size() && separators.find(text[i]) == std::string_view::npos) continue;
        std::string item = trim(text.substr(start, i - start));
        if (!item.empty()) items.push_back(item);
        start = i + 1;
    }
    return items;
}

BatchOutputs parse_formats(const std::string& text) {
    BatchOutputs o{false, false, false};
    for (const std::string& f : split_list(text, ",;+")) {
        if (f == "png")
            o.png = true;
        else if (f == "svg")
            o.svg = true;
        else if (f == "lines-json")
            o.lines_json = true;
        else
            throw InputError("format: unknown output format " + io::quote_token(f) +
                             " (choose png, svg, lines-json or a list of them)");
    }
    if (!o.png && !o.svg && !o.lines_json)
        throw InputError("format: no output format given (choose png, svg, lines-json or a list of them)");
    return o;
}

void check_relative_stem(const std::string& what, const std::string& stem) {
    if (stem.empty()) throw InputError(what + ": empty");
    if (stem.front() == '/')
        throw InputError(what + ": " + io::quote_token(stem) + " must be relative to the output directory");
    for (const std::string& part : split_list(stem, "/"))
        if (part == "..")
            throw InputError(what + ": " + io::quote_token(stem) + " must stay inside the output directory");
    if (stem.back() == '/' || stem.find("//") != std::string::npos)
        throw InputError(what + ": " + io::quote_token(stem) + " has an empty path component");
    for (char c : stem)
        if (static_cast<unsigned char>(c) < 0x20) throw InputError(what + ": control character in the name");
}

JobGroup default_group(const BatchDefaults& d) {
    JobGroup g;
    g.views = d.views;
    g.styles = d.styles;
    g.outputs = d.outputs;
    g.options = d.options;
    return g;
}

void expand_group(const JobGroup& group, std::vector<BatchJob>& out) {
    if (group.model.empty()) throw InputError("model: empty");
    const std::vector<BatchView> views = parse_views(group.views);
    const std::vector<std::string> styles =
        group.styles.empty() ? std::vector<std::string>{default_style_name(group.model)} : split_list(group.styles, ",;");
    if (styles.empty()) throw InputError("styles: no style given");
    std::map<std::string, std::string> style_names;  // stem name -> style, to catch a clash
    for (const std::string& s : styles) {
        auto [it, fresh] = style_names.emplace(style_stem_name(s), s);
        if (!fresh)
            throw InputError("styles: " + io::quote_token(s) + " and " + io::quote_token(it->second) +
                             " would write the same files (" + it->first + ")");
    }
    const std::string name = group.name.empty() ? model_name(group.model) : group.name;
    check_relative_stem("name", name);
    if (!group.options.export_mesh.empty() && group.options.export_mesh != "obj" && group.options.export_mesh != "ply")
        throw InputError("export-mesh: batch takes obj or ply (it writes NAME.mesh.EXT in the output directory), got " +
                         io::quote_token(group.options.export_mesh));
    if (!group.output.empty()) {
        check_relative_stem("output", group.output);
        if (views.size() * styles.size() != 1)
            throw InputError("output: names one job, but the line gives " + std::to_string(views.size()) + " views x " +
                             std::to_string(styles.size()) + " styles (drop output or use name)");
    }
    for (const std::string& style : styles) {
        for (BatchView view : views) {
            BatchJob job;
            job.model = group.model;
            job.style = style;
            job.outputs = group.outputs;
            job.stem = group.output.empty() ? name + "/" + style_stem_name(style) + "/" + view.name : group.output;
            job.name = name;
            job.view = std::move(view);
            job.source = group.source;
            job.options = group.options;
            out.push_back(std::move(job));
        }
    }
}

void check_unique_stems(const std::vector<BatchJob>& jobs) {
    std::map<std::string, const BatchJob*> seen, meshes;
    for (const BatchJob& job : jobs) {
        if (const std::string mesh = mesh_file_stem(job); !mesh.empty()) {
            auto [it, fresh] = meshes.emplace(mesh, &job);
            if (!fresh && !same_mesh(job, *it->second))
                throw InputError(io::one_line(job.source + ": export-mesh " + mesh + " (" + job.model +
                                              ") is also written by " + it->second->source + " (" + it->second->model +
                                              ") with another model or pose; give the lines different names"));
        }
        auto [it, fresh] = seen.emplace(job.stem, &job);
        if (!fresh)
            throw InputError(io::one_line(job.source + ": output " + job.stem + " (" + job.model + ", " + job.style +
                                          ") is also written by " + it->second->source + " (" + it->second->model +
                                          ", " + it->second->style + "); give the models different names"));
    }
}

}  // namespace batch

SceneRequest job_request(const BatchJob& job) {
    SceneRequest r = job.options;
    const CameraOptions& view = job.view.camera;
    CameraOptions& c = r.camera;
    c.azimuth_degrees = view.azimuth_degrees;
    c.elevation_degrees = view.elevation_degrees;
    c.distance = view.distance;
    c.eye = view.eye;
    c.target = view.target;
    c.up = view.up;
    r.file_camera = job.view.file_camera;
    if (!r.file_camera.empty()) {  // a file's camera has its own projection
        c.fov_degrees = CameraOptions{}.fov_degrees;
        c.orthographic = false;
    }
    return r;
}

AovSet job_aovs(const BatchJob& job) {
    AovSet set = aov_set("aov", job.options.aovs);
    if (job.options.lineset_ids.value_or(false)) set.add(Aov::LineSets);  // the lineset-ids column
    return set;
}

std::string model_name(const std::string& model) {
    constexpr std::string_view kBuiltin = "builtin:";
    if (model.starts_with(kBuiltin)) {
        std::string name = model.substr(kBuiltin.size());
        for (char& c : name)
            if (c == ':' || c == ',') c = '-';
        return batch::file_safe(name);
    }
    const std::string stem = std::filesystem::path(model).stem().string();
    return batch::file_safe(stem.empty() ? model : stem);
}

std::vector<BatchJob> expand_jobs(const std::vector<BatchModel>& models, const BatchDefaults& defaults,
                                  const std::string& source) {
    std::vector<BatchJob> jobs;
    for (const BatchModel& model : models) {
        batch::JobGroup group = batch::default_group(defaults);
        group.model = model.path;
        group.name = model.name;
        group.source = source;
        try {
            batch::expand_group(group, jobs);
        } catch (const InputError& e) {
            throw InputError(io::one_line(source + ": " + model.path + ": " + e.what()));
        }
    }
    batch::check_unique_stems(jobs);
    return jobs;
}

}  // namespace inkshade
