// Batch job metadata (batch/metadata.hpp): written last, so its presence with the right
// hash marks a complete job.
#include "batch/metadata.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "batch/jobs.hpp"
#include "inkshade/options.hpp"
#include "inkshade/version.hpp"

namespace inkshade::batch {

namespace {

using Json = nlohmann::ordered_json;

// The shortest text that reads back to the same float, as a JSON number: 0.1f is written
// 0.1, not 0.10000000149011612.
Json number(float v) {
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    if (ec != std::errc()) return double(v);
    return std::stod(std::string(buf, end));
}

Json vec3(const glm::vec3& v) { return Json::array({number(v.x), number(v.y), number(v.z)}); }

// Rows of the matrix (glm stores columns): clip = projection * view * (x, y, z, 1).
Json rows(const glm::mat4& m) {
    Json out = Json::array();
    for (int r = 0; r < 4; ++r)
        out.push_back(Json::array({number(m[0][r]), number(m[1][r]), number(m[2][r]), number(m[3][r])}));
    return out;
}

Json optional_number(const std::optional<float>& v) { return v ? number(*v) : Json(nullptr); }

// Indented like dump(2), but an array of numbers or strings stays on one line: a matrix
// reads as four rows instead of twenty lines.
void write_pretty(const Json& j, int indent, std::string& out) {
    const std::string pad(size_t(indent) * 2, ' '), inner(size_t(indent + 1) * 2, ' ');
    if (j.is_object() && !j.empty()) {
        out += "{\n";
        size_t n = 0;
        for (const auto& [key, value] : j.items()) {
            out += inner + Json(key).dump() + ": ";
            write_pretty(value, indent + 1, out);
            out += ++n < j.size() ? ",\n" : "\n";
        }
        out += pad + "}";
    } else if (j.is_array() && !j.empty() &&
               !std::all_of(j.begin(), j.end(), [](const Json& e) { return e.is_primitive(); })) {
        out += "[\n";
        for (size_t i = 0; i < j.size(); ++i) {
            out += inner;
            write_pretty(j[i], indent + 1, out);
            out += i + 1 < j.size() ? ",\n" : "\n";
        }
        out += pad + "]";
    } else if (j.is_array()) {
        out += "[";
        for (size_t i = 0; i < j.size(); ++i) out += (i ? ", " : "") + j[i].dump();
        out += "]";
    } else {
        out += j.dump();
    }
}

// An option's value in the metadata, as it has always been written: numbers of the "view"
// object in their shortest form, the others as JSON converts a float.
Json option_json(const OptionValue& value, bool nested) {
    struct ToJson {
        bool nested;
        Json operator()(std::monostate) const { return nullptr; }
        Json operator()(float v) const { return nested ? number(v) : Json(v); }
        Json operator()(int v) const { return v; }
        Json operator()(bool v) const { return v; }
        Json operator()(const std::string& v) const { return v; }
        Json operator()(const glm::vec3& v) const { return vec3(v); }
        Json operator()(const glm::vec4& v) const { return Json::array({v.x, v.y, v.z, v.w}); }
        Json operator()(const glm::ivec2& v) const { return Json::array({v.x, v.y}); }
        Json operator()(const std::vector<std::string>& v) const { return v; }
        Json operator()(const std::vector<NamedWeight>& v) const {
            Json out = Json::object();
            for (const NamedWeight& w : v) out[w.name] = w.weight;
            return out;
        }
        Json operator()(const OcclusionLevels& v) const { return Json::array({v.min, v.max}); }
    };
    return std::visit(ToJson{nested}, value);
}

// The options with a metadata key: those inside an object ("view.margin") or the top-level ones,
// in the table's order; where the job hash always writes one, always, else where it is set.
void add_options(const SceneRequest& r, bool nested, Json& j) {
    for (const OptionSpec& spec : scene_options()) {
        const size_t dot = spec.metadata.find('.');
        if (spec.metadata.empty() || (dot != std::string::npos) != nested) continue;
        const OptionValue value = spec.get(r);
        const bool always = spec.hash == HashUse::ViewAlways;
        if (!always && !option_is_set(spec, r)) continue;
        if (nested)
            j[spec.metadata.substr(0, dot)][spec.metadata.substr(dot + 1)] = option_json(value, true);
        else
            j[spec.metadata] = option_json(value, false);
    }
}

}  // namespace

std::string job_file(const std::string& output_dir, const BatchJob& job, const char* extension) {
    return (std::filesystem::path(output_dir) / (job.stem + extension)).string();
}

std::string format_metadata(const JobRecord& r) {
    const BatchJob& job = *r.job;
    const std::string file = std::filesystem::path(job.stem).filename().string();
    const SceneRequest request = job_request(job);
    const float aspect = float(request.size.x) / float(request.size.y);
    Json j;
    j["inkshade"] = kVersion;
    j["job_hash"] = r.hash;
    j["stem"] = job.stem;
    j["source"] = job.source;
    j["model"] = {{"path", job.model},
                  {"bytes", r.model_bytes >= 0 ? Json(r.model_bytes) : Json(nullptr)},
                  {"vertices", r.vertices},
                  {"triangles", r.triangles}};
    j["view"] = {{"name", job.view.name},
                 {"azimuth_degrees", optional_number(job.view.camera.azimuth_degrees)},
                 {"elevation_degrees", optional_number(job.view.camera.elevation_degrees)},
                 {"distance", optional_number(job.view.camera.distance)}};
    if (job.view.roll_degrees) j["view"]["roll_degrees"] = number(*job.view.roll_degrees);
    add_options(request, /*nested=*/true, j);
    if (!job.view.file_camera.empty()) j["view"]["file_camera"] = job.view.file_camera;  // camera=NAME
    add_options(request, /*nested=*/false, j);
    j["camera"] = {{"eye", vec3(r.camera.eye)},
                   {"target", vec3(r.camera.target)},
                   {"up", vec3(r.camera.up)},
                   {"fov_degrees", number(r.camera.fov_degrees)},
                   {"orthographic", r.camera.orthographic},
                   {"ortho_height", number(r.camera.ortho_height)},
                   {"near", number(r.camera.near_plane)},
                   {"far", number(r.camera.far_plane)},
                   {"aspect", number(aspect)},
                   {"view_matrix", rows(r.camera.view())},
                   {"projection_matrix", rows(r.camera.projection(aspect))}};
    j["image"] = {{"width", request.size.x}, {"height", request.size.y}, {"samples", request.samples}};
    j["style"] = {{"name", job.style}, {"toml", r.style_toml}};
    j["lines"] = r.lines;
    Json outputs = Json::object();
    if (job.outputs.png) outputs["png"] = file + ".png";
    if (job.outputs.svg) outputs["svg"] = file + ".svg";
    if (job.outputs.lines_json) outputs["lines_json"] = file + ".lines.json";
    if (job.outputs.svg || job.outputs.lines_json) j["svg_lines"] = r.svg_lines;
    if (const std::string mesh = mesh_file_stem(job); !mesh.empty())  // relative to the metadata, as the others
        outputs["mesh"] = std::filesystem::path(mesh)
                              .lexically_relative(std::filesystem::path(job.stem).parent_path())
                              .generic_string();
    if (const AovSet aovs = job_aovs(job); !aovs.empty()) {
        outputs["aov"] = r.aov_files;
        j["aov"] = format_aov_set(aovs);
        if (!aovs.fields().empty()) j["fields"] = Json::parse(format_field_scales(r.fields));
    }
    j["outputs"] = outputs;
    j["renderer"] = r.gl_renderer.empty() ? Json(nullptr) : Json(r.gl_renderer);
    Json timings = Json::object();
    for (const auto& [stage, ms] : r.timings_ms) timings[stage] = std::round(ms * 1000.0) / 1000.0;
    j["timings_ms"] = timings;
    std::string text;
    write_pretty(j, 0, text);
    return text + "\n";
}

bool job_complete(const std::string& output_dir, const BatchJob& job, const std::string& hash) {
    std::error_code ec;
    if ((job.outputs.png && !std::filesystem::is_regular_file(job_file(output_dir, job, ".png"), ec)) ||
        (job.outputs.svg && !std::filesystem::is_regular_file(job_file(output_dir, job, ".svg"), ec)) ||
        (job.outputs.lines_json && !std::filesystem::is_regular_file(job_file(output_dir, job, ".lines.json"), ec)))
        return false;
    if (const std::string mesh = mesh_file_stem(job);
        !mesh.empty() && !std::filesystem::is_regular_file(std::filesystem::path(output_dir) / mesh, ec))
        return false;
    std::ifstream in(job_file(output_dir, job, ".json"), std::ios::binary);
    if (!in) return false;
    std::stringstream text;
    text << in.rdbuf();
    const Json j = Json::parse(text.str(), nullptr, /*allow_exceptions=*/false);
    if (!j.is_object()) return false;  // unreadable metadata: render the job again
    const auto it = j.find("job_hash");
    if (it == j.end() || !it->is_string() || it->get<std::string>() != hash) return false;
    if (job_aovs(job).empty()) return true;
    const Json* aov = j.contains("outputs") && j["outputs"].is_object() && j["outputs"].contains("aov")
                          ? &j["outputs"]["aov"]
                          : nullptr;
    if (!aov || !aov->is_array()) return false;
    const std::filesystem::path dir = std::filesystem::path(job_file(output_dir, job, "")).parent_path();
    for (const Json& name : *aov)
        if (!name.is_string() || !std::filesystem::is_regular_file(dir / name.get<std::string>(), ec)) return false;
    return true;
}

}  // namespace inkshade::batch
