// A batch job's style, loaded once for the whole batch to check it and hash its text (the
// runner's job hashes and --verify's).
#pragma once
#include <optional>
#include <string>

#include "inkshade/scene.hpp"

namespace inkshade::batch {

struct ResolvedStyle {
    std::string toml;   // format_style: hashed and recorded, so an edited style file re-renders
    std::string error;  // the style does not load: every job of the style fails with this
    std::optional<float> smooth_angle;
    NormalWeighting normal_weighting = NormalWeighting::Angle;  // Scene::normal_weighting
};

ResolvedStyle resolve_style(const std::string& name);

// A model file's size in bytes for the job hash, -1 for a builtin or a file it cannot stat.
int64_t model_bytes(const std::string& path);

}  // namespace inkshade::batch
