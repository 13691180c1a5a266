// A batch job's output files from its metadata (batch/job_outputs.hpp).
#include "batch/job_outputs.hpp"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "inkshade/error.hpp"

namespace inkshade::batch {

namespace {

// ordered: the order the metadata lists them in (png, svg, aov, ...).
using Json = nlohmann::ordered_json;

void collect(const Json& j, std::vector<std::string>& names) {
    if (j.is_string()) {
        if (std::find(names.begin(), names.end(), j.get<std::string>()) == names.end())
            names.push_back(j.get<std::string>());
    } else if (j.is_array() || j.is_object()) {
        for (const Json& e : j) collect(e, names);
    }
}

}  // namespace

std::vector<std::string> job_output_names(const std::string& metadata_text) {
    const Json j = Json::parse(metadata_text, nullptr, false);
    if (!j.is_object() || !j.contains("outputs") || !j["outputs"].is_object())
        throw RuntimeError("the metadata has no \"outputs\" object");
    std::vector<std::string> names;
    collect(j["outputs"], names);
    return names;
}

std::string metadata_job_hash(const std::string& metadata_text) {
    const Json j = Json::parse(metadata_text, nullptr, false);
    if (!j.is_object() || !j.contains("job_hash") || !j["job_hash"].is_string()) return "";
    return j["job_hash"].get<std::string>();
}

}  // namespace inkshade::batch
