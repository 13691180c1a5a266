// What a command left in a directory, for comparing outputs byte for byte (a batch's folder
// layout against its WebDataset shards, a resumed run against a fresh one).
#pragma once
#include <filesystem>
#include <map>
#include <string>

#include "cli/run_cli.hpp"

namespace inkshade::test {

// Relative path -> bytes of every file under `dir`, hidden ones (temporaries) included; empty
// when `dir` does not exist.
inline std::map<std::string, std::string> files_under(const std::filesystem::path& dir) {
    std::map<std::string, std::string> files;
    if (!std::filesystem::exists(dir)) return files;
    for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
        if (e.is_regular_file()) files[e.path().lexically_relative(dir).string()] = slurp(e.path().string());
    return files;
}

}  // namespace inkshade::test
