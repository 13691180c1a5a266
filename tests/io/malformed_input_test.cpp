// Robustness: random bytes and randomly damaged valid files of every format must load or
// fail with a one-line InputError; never crash, hang or throw anything else. Runs under the
// sanitizer build too (INKSHADE_SANITIZE), which turns out-of-bounds reads into failures.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdlib>
#include <random>

#include "io/gltf_files.hpp"
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
    for (const char* ext : {".obj", ".stl", ".ply", ".off", ".gltf", ".glb", ".vrm"}) {
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
        {".obj", cube_obj()},       {".stl", cube_ascii_stl()},       {".stl", cube_binary_stl()},
        {".ply", cube_ascii_ply()}, {".ply", cube_binary_ply(false)}, {".ply", cube_binary_ply(true)},
        {".off", cube_off()},       {".glb", textured_quad().glb()},  {".gltf", textured_quad().gltf_embedded()}};
    const std::string tokens[] = {"-1",          "0", "nan", "inf", "1e40", "2147483648", "4294967295",
                                  "99999999999", "x", "\n",  " ",   "/",    "#"};
    for (const auto& [ext, original] : originals) {
        for (int i = 0; i < 300 * scale(); ++i) {
            std::string s = original;
            for (int edits = 1 + int(rng() % 3); edits > 0 && !s.empty(); --edits) {
                size_t at = rng() % s.size();
                switch (rng() % 4) {
                    case 0: s[at] = char(rng()); break;                              // flip a byte
                    case 1: s.resize(at); break;                                     // truncate
                    case 2: s.insert(at, tokens[rng() % std::size(tokens)]); break;  // splice a token
                    case 3: s.erase(at, rng() % 8); break;                           // drop bytes
                }
            }
            if (s.empty()) s = "x";
            expect_loads_or_input_error(dir.write("damaged" + ext, s), ext + " #" + std::to_string(i));
        }
    }
}

// GLB damage where it hurts most: the header, chunk table and JSON numbers (lengths, offsets,
// counts, indices), each replaced by extreme values. Every result loads or fails cleanly.
TEST(MalformedInput, GlbWithExtremeNumbersFailsCleanly) {
    TempDir dir;
    std::mt19937 rng(2024);
    const std::string original = textured_quad().glb();
    const std::string numbers[] = {"0",     "-1",  "3",    "4294967295", "4294967296", "2147483647", "99999999999999",
                                   "1e308", "0.5", "null", "\"x\""};
    for (int i = 0; i < 300 * scale(); ++i) {
        std::string s = original;
        if (i % 3 == 0) {  // a header or chunk-table word
            size_t at = std::array<size_t, 4>{4, 8, 12, 16}[rng() % 4];
            uint32_t v = std::array<uint32_t, 5>{0, 1, 2, 0xFFFFFFFFu, uint32_t(rng())}[rng() % 5];
            std::memcpy(&s[at], &v, 4);
        } else {  // a number in the JSON chunk, same length kept by padding with spaces
            uint32_t json_length;
            std::memcpy(&json_length, &s[12], 4);
            std::vector<size_t> digits;
            for (size_t k = 20; k < 20 + json_length; ++k)
                if (std::isdigit(static_cast<unsigned char>(s[k])) &&
                    !std::isdigit(static_cast<unsigned char>(s[k - 1])))
                    digits.push_back(k);
            size_t at = digits[rng() % digits.size()], end = at;
            while (std::isdigit(static_cast<unsigned char>(s[end])) || s[end] == '.') ++end;
            std::string json = s.substr(20, json_length);
            json.replace(at - 20, end - at, numbers[rng() % std::size(numbers)]);
            while (json.size() % 4) json.push_back(' ');
            uint32_t new_length = uint32_t(json.size());
            s.replace(20, json_length, json);
            std::memcpy(&s[12], &new_length, 4);
            uint32_t total = uint32_t(s.size());
            std::memcpy(&s[8], &total, 4);
        }
        expect_loads_or_input_error(dir.write("extreme.glb", s), "glb #" + std::to_string(i));
    }
}

}  // namespace
}  // namespace inkshade::test
