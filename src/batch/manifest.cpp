// Batch manifests (inkshade/batch.hpp): CSV with a header line or JSON Lines, one job group
// per line, every problem reported as SOURCE:LINE.
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "batch/jobs.hpp"
#include "core/name_suggestion.hpp"
#include "inkshade/error.hpp"
#include "inkshade/scene.hpp"
#include "io/text_scanner.hpp"

namespace inkshade {

namespace {

using batch::default_group;
using batch::JobGroup;

const std::set<std::string> kColumns = {
    "model",     "name",    "views",        "view",   "styles",          "style",  "size", "format",           "fov",
    "ortho",     "up-axis", "smooth-angle", "lights", "light-intensity", "margin", "aov",  "occlusion-levels", "time",
    "animation", "morph",   "expression",   "output"};
const char* kColumnList =
    "model, name, views, styles, size, format, fov, ortho, up-axis, smooth-angle, lights, light-intensity, margin, "
    "aov, occlusion-levels, time, animation, morph, expression, output";

// Lines of the text with their 1-based numbers; '\r' before '\n' dropped.
std::vector<std::pair<int, std::string_view>> numbered_lines(std::string_view text) {
    if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);  // UTF-8 byte order mark
    std::vector<std::pair<int, std::string_view>> lines;
    int number = 0;
    while (!text.empty()) {
        size_t nl = text.find('\n');
        std::string_view line = text.substr(0, nl);
        if (line.ends_with('\r')) line.remove_suffix(1);
        lines.emplace_back(++number, line);
        if (nl == std::string_view::npos) break;
        text.remove_prefix(nl + 1);
    }
    return lines;
}

bool skipped(std::string_view line) {
    const std::string t = batch::trim(line);
    return t.empty() || t.front() == '#';
}

// Sets one field of a group from its text form (CSV cells; JSON strings).
// A number of a column in [lo, hi] ("KEY: expected EXPECTED, got 'x'" else).
float number_in(const std::string& key, const std::string& value, double lo, double hi, const char* expected) {
    double v = 0;
    auto [ptr, ec] = std::from_chars(value.data(), value.data() + value.size(), v);
    if (ec != std::errc() || ptr != value.data() + value.size() || !(v >= lo && v <= hi))
        throw InputError(key + ": expected " + expected + ", got " + io::quote_token(value));
    return float(v);
}

void set_field(JobGroup& g, const std::string& key, const std::string& value) {
    if (key == "model")
        g.model = value;
    else if (key == "name")
        g.name = value;
    else if (key == "views" || key == "view")
        g.views = value;
    else if (key == "styles" || key == "style")
        g.styles = value;
    else if (key == "output")
        g.output = value;
    else if (key == "size") {
        const glm::ivec2 size = parse_image_size("size", value);
        g.width = size.x, g.height = size.y;
    } else if (key == "format")
        g.outputs = batch::parse_formats(value);
    else if (key == "fov" || key == "margin") {
        double v = 0;
        auto [ptr, ec] = std::from_chars(value.data(), value.data() + value.size(), v);
        if (ec != std::errc() || ptr != value.data() + value.size())
            throw InputError(key + ": expected " + (key == "fov" ? "degrees" : "a fraction") + ", got " +
                             io::quote_token(value));
        CameraOptions camera;
        camera.fov_degrees = g.fov_degrees;
        camera.margin = g.margin;
        (key == "fov" ? camera.fov_degrees : camera.margin) = io::to_float(v);
        check_camera_options(camera, OptionNames::Keywords);  // the range every front end takes
        g.fov_degrees = camera.fov_degrees;
        g.margin = camera.margin;
    } else if (key == "up-axis") {
        g.up_axis = parse_up_axis("up-axis", value);
    } else if (key == "smooth-angle") {
        g.smooth_angle = number_in(key, value, 0.0, 180.0, "degrees in [0, 180]");
    } else if (key == "lights") {
        g.lights = parse_light_source("lights", value);
    } else if (key == "aov") {
        g.aovs = parse_aov_list("aov", value);
    } else if (key == "occlusion-levels") {
        g.occlusion_levels = parse_occlusion_levels(value);
    } else if (key == "time") {
        g.time = number_in(key, value, -1e9, 1e9, "seconds");
    } else if (key == "animation") {
        g.animation = value;
    } else if (key == "morph") {
        g.morphs = parse_named_weights("morph", value);
    } else if (key == "expression") {
        g.expressions = parse_named_weights("expression", value);
        SceneRequest check;  // weights in [0, 1], as every front end checks them
        check.names = OptionNames::Keywords;
        check.expressions = g.expressions;
        make_scene(check);
    } else if (key == "light-intensity") {
        g.light_intensity = number_in(key, value, 0.0, 1e6, "a number in [0, 1e6]");
    } else if (key == "ortho") {
        if (value == "true" || value == "1" || value == "yes")
            g.orthographic = true;
        else if (value == "false" || value == "0" || value == "no")
            g.orthographic = false;
        else
            throw InputError("ortho: expected true or false, got " + io::quote_token(value));
    }
}

void check_column(const std::string& key, std::set<std::string>& seen) {
    if (!kColumns.count(key))
        throw InputError("unknown column " + io::quote_token(key) + " (columns: " + kColumnList + ")");
    // "view" and "views" (and "style" / "styles") are one column under two spellings.
    std::string canonical = key == "view" ? "views" : key == "style" ? "styles" : key;
    if (!seen.insert(canonical).second) throw InputError("column " + io::quote_token(key) + " is given twice");
}

// One CSV record (RFC 4180 quoting within the line: "a, b" and "" for a quote).
std::vector<std::string> csv_fields(std::string_view line) {
    std::vector<std::string> fields;
    std::string field;
    size_t i = 0;
    while (true) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        field.clear();
        if (i < line.size() && line[i] == '"') {
            ++i;
            while (true) {
                if (i >= line.size()) throw InputError("unterminated quoted field (records are one line each)");
                if (line[i] == '"') {
                    if (i + 1 < line.size() && line[i + 1] == '"') {
                        field += '"';
                        i += 2;
                        continue;
                    }
                    ++i;
                    break;
                }
                field += line[i++];
            }
            while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
            if (i < line.size() && line[i] != ',')
                throw InputError("unexpected text after a quoted field: " + io::quote_token(line.substr(i)));
        } else {
            size_t end = line.find(',', i);
            if (end == std::string_view::npos) end = line.size();
            field = batch::trim(line.substr(i, end - i));
            if (field.find('"') != std::string::npos)
                throw InputError("quote inside an unquoted field: " + io::quote_token(field));
            i = end;
        }
        fields.push_back(field);
        if (i >= line.size()) break;
        ++i;  // the comma
    }
    return fields;
}

