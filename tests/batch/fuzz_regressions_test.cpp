// Manifests the fuzzer (fuzz/fuzz_manifest.cpp, docs/testing.md "Fuzzing") found breaking
// parse_manifest's contract, saved as libFuzzer wrote them in tests/batch/fuzz_regressions/manifest/
// and replayed with the seed corpus (fuzz/corpus/manifest) through the target's own code
// (fuzz/manifest_target.hpp): each must parse or fail with one line that names its source.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "../../fuzz/manifest_target.hpp"

namespace inkshade::test {
namespace {

TEST(ManifestFuzzRegressions, ReplaySavedInputs) {
    const std::filesystem::path root(INKSHADE_SOURCE_DIR);
    std::vector<std::filesystem::path> files;
    for (const auto& dir : {root / "tests/batch/fuzz_regressions/manifest", root / "fuzz/corpus/manifest"})
        for (const auto& entry : std::filesystem::directory_iterator(dir)) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    ASSERT_FALSE(files.empty());
    for (const auto& file : files) {
        std::ifstream in(file, std::ios::binary);
        std::ostringstream bytes;
        bytes << in.rdbuf();
        try {
            fuzz::manifest_input(bytes.str());
        } catch (const std::exception& e) {
            ADD_FAILURE() << file.string() << ": " << e.what();
        }
    }
}

}  // namespace
}  // namespace inkshade::test
