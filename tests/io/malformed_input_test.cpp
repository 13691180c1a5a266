// Robustness: random bytes and randomly damaged valid files of every format must load or
// fail with a one-line InputError; never crash, hang or throw anything else. Runs under the
// sanitizer build too (INKSHADE_SANITIZE), which turns out-of-bounds reads into failures.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <random>

#include "io/mesh_files.hpp"
#include "support/temp_dir.hpp"

namespace inkshade::test {
namespace {

// INKSHADE_FUZZ_SCALE=100 runs a hundred times the default number of cases (for a soak).
int scale() {
    const char* s = std::getenv("INKSHADE_FUZZ_SCALE");
    return s ? std::max(1, std::atoi(s)) : 1;
}

void expect_loads_or_input_error(const std::string& path, const std::string& label) {
    try {
        load_mesh(path);
    } catch (const InputError& e) {
        std::string what = e.what();
        EXPECT_EQ(what.find('\n'), std::string::npos) << label << ": " << what;
        EXPECT_EQ(what.rfind(path, 0), 0u) << label << ": " << what;
    } catch (const std::exception& e) {
        ADD_FAILURE() << label << ": unexpected " << typeid(e).name() << ": " << e.what();
    }
}

TEST(MalformedInput, RandomBytesFailCleanlyInEveryFormat) {
    TempDir dir;
    std::mt19937 rng(1234);
    for (const char* ext : {".obj", ".stl", ".ply", ".off"}) {
        for (int i = 0; i < 100 * scale(); ++i) {
            std::string s(rng() % 3000 + 1, '\0');
            for (char& c : s) c = char(rng());
            expect_loads_or_input_error(dir.write(std::string("r") + ext, s), ext);
        }
    }
}

TEST(MalformedInput, DamagedValidFilesFailCleanly) {
    TempDir dir;
    std::mt19937 rng(99);
    const std::vector<std::pair<std::string, std::string>> originals = {
        {".obj", cube_obj()}, {".stl", cube_ascii_stl()}, {".stl", cube_binary_stl()},
        {".ply", cube_ascii_ply()}, {".ply", cube_binary_ply(false)}, {".ply", cube_binary_ply(true)},
        {".off", cube_off()}};
    const std::string tokens[] = {"-1", "0", "nan", "inf", "1e40", "2147483648", "4294967295", "99999999999", "x", "\n", " ", "/", "#"};
    for (const auto& [ext, original] : originals) {
        for (int i = 0; i < 300 * scale(); ++i) {
            std::string s = original;
            for (int edits = 1 + int(rng() % 3); edits > 0 && !s.empty(); --edits) {
                size_t at = rng() % s.size();
                switch (rng() % 4) {
                    case 0: s[at] = char(rng()); break;                                      // flip a byte
                    case 1: s.resize(at); break;                                             // truncate
                    case 2: s.insert(at, tokens[rng() % std::size(tokens)]); break;          // splice a token
                    case 3: s.erase(at, rng() % 8); break;                                   // drop bytes
                }
            }
            if (s.empty()) s = "x";
            expect_loads_or_input_error(dir.write("damaged" + ext, s), ext + " #" + std::to_string(i));
        }
    }
}

}  // namespace
}  // namespace inkshade::test
