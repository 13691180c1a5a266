// The job hash of batch metadata (inkshade/batch.hpp): resume renders a job again exactly
// when something that decides its files changed.
#include <cstdio>
#include <optional>

#include "inkshade/batch.hpp"

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

}  // namespace

std::string job_hash(const BatchJob& job, std::string_view style_text, int64_t model_bytes, int samples) {
    const CameraOptions& c = job.view.camera;
    std::string text = "inkshade-batch " + std::to_string(kHashFormat) + "\n";
    text += "model=" + job.model + "\nbytes=" + std::to_string(model_bytes) + "\n";
    text += "view=" + job.view.name + " az=" + optional_number(c.azimuth_degrees) +
            " el=" + optional_number(c.elevation_degrees) + " dist=" + optional_number(c.distance) +
            " eye=" + optional_vec3(c.eye) + " target=" + optional_vec3(c.target) + " up=" + optional_vec3(c.up) +
            " fov=" + number(c.fov_degrees) + " ortho=" + (c.orthographic ? "1" : "0") + " margin=" + number(c.margin);
    // Only a model that is not y-up adds to the text, so earlier jobs keep their hashes.
    if (c.up_axis && *c.up_axis != UpAxis::PosY) text += " up-axis=" + std::to_string(int(*c.up_axis));
    if (job.smooth_angle) text += " smooth-angle=" + number(*job.smooth_angle);
    if (!job.view.file_camera.empty()) text += " camera=" + job.view.file_camera;
    if (job.lights == LightSource::File) text += " lights=file";
    if (job.light_intensity) text += " light-intensity=" + number(*job.light_intensity);
    text += "\n";
    text += "size=" + std::to_string(job.width) + "x" + std::to_string(job.height) +
            " samples=" + std::to_string(samples) + " png=" + (job.outputs.png ? "1" : "0") +
            " svg=" + (job.outputs.svg ? "1" : "0");
    // Only jobs with AOVs add to the text, so earlier jobs keep their hashes.
    if (!job.aovs.empty()) text += " aov=" + format_aov_set(job.aovs);
    // Likewise only jobs with occlusion levels (their SVG has other layers).
    if (job.occlusion_levels)
        text += " occlusion-levels=" + std::to_string(job.occlusion_levels->min) + "-" +
                std::to_string(job.occlusion_levels->max);
    // Likewise only posed jobs (a glTF animation's time, expressions, morph weights).
    if (job.time) text += " time=" + number(*job.time);
    if (!job.animation.empty()) text += " animation=" + job.animation;
    for (const NamedWeight& e : job.expressions) text += " expression=" + e.name + "=" + number(e.weight);
    for (const NamedWeight& m : job.morphs) text += " morph=" + m.name + "=" + number(m.weight);
    text += "\n";
    text += "style=" + job.style + "\n";
    text += style_text;
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(fnv1a(text)));
    return hex;
}

}  // namespace inkshade
