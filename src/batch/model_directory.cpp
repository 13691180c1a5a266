// The models of a directory for `inkshade batch --models DIR` (find_models, inkshade/batch.hpp).
#include <algorithm>
#include <filesystem>

#include "core/name_suggestion.hpp"
#include "inkshade/batch.hpp"
#include "inkshade/error.hpp"

namespace inkshade {

namespace {

// The extensions load_mesh reads (io/load_mesh.cpp); other files (textures, .mtl) are not models.
bool is_model_file(const std::filesystem::path& p) {
    const std::string ext = lower_ascii(p.extension().string());
    for (const char* known : {".obj", ".stl", ".ply", ".off", ".gltf", ".glb", ".vrm"})
        if (ext == known) return true;
    return false;
}

}  // namespace

std::vector<BatchModel> find_models(const std::string& directory) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::is_directory(directory, ec)) throw InputError(directory, "not a directory");
    std::vector<BatchModel> models;
    fs::recursive_directory_iterator it(directory, fs::directory_options::follow_directory_symlink, ec), end;
    if (ec) throw InputError(directory, "cannot read directory (" + ec.message() + ")");
    for (; it != end; it.increment(ec)) {
        if (ec) throw InputError(directory, "cannot read directory (" + ec.message() + ")");
        std::error_code type_ec;
        if (!it->is_regular_file(type_ec) || !is_model_file(it->path())) continue;
        const fs::path relative = it->path().lexically_relative(directory);
        BatchModel m;
        m.path = it->path().string();
        m.name = (relative.parent_path() / relative.stem()).generic_string();
        models.push_back(std::move(m));
    }
    std::sort(models.begin(), models.end(), [](const BatchModel& a, const BatchModel& b) { return a.path < b.path; });
    if (models.empty())
        throw InputError(directory, "no model files (.obj .stl .ply .off .gltf .glb .vrm) in the directory");
    return models;
}

}  // namespace inkshade
