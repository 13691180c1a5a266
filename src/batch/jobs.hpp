// Building batch jobs from one group (a manifest line, or one model of --models): the pieces
// that parse_manifest and expand_jobs share, so both spell values and stems the same way.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "inkshade/batch.hpp"

namespace inkshade::batch {

// One manifest line's worth of jobs before expansion; empty strings take the defaults.
struct JobGroup {
    std::string model;
    std::string name;    // model part of the stems; empty = model_name(model)
    std::string views;   // parse_views text
    std::string styles;  // comma- or semicolon-separated style names / files
    std::string output;  // the stem of the one job, instead of NAME/STYLE/VIEW
    BatchOutputs outputs;
    SceneRequest options;  // the option table's values (BatchJob::options)
    std::string source;
};

// A group holding the defaults' views, styles, outputs and options (no model yet).
JobGroup default_group(const BatchDefaults& defaults);

// Appends the group's views x styles jobs (style-major). Throws InputError(problem) without
// the source: the caller knows where the group came from.
void expand_group(const JobGroup& group, std::vector<BatchJob>& out);

// Throws InputError("SOURCE: output STEM is also written by SOURCE2") for a shared stem, and
// for an export-mesh file that two jobs would write from different models or poses.
void check_unique_stems(const std::vector<BatchJob>& jobs);

// The file export-mesh writes for the job, relative to the output directory: NAME.mesh.obj or
// NAME.mesh.ply; empty when the job asks for none. check_unique_stems checks that jobs sharing
// one have the same model and pose.
std::string mesh_file_stem(const BatchJob& job);

// Non-empty trimmed items of `text` split at any of `separators`.
std::vector<std::string> split_list(std::string_view text, std::string_view separators);

std::string trim(std::string_view text);

// "png", "svg", "png,svg" (also '+' or ';' between). Throws InputError.
BatchOutputs parse_formats(const std::string& text);
// A relative path inside the output directory: no root, no "..", no empty components.
void check_relative_stem(const std::string& what, const std::string& stem);

}  // namespace inkshade::batch
