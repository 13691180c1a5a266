// A job's WebDataset sample from its files in the staging folder (batch/webdataset_shards.hpp):
// whatever files the metadata's "outputs" lists, so a new kind of output joins the sample
// without a change here.
#include <filesystem>
#include <fstream>
#include <sstream>

#include "batch/job_outputs.hpp"
#include "batch/webdataset_shards.hpp"
#include "inkshade/batch.hpp"
#include "inkshade/error.hpp"
#include "io/tar_writer.hpp"

namespace inkshade::batch {

namespace fs = std::filesystem;

namespace {

std::string read_bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw RuntimeError(path.string() + ": cannot read the staged file");
    std::stringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

}  // namespace

std::string take_staged_sample(const std::string& staging, const std::string& stem) {
    const fs::path metadata = fs::path(staging) / (stem + ".json");
    const std::string metadata_text = read_bytes(metadata);
    const fs::path dir = metadata.parent_path();
    const std::string base = fs::path(stem).filename().string();
    const std::string key = webdataset_key(stem);
    std::string sample;
    std::vector<fs::path> staged;
    for (const std::string& name : job_output_names(metadata_text)) {
        // Every output is STEM + extension ("VIEW.depth.exr"): in the sample KEY + extension.
        if (!name.starts_with(base + ".") || name.find('/') != std::string::npos)
            throw RuntimeError(stem + ": output '" + name + "' is not named after the job's stem");
        staged.push_back(dir / name);
        sample += io::tar_member(key + name.substr(base.size()), read_bytes(staged.back()));
    }
    sample += io::tar_member(key + ".json", metadata_text);  // last, as in the folder layout
    staged.push_back(metadata);
    std::error_code ec;
    for (const fs::path& p : staged) fs::remove(p, ec);
    return sample;
}

}  // namespace inkshade::batch
