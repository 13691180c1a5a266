// The metadata file of a batch job (STEM.json): what was rendered, how, and the job hash
// that tells resume whether the job's files are complete and current.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "inkshade/aov.hpp"
#include "inkshade/batch.hpp"
#include "inkshade/camera.hpp"

namespace inkshade::batch {

struct JobRecord {
    const BatchJob* job = nullptr;
    std::string hash;          // job_hash
    int64_t model_bytes = -1;  // -1: not a file (builtin)
    size_t vertices = 0, triangles = 0;
    Camera camera;  // as framed for the job
    std::string style_toml;                                  // format_style of the style used
    std::vector<std::string> lines;                          // the style's line types (drawn in the PNG)
    std::vector<std::string> svg_lines;                      // object-space types in the SVG
    std::string gl_renderer;                                 // empty when no PNG was rendered
    std::vector<std::pair<std::string, double>> timings_ms;  // "load", "render", "svg", "write"
    std::vector<std::string> aov_files;                      // write_aov_files's names
    FieldScales fields;                                      // with a surface-field AOV (docs/aov.md)
};

// STEM.json text (docs/cli.md#batch lists the fields), keys in a fixed order.
std::string format_metadata(const JobRecord& record);

// OUTPUT_DIR/STEM + extension (".png", ".svg", ".json").
std::string job_file(const std::string& output_dir, const BatchJob& job, const char* extension);

// True when STEM.json exists and holds `hash`, and each output the job asks for exists (the AOV
// files as its outputs.aov lists them).
bool job_complete(const std::string& output_dir, const BatchJob& job, const std::string& hash);

}  // namespace inkshade::batch
