// A linked GLSL program built from embedded shader files, with cached uniform locations.
#pragma once
#include <epoxy/gl.h>

#include <string>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>

#include "gpu/gl_handle.hpp"

namespace inkshade::gpu {

class ShaderProgram {
public:
    // Paths are relative to shaders/ (embedded). `defines` is inserted after #version.
    // `fragment_defines` go after `defines` in the fragment shader only, and
    // `fragment_epilogue` (GLSL text) is appended to it: with `#define main NAME` there, the
    // epilogue wraps the shader's main (how the line passes add render targets and rim lines
    // to every shading model, src/render/surface_lines.hpp).
    // Throws RuntimeError naming the file and the compiler's first error line.
    ShaderProgram(const std::string& vertex_path, const std::string& fragment_path,
                  const std::string& defines = "", const std::string& fragment_defines = "",
                  const std::string& fragment_epilogue = "");

    void use() const { glUseProgram(program_.id()); }
    GLuint id() const { return program_.id(); }

    // Setters ignore uniforms the compiler optimised away (location -1).
    void set(const std::string& name, float v);
    void set(const std::string& name, int v);
    void set(const std::string& name, const glm::vec2& v);
    void set(const std::string& name, const glm::ivec2& v);
    void set(const std::string& name, const glm::vec3& v);
    void set(const std::string& name, const glm::vec4& v);
    void set(const std::string& name, const glm::mat3& v);
    void set(const std::string& name, const glm::mat4& v);
    void set_array(const std::string& name, const std::vector<float>& v);
    GLint location(const std::string& name);

private:
    GlProgram program_;
    std::unordered_map<std::string, GLint> locations_;
};

}  // namespace inkshade::gpu
