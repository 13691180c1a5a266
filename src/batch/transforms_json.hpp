// transforms.json for multi-view pipelines (instant-ngp, nerfstudio, Gaussian splatting): one
// per output directory of a batch, listing the complete jobs whose image lies there.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "inkshade/batch.hpp"

namespace inkshade::batch {

// The text of one transforms.json for `frames`: each frame's image file name (relative to the
// json) and the metadata (STEM.json) text of its job. Intrinsics go at the top when every frame
// has the same, else into each frame (docs/cli.md#batch). Throws InputError for metadata
// without a camera.
std::string format_transforms_json(const std::vector<std::pair<std::string, std::string>>& frames);

// Writes DIR/transforms.json atomically for each directory DIR of the jobs' PNG images, listing
// those of its jobs that are complete (batch::job_complete with `hashes[i]`) in the jobs'
// order; a directory without a complete job gets none. Reads the cameras from the metadata, so
// a resumed batch lists the jobs an earlier run rendered too. Throws RuntimeError.
void write_transforms_json(const std::string& output_dir, const std::vector<BatchJob>& jobs,
                           const std::vector<std::string>& hashes);

}  // namespace inkshade::batch
