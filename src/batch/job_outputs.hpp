// The files a batch job wrote, as its metadata (STEM.json) lists them under "outputs": what the
// WebDataset packer puts in a job's sample and --verify checks, whatever outputs a job has.
#pragma once
#include <string>
#include <vector>

namespace inkshade::batch {

// The file names (relative to the metadata's folder) of every string under the metadata's
// "outputs" object, nested arrays and objects included, in order, each once. Throws
// RuntimeError when the text is not a metadata object with "outputs".
std::vector<std::string> job_output_names(const std::string& metadata_text);

// The metadata's "job_hash", or "" when the text is not a JSON object holding one.
std::string metadata_job_hash(const std::string& metadata_text);

}  // namespace inkshade::batch
