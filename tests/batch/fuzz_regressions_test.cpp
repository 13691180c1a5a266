// Manifests the fuzzer (fuzz/fuzz_manifest.cpp, docs/testing.md "Fuzzing") found breaking
// parse_manifest's contract, saved as libFuzzer wrote them in tests/batch/fuzz_regressions/manifest/
// and replayed with the seed corpus (fuzz/corpus/manifest) through the target's own code
// (fuzz/manifest_target.hpp): each must parse or fail with one line that names its source.
#include <gtest/gtest.h>

#include "../../fuzz/manifest_target.hpp"
#include "support/fuzz_replay.hpp"

namespace inkshade::test {
namespace {

TEST(ManifestFuzzRegressions, ReplaySavedInputs) {
    replay_fuzz_inputs({"tests/batch/fuzz_regressions/manifest", "fuzz/corpus/manifest"},
                       [](const std::string& bytes) { fuzz::manifest_input(bytes); });
}

}  // namespace
}  // namespace inkshade::test
