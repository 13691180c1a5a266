// Batch mesh export (batch/mesh_export.hpp).
#include "batch/mesh_export.hpp"

#include <filesystem>
#include <set>

#include "batch/jobs.hpp"
#include "inkshade/mesh_writer.hpp"

namespace inkshade::batch {

void write_mesh_files(const std::string& output_dir, const std::vector<BatchJob>& jobs,
                      const std::vector<size_t>& indices, const Mesh& mesh) {
    std::set<std::string> written;
    for (size_t i : indices) {
        const std::string stem = mesh_file_stem(jobs[i]);
        if (stem.empty() || !written.insert(stem).second) continue;
        const std::filesystem::path path = std::filesystem::path(output_dir) / stem;
        std::filesystem::create_directories(path.parent_path());
        write_mesh(path.string(), mesh);
    }
}

}  // namespace inkshade::batch
