// Style inputs the fuzzer (fuzz/fuzz_style, docs/testing.md "Fuzzing") found crashing, saved as
// libFuzzer wrote them in tests/styles/fuzz_regressions/ and replayed through the target's own
// code (fuzz/style_target.hpp: parse_style, overrides, the format_style round trip), and the
// fixes pinned down with small inputs.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "../../fuzz/scene_target.hpp"
#include "../../fuzz/style_target.hpp"
#include "support/fuzz_replay.hpp"

namespace inkshade {
namespace {

std::string error_of(std::string_view text) {
    try {
        parse_style(text, "my.toml");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

// Every saved input, and the seed corpus (fuzz/corpus/style: the presets and an override file).
TEST(StyleFuzzRegressions, ReplaySavedInputs) {
    test::replay_fuzz_inputs({"tests/styles/fuzz_regressions", "fuzz/corpus/style"},
                             [](const std::string& bytes) { fuzz::style_input(bytes); });
}

// toml++ 3.3 writes a string with a line break as '''...''' even when it holds ''' itself,
// and then cannot read it back: such strings are written as escaped basic strings.
TEST(StyleFuzzRegressions, SavedStringsWithQuotesAndLineBreaksReadBack) {
    for (const std::string description :
         {"a\nb''' c", "tab\tquote\" back\\slash", "del\x7f bell\x07", "it's", "plain text"}) {
        Style style = parse_style("[shading]\nmodel = 'phong'\n", "s.toml");
        style.description = description;
        const std::string text = format_style(style);
        EXPECT_EQ(parse_style(text, "s.toml").description, description) << text;
    }
}

// The scene target's seed corpus (fuzz/corpus/scene) and the inputs it found (a JSON key with a
// line break, quoted in an error; a number beyond double range, which nlohmann::json reports as
// out_of_range rather than parse_error).
TEST(SceneFuzzRegressions, ReplaySavedInputs) {
    EXPECT_GE(test::replay_fuzz_inputs({"tests/styles/scene_fuzz_regressions", "fuzz/corpus/scene"},
                                       [](const std::string& bytes) { fuzz::scene_input(bytes); }),
              7u);
}

// toml++ 3.3 reaches __builtin_unreachable when it tests a non-ASCII character for whitespace
// (after a key, inside a bare value, after a backslash in a multi-line string). TOML allows
// such characters only in strings and comments; elsewhere parse_style refuses them first.
TEST(StyleFuzzRegressions, NonAsciiOutsideStringsIsAnErrorBeforeTomlSeesIt) {
    const std::string model = "[shading]\nmodel = \"lambert\"\n";
    EXPECT_EQ(error_of(model + "base\xd0\x9c"
                               "color = 1\n"),
              "my.toml: line 3: non-ASCII character outside a string or comment (keys and values are ASCII)");
    EXPECT_EQ(error_of("background = \"white\" \xc2\xa1\n" + model),
              "my.toml: line 1: non-ASCII character outside a string or comment (keys and values are ASCII)");
    EXPECT_EQ(error_of("description = \"\"\"a\\\xc3\xa9\"\"\"\n" + model),
              "my.toml: line 1: non-ASCII character after a backslash in a multi-line string");
    EXPECT_EQ(error_of("description = \"\"\"a\\  \n\n  \xe3\x80\x80 b\"\"\"\n" + model),
              "my.toml: line 3: non-ASCII character after a line-ending backslash");
    // A quote inside a bare value starts no string: toml++ reads `0["\xc8\x9a` as one word.
    for (const char* value : {"0[\"\xc8\x9a\"]", "-1base-col'''or\xd0\x9c", "1.'\xc3\xa9'", "true\"\xc3\xa9\""})
        EXPECT_EQ(error_of(std::string("width = ") + value + "\n" + model),
                  "my.toml: line 1: non-ASCII character outside a string or comment (keys and values are ASCII)")
            << value;
    // Where TOML allows them they are fine: comments, strings of every kind, quoted keys.
    const std::string colour = error_of(
        "\xEF\xBB\xBF# caf\xc3\xa9 \xe2\x80\x94 n\xc2\xb7v\ndescription = \"\xc3\xa9\\\"\xe2\x80\x94\" # \xc2\xa1\n"
        "[light]\n\"color\" = '\xc3\xa9' # bad colour, but not a non-ASCII problem\n" +
        model);
    EXPECT_EQ(colour.rfind("my.toml: light.color: bad colour", 0), 0u) << colour;  // got past the check and toml++
    EXPECT_EQ(
        error_of("description = \"\"\"\xc3\xa9\n\xe2\x80\x94 \\\n   x\"\"\"\"\"\ntext = '''\xc3\xa9'''\n" + model),
        "my.toml: unknown key 'text' (allowed: description, background, base-color, mesh-colors, smooth-angle, "
        "up-axis, line-unit, light, shading, lines, lineset)");
}

// toml++ nests a table per dot of a key and frees them recursively: a key of 300000 dots (a
// 600 KB file, under the 1 MiB limit) overflowed the stack. At most 128 dots per line.
TEST(StyleFuzzRegressions, DeeplyDottedKeysAreRefusedBeforeTheStackOverflows) {
    std::string deep = "[shading]\nmodel = \"lambert\"\n";
    for (int i = 0; i < 300000; ++i) deep += "a.";
    EXPECT_EQ(error_of(deep + "b = 1\n"),
              "my.toml: line 3: more than 128 dots outside strings (keys nest at most that deep)");
    EXPECT_EQ(error_of("[" + deep.substr(30) + "b]\n"),
              "my.toml: line 1: more than 128 dots outside strings (keys nest at most that deep)");
    // Dots in strings and comments do not count; 128 on a line are fine (then: an unknown key).
    std::string fine = "description = \"" + std::string(1000, '.') + "\" # " + std::string(1000, '.') + "\n";
    for (int i = 0; i < 128; ++i) fine += "a.";
    EXPECT_EQ(error_of(fine + "b = 1\n").rfind("my.toml: unknown key 'a'", 0), 0u);
    // Arrays nested beyond toml++'s own limit of 256 are its error.
    const std::string arrays = "description = " + std::string(100000, '[') + std::string(100000, ']') + "\n";
    EXPECT_NE(error_of(arrays).find("exceeded maximum nested value depth of 256"), std::string::npos);
}

// Errors quote keys and values, which may hold line breaks: "a\r" is a valid TOML key, and
// --set text is anything. Control characters become '?' so errors stay one line.
TEST(StyleFuzzRegressions, ErrorsQuotingControlCharactersStayOneLine) {
    EXPECT_EQ(error_of("\"a\\r\\nb\" = 1\n[shading]\nmodel = \"lambert\"\n"),
              "my.toml: unknown key 'a??b' (allowed: description, background, base-color, mesh-colors, smooth-angle, "
              "up-axis, line-unit, light, shading, lines, lineset)");
    EXPECT_EQ(error_of("[shading]\nmodel = \"lam\\rbert\"\n").find_first_of("\r\n"), std::string::npos);
    Style style = parse_style("[shading]\nmodel = \"phong\"\n", "my.toml");
    try {
        apply_override(style, "model \r\r=1");
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("model 'phong' has no parameter 'model ?\?'", 0), 0u) << e.what();
    }
}

// A NUL where a table name should start: toml++ asserts in debug builds; the library Inkshade
// links (Debian's release build) reports a parse error, and so must parse_style.
TEST(StyleFuzzRegressions, NulInTableHeaderIsAParseError) {
    const std::string error = error_of(std::string("[shading]\nmodel = \"lambert\"\n[[\0", 31));
    EXPECT_NE(error.find("my.toml: line 3: "), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
}

}  // namespace
}  // namespace inkshade
