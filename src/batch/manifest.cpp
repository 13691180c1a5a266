// Batch manifests (inkshade/batch.hpp): CSV with a header line or JSON Lines, one job group
// per line, every problem reported as SOURCE:LINE.
#include <algorithm>
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
#include "inkshade/options.hpp"
#include "inkshade/scene.hpp"
#include "io/text_scanner.hpp"

namespace inkshade {

namespace {

using batch::default_group;
using batch::JobGroup;

// The columns of a manifest that are not scene options: what and where, not how.
const std::vector<std::string> kJobColumns = {"model", "name", "views", "styles", "format", "output"};

// The scene option a column sets (one that batch takes), or null.
const OptionSpec* option_column(const std::string& key) {
    const OptionSpec* spec = find_option(key);
    return spec && spec->takes(kBatch) && spec->name == key ? spec : nullptr;
}

std::vector<std::string> column_names() {
    std::vector<std::string> names = kJobColumns;
    for (const OptionSpec& s : scene_options())
        if (s.takes(kBatch)) names.push_back(s.name);
    return names;
}

std::string column_list() {
    std::string list;
    for (const std::string& c : column_names()) list += (list.empty() ? "" : ", ") + c;
    return list;
}

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

// Sets one field of a group from its text form (CSV cells; JSON strings): a cell replaces the
// default, a list included.
void set_field(JobGroup& g, const std::string& key, const std::string& value) {
    if (key == "model")
        g.model = value;
    else if (key == "name")
        g.name = value;
    else if (key == "views" || key == "view")
        g.views = value;
    else if (key == "styles" || key == "style") {
        // An empty list given is an error; a column left out keeps the model's own style.
        if (batch::split_list(value, ",;").empty()) throw InputError("styles: no style given");
        g.styles = value;
    }
    else if (key == "output")
        g.output = value;
    else if (key == "format")
        g.outputs = batch::parse_formats(value);
    else if (const OptionSpec* spec = option_column(key))
        replace_option(g.options, *spec, value, OptionNames::Columns);
}

void check_column(const std::string& key, std::set<std::string>& seen) {
    const bool job_column = key == "view" || key == "style" ||
                            std::find(kJobColumns.begin(), kJobColumns.end(), key) != kJobColumns.end();
    if (!job_column && !option_column(key))
        throw InputError("unknown column " + io::quote_token(key) + " (columns: " + column_list() + ")" +
                         did_you_mean(key, column_names()));
    // "view" and "views" (and "style" / "styles") are one column under two spellings.
    std::string canonical = key == "view" ? "views" : key == "style" ? "styles" : key;
    if (!seen.insert(canonical).second) throw InputError("column " + io::quote_token(key) + " is given twice");
}

// A group's values checked as every front end checks a request (ranges, weights, ...).
void check_group(const JobGroup& g) {
    SceneRequest check = g.options;
    check.names = OptionNames::Columns;
    check_request(check);
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
            check_group(g);
            batch::expand_group(g, jobs);
        } catch (const InputError& e) {
            throw InputError(source + ":" + std::to_string(number) + ": " + e.what());
        }
    }
}

// A JSON value as set_field's text: strings as they are, lists joined, numbers and booleans
// written out, each where the column's kind of value takes it; `size` may also be [W, H].
std::string json_text(const std::string& key, const nlohmann::json& v) {
    if (v.is_string()) return v.get<std::string>();
    const OptionSpec* spec = option_column(key);
    const OptionKind kind = spec ? spec->kind : OptionKind::Text;
    if (v.is_boolean() && kind == OptionKind::Flag) return v.get<bool>() ? "true" : "false";
    if (v.is_number_integer() && (kind == OptionKind::Levels || kind == OptionKind::Integer))
        return std::to_string(v.get<long long>());
    if (v.is_number() && kind == OptionKind::Number) {
        const double d = v.get<double>();
        if (!std::isfinite(d)) throw InputError(key + ": not a finite number");
        std::ostringstream out;
        out.precision(17);
        out << d;
        return out.str();
    }
    if (v.is_array() && kind == OptionKind::Size) {
        if (v.size() != 2 || !v[0].is_number_integer() || !v[1].is_number_integer())
            throw InputError("size: expected \"WxH\" or [W, H]");
        return std::to_string(v[0].get<long long>()) + "x" + std::to_string(v[1].get<long long>());
    }
    const bool list = key == "views" || key == "view" || key == "styles" || key == "style" || key == "format" ||
                      kind == OptionKind::Names;
    if (v.is_array() && list) {
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
            check_group(g);
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