void parse_csv(const std::vector<std::pair<int, std::string_view>>& lines, const std::string& source,
               const BatchDefaults& defaults, std::vector<BatchJob>& jobs) {
    std::vector<std::string> header;
    for (const auto& [number, line] : lines) {
        if (skipped(line)) continue;
        try {
            const std::vector<std::string> fields = csv_fields(line);
            if (header.empty()) {
                std::set<std::string> seen;
                for (const std::string& f : fields) check_column(f, seen);
                if (!seen.count("model"))
                    throw InputError(
                        "the header line has no 'model' column (a CSV manifest starts with a header "
                        "such as model,views,styles)");
                header = fields;
                continue;
            }
            if (fields.size() != header.size())
                throw InputError("expected " + std::to_string(header.size()) + " fields as in the header, got " +
                                 std::to_string(fields.size()));
            JobGroup g = default_group(defaults);
            g.source = source + ":" + std::to_string(number);
            for (size_t i = 0; i < fields.size(); ++i)
                if (!fields[i].empty()) set_field(g, header[i], fields[i]);
            if (g.model.empty()) throw InputError("model: empty");
            batch::expand_group(g, jobs);
        } catch (const InputError& e) {
            throw InputError(source + ":" + std::to_string(number) + ": " + e.what());
        }
    }
}

