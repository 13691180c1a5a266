// The job hash of batch metadata (inkshade/batch.hpp): resume renders a job again exactly
// when something that decides its files changed.
#include <cstdio>
#include <fstream>
#include <iterator>
#include <optional>

#include "inkshade/batch.hpp"
#include "inkshade/options.hpp"
#include "io/vrm_animation.hpp"

namespace inkshade {

namespace {

// Version of what the hashed text means; bump it when the same text would render differently.
// 2: auto-framing frames the box corners tightly with a margin (the same view renders larger).
constexpr int kHashFormat = 2;

std::string number(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", double(v));  // round-trips every float
    return buf;
}

std::string optional_number(const std::optional<float>& v) { return v ? number(*v) : "-"; }

std::string optional_vec3(const std::optional<glm::vec3>& v) {
    return v ? number(v->x) + "," + number(v->y) + "," + number(v->z) : "-";
}

// FNV-1a, 64 bits: stable across platforms and releases, unlike std::hash.
uint64_t fnv1a(std::string_view text) {
    uint64_t h = 0xcbf29ce484222325ull;
    for (unsigned char c : text) {
        h ^= c;
        h *= 0x100000001b3ull;
    }
    return h;
}

// " NAME=VALUE" for each option of the view's line or the image's, in the table's order: always,
// or where the value is not SceneRequest's default (a list once per item).
std::string hashed_options(const SceneRequest& r, bool view_line) {
    const HashUse always = view_line ? HashUse::ViewAlways : HashUse::None;
    const HashUse when_set = view_line ? HashUse::ViewWhenSet : HashUse::ImageWhenSet;
    std::string text;
    for (const OptionSpec& spec : scene_options()) {
        if (spec.hash == HashUse::None || (spec.hash != always && spec.hash != when_set)) continue;
        const OptionValue value = spec.get(r);
        if (spec.hash == when_set && !option_is_set(spec, r)) continue;
        if (const auto* weights = std::get_if<std::vector<NamedWeight>>(&value)) {
            for (const NamedWeight& w : *weights) text += " " + spec.name + "=" + w.name + "=" + number(w.weight);
            continue;
        }
        const std::string spelled = format_option_hash(spec, value);
        if (!spelled.empty()) text += " " + spec.name + "=" + spelled;
    }
    return text;
}

// " animation-file=HASH" for a .vrma animation: its bytes decide the pose as the model's do
// (unreadable: "-", and the render reports why).
std::string animation_file(const std::string& animation) {
    if (!io::is_vrma_path(animation)) return {};
    std::ifstream in(animation, std::ios::binary);
    if (!in) return " animation-file=-";
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(fnv1a(bytes)));
    return std::string(" animation-file=") + hex;
}

}  // namespace

std::string job_hash(const BatchJob& job, std::string_view style_text, int64_t model_bytes) {
    const SceneRequest r = job_request(job);
    const CameraOptions& c = r.camera;
    std::string text = "inkshade-batch " + std::to_string(kHashFormat) + "\n";
    text += "model=" + job.model + "\nbytes=" + std::to_string(model_bytes) + "\n";
    text += "view=" + job.view.name + " az=" + optional_number(c.azimuth_degrees) +
            " el=" + optional_number(c.elevation_degrees) + " dist=" + optional_number(c.distance) +
            " eye=" + optional_vec3(c.eye) + " target=" + optional_vec3(c.target) + " up=" + optional_vec3(c.up);
    if (job.view.roll_degrees) text += " roll=" + number(*job.view.roll_degrees);  // only when set: earlier hashes stay
    // Options added after a job was hashed write nothing at their default, so the job keeps its hash.
    text += hashed_options(r, /*view_line=*/true) + "\n";
    text += "size=" + std::to_string(r.size.x) + "x" + std::to_string(r.size.y) +
            " samples=" + std::to_string(r.samples) + " png=" + (job.outputs.png ? "1" : "0") +
            " svg=" + (job.outputs.svg ? "1" : "0") + (job.outputs.lines_json ? " lines-json=1" : "");
    text += hashed_options(r, /*view_line=*/false) + animation_file(r.animation) + "\n";
    text += "style=" + job.style + "\n";
    text += style_text;
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(fnv1a(text)));
    return hex;
}

}  // namespace inkshade
