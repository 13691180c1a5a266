// What fuzz_manifest does with one input: parse_manifest on the bytes, as CSV or JSON Lines.
// Byte 0 picks the source name, whose extension decides the format (.csv, .jsonl, or neither:
// the first character decides). Errors must be one line starting with the source.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "fuzz_common.hpp"
#include "inkshade/batch.hpp"

namespace inkshade::fuzz {

inline void manifest_input(std::string_view data) {
    static constexpr const char* kSources[] = {"jobs.csv", "jobs.jsonl", "jobs.txt"};
    if (data.empty()) return;
    const std::string source = kSources[static_cast<unsigned char>(data[0]) % 3];
    try {
        const std::vector<BatchJob> jobs = parse_manifest(data.substr(1), source);
        for (const BatchJob& job : jobs)
            if (job.model.empty() || job.stem.empty() || job.options.size.x < 1 || job.options.size.y < 1)
                broken("parse_manifest returned a job without model, stem or size");
    } catch (const InputError& e) {
        const std::string what = e.what();
        if (what.find('\n') != std::string::npos || what.find('\r') != std::string::npos)
            broken("multi-line error: " + what);
        if (what.rfind(source, 0) != 0) broken("error does not start with the source: " + what);
    }
}

}  // namespace inkshade::fuzz
