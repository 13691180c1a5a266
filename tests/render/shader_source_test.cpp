// gpu/shader_source.hpp: `#include "file"` lines are expanded where they stand, each file once
// per source; a missing include, a cycle or a malformed line is an error naming the including
// file and line. Every embedded shader expands.
#include <gtest/gtest.h>

#include <map>

#include "gpu/embedded_shaders.hpp"
#include "gpu/shader_source.hpp"
#include "inkshade/error.hpp"

namespace inkshade::test {
namespace {

std::string expand(const std::map<std::string, std::string>& files, const std::string& path) {
    return gpu::expand_includes(path, [&](const std::string& p) -> const char* {
        auto it = files.find(p);
        return it == files.end() ? nullptr : it->second.c_str();
    });
}

std::string error_of(const std::map<std::string, std::string>& files, const std::string& path) {
    try {
        expand(files, path);
    } catch (const RuntimeError& e) {
        return e.what();
    }
    return "";
}

TEST(ShaderSource, IncludesExpandInPlaceOncePerSource) {
    const std::map<std::string, std::string> files = {
        {"main.frag", "#version 450 core\n#include \"a.glsl\"  // why\n#include \"b.glsl\"\nvoid main() {}\n"},
        {"a.glsl", "#include \"common.glsl\"\nfloat a;\n"},
        {"b.glsl", "#include \"common.glsl\"\nfloat b;\n"},
        {"common.glsl", "float common;\n"},
    };
    EXPECT_EQ(expand(files, "main.frag"), "#version 450 core\nfloat common;\nfloat a;\nfloat b;\nvoid main() {}\n");
}

TEST(ShaderSource, MissingIncludeNamesTheIncludingFileAndLine) {
    const std::map<std::string, std::string> files = {
        {"main.frag", "#version 450 core\n#include \"a.glsl\"\n"},
        {"a.glsl", "float a;\n#include \"common/nope.glsl\"\n"},
    };
    const std::string error = error_of(files, "main.frag");
    EXPECT_NE(error.find("a.glsl line 2"), std::string::npos) << error;
    EXPECT_NE(error.find("common/nope.glsl is not embedded"), std::string::npos) << error;
    EXPECT_NE(error_of(files, "missing.frag").find("missing.frag is not embedded"), std::string::npos);
}

TEST(ShaderSource, CyclesAndMalformedIncludesAreErrors) {
    const std::map<std::string, std::string> cycle = {
        {"a.glsl", "#include \"b.glsl\"\n"},
        {"b.glsl", "\n#include \"a.glsl\"\n"},
    };
    const std::string error = error_of(cycle, "a.glsl");
    EXPECT_NE(error.find("b.glsl line 2: #include \"a.glsl\" includes itself"), std::string::npos) << error;
    const std::map<std::string, std::string> malformed = {{"a.glsl", "#include \"b.glsl\n"}};
    EXPECT_NE(error_of(malformed, "a.glsl").find("a.glsl line 1: malformed #include"), std::string::npos);
}

TEST(ShaderSource, EveryEmbeddedShaderExpands) {
    int count = 0;
    for (const EmbeddedFile& f : gpu::embedded_shaders()) {
        std::string source;
        ASSERT_NO_THROW(source = gpu::shader_source(f.path)) << f.path;
        EXPECT_EQ(source.find("#include"), std::string::npos) << f.path;
        ++count;
    }
    EXPECT_GT(count, 30);
}

}  // namespace
}  // namespace inkshade::test
