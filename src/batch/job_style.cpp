// Styles and model sizes as the job hash takes them (batch/job_style.hpp).
#include "batch/job_style.hpp"

#include <filesystem>

#include "inkshade/style.hpp"

namespace inkshade::batch {

ResolvedStyle resolve_style(const std::string& name) {
    ResolvedStyle r;
    try {
        SceneRequest request;
        request.style = name;
        const Scene scene = make_scene(request);
        r.toml = format_style(scene.style);
        r.smooth_angle = scene.style.smooth_angle;
        r.normal_weighting = scene.normal_weighting;
    } catch (const std::exception& e) {
        r.error = e.what();
    }
    return r;
}

int64_t model_bytes(const std::string& path) {
    if (path.starts_with("builtin:")) return -1;
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    return ec ? -1 : int64_t(size);
}

}  // namespace inkshade::batch
