// gpu/shader_source.hpp: the embedded shaders hold their sources with every `#include` already
// expanded (cmake/embed_files.cmake; the expansion itself is tested by
// tests/embed/embed_files_test.py), and every shader stage compiles as embedded.
#include <gtest/gtest.h>

#include <algorithm>
#include <regex>
#include <string>

#include "gpu/embedded_shaders.hpp"
#include "gpu/gl_handle.hpp"
#include "gpu/shader_source.hpp"
#include "inkshade/error.hpp"
#include "render/render_fixture.hpp"

namespace inkshade::test {
namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

TEST(ShaderSource, EveryEmbeddedShaderIsExpandedAtBuildTime) {
    const std::regex include_line(R"(^[ \t]*#[ \t]*include)", std::regex::multiline);
    int count = 0;
    for (const EmbeddedFile& f : gpu::embedded_shaders()) {
        std::string source;
        ASSERT_NO_THROW(source = gpu::shader_source(f.path)) << f.path;
        EXPECT_EQ(source, f.contents) << f.path;  // looked up, not rewritten
        EXPECT_FALSE(std::regex_search(source, include_line)) << f.path;
        ++count;
    }
    EXPECT_GT(count, 30);
}

TEST(ShaderSource, UnknownShaderIsAnError) {
    try {
        gpu::shader_source("shading/nope.frag");
        FAIL();
    } catch (const RuntimeError& e) {
        EXPECT_NE(std::string(e.what()).find("shading/nope.frag is not embedded"), std::string::npos) << e.what();
    }
}

// Each vertex and fragment stage compiles on its own, without the #defines of a variant (the
// variants are compiled by the renderer tests).
TEST(ShaderSource, EveryEmbeddedStageCompiles) {
    shared_renderer();  // a current context
    int count = 0;
    for (const EmbeddedFile& f : gpu::embedded_shaders()) {
        const std::string path = f.path;
        GLenum type = 0;
        if (ends_with(path, ".vert"))
            type = GL_VERTEX_SHADER;
        else if (ends_with(path, ".frag"))
            type = GL_FRAGMENT_SHADER;
        else
            continue;
        const auto shader = gpu::GlShader::create(type);
        const std::string source = gpu::shader_source(path);
        const char* text = source.c_str();
        glShaderSource(shader.id(), 1, &text, nullptr);
        glCompileShader(shader.id());
        GLint ok = 0;
        glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
        std::string log;
        if (!ok) {
            GLint len = 0;
            glGetShaderiv(shader.id(), GL_INFO_LOG_LENGTH, &len);
            log.assign(size_t(std::max(len, 1)), '\0');
            glGetShaderInfoLog(shader.id(), len, nullptr, log.data());
        }
        EXPECT_TRUE(ok) << path << ": " << log;
        ++count;
    }
    EXPECT_GT(count, 25);
}

}  // namespace
}  // namespace inkshade::test
