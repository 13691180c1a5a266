// Replays what a fuzzer saved (inputs that once broke a parser's contract) and the target's seed
// corpus through the fuzz target's own code: an exception escaping the target fails the test and
// names the file. Shared by the loaders', manifests', styles' and scenes' regression tests.
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <sstream>
#include <string>
#include <vector>

namespace inkshade::test {

// `dirs` relative to the source tree; missing ones are skipped, but some input must be found.
// Returns how many inputs were replayed.
inline size_t replay_fuzz_inputs(std::initializer_list<const char*> dirs,
                                 const std::function<void(const std::string& bytes)>& target) {
    const std::filesystem::path root(INKSHADE_SOURCE_DIR);
    std::vector<std::filesystem::path> files;
    for (const char* dir : dirs)
        if (std::filesystem::is_directory(root / dir))
            for (const auto& entry : std::filesystem::directory_iterator(root / dir)) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    EXPECT_FALSE(files.empty()) << "no inputs in " << *dirs.begin();
    for (const auto& file : files) {
        std::ifstream in(file, std::ios::binary);
        std::ostringstream bytes;
        bytes << in.rdbuf();
        try {
            target(bytes.str());
        } catch (const std::exception& e) {
            ADD_FAILURE() << file.string() << ": " << e.what();
        }
    }
    return files.size();
}

}  // namespace inkshade::test