// A JSON value as set_field's text: strings as they are, lists joined, numbers and booleans
// written out; `size` may also be [W, H].
std::string json_text(const std::string& key, const nlohmann::json& v) {
    if (v.is_string()) return v.get<std::string>();
    if (v.is_boolean() && key == "ortho") return v.get<bool>() ? "true" : "false";
    if (v.is_number_integer() && key == "occlusion-levels") return std::to_string(v.get<long long>());
    if (v.is_number() && (key == "fov" || key == "margin" || key == "light-intensity" || key == "time")) {
        const double d = v.get<double>();
        if (!std::isfinite(d)) throw InputError(key + ": not a finite number");
        std::ostringstream out;
        out.precision(17);
        out << d;
        return out.str();
    }
    if (v.is_array() && key == "size") {
        if (v.size() != 2 || !v[0].is_number_integer() || !v[1].is_number_integer())
            throw InputError("size: expected \"WxH\" or [W, H]");
        return std::to_string(v[0].get<long long>()) + "x" + std::to_string(v[1].get<long long>());
    }
    if (v.is_array() &&
        (key == "views" || key == "view" || key == "styles" || key == "style" || key == "format" || key == "aov")) {
        std::string joined;
        for (const auto& item : v) {
            if (!item.is_string()) throw InputError(key + ": expected a list of strings");
            // Views join with ';' so an explicit camera (eye=X,Y,Z) stays one item.
            joined += (joined.empty() ? "" : ";") + item.get<std::string>();
        }
        return joined;
    }
    throw InputError(key + ": unexpected JSON " + std::string(v.type_name()));
}

void parse_jsonl(const std::vector<std::pair<int, std::string_view>>& lines, const std::string& source,
                 const BatchDefaults& defaults, std::vector<BatchJob>& jobs) {
    for (const auto& [number, line] : lines) {
        if (skipped(line)) continue;
        try {
            nlohmann::json object;
            try {
                object = nlohmann::json::parse(line);
            } catch (const nlohmann::json::exception& e) {
                std::string what = e.what();
                const size_t colon = what.find("] ");
                throw InputError("not valid JSON (" + (colon == std::string::npos ? what : what.substr(colon + 2)) +
                                 ")");
            }
            if (!object.is_object()) throw InputError("expected a JSON object such as {\"model\": \"a.obj\"}");
            JobGroup g = default_group(defaults);
            g.source = source + ":" + std::to_string(number);
            std::set<std::string> seen;
            for (const auto& [key, value] : object.items()) {
                check_column(key, seen);
                if (!value.is_null()) set_field(g, key, json_text(key, value));
            }
            if (g.model.empty()) throw InputError("no \"model\" given");
            batch::expand_group(g, jobs);
        } catch (const InputError& e) {
            throw InputError(source + ":" + std::to_string(number) + ": " + e.what());
        }
    }
}

bool is_json_lines(std::string_view text, const std::string& source) {
    const std::string ext = lower_ascii(std::filesystem::path(source).extension().string());
    if (ext == ".csv") return false;
    if (ext == ".jsonl" || ext == ".ndjson" || ext == ".json") return true;
    for (const auto& [number, line] : numbered_lines(text))
        if (!skipped(line)) return batch::trim(line).front() == '{';
    return false;
}

}  // namespace

std::vector<BatchJob> parse_manifest(std::string_view text, const std::string& source, const BatchDefaults& defaults) {
    try {
        const auto lines = numbered_lines(text);
        std::vector<BatchJob> jobs;
        if (is_json_lines(text, source))
            parse_jsonl(lines, source, defaults, jobs);
        else
            parse_csv(lines, source, defaults, jobs);
        if (jobs.empty()) throw InputError(source + ": no jobs (the manifest lists no models)");
        batch::check_unique_stems(jobs);
        return jobs;
    } catch (const InputError& e) {
        throw InputError(io::one_line(e.what()));  // a lone CR in a field (found by fuzzing)
    }
}

std::vector<BatchJob> load_manifest(const std::string& path, const BatchDefaults& defaults) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw InputError(path, "is a directory (use --models DIR for a directory of models)");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, "cannot open file");
    std::stringstream ss;
    ss << in.rdbuf();
    return parse_manifest(ss.str(), path, defaults);
}

}  // namespace inkshade
