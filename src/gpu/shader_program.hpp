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
    // Paths are relative to shaders/ (embedded; `#include "file"` lines expanded, see
    // shader_source.hpp). `defines` is inserted after #version in both stages,
    // `fragment_defines` after it in the fragment stage only.
    // Throws RuntimeError naming the file and the compiler's first error line.
    ShaderProgram(const std::string& vertex_path, const std::string& fragment_path, const std::string& defines = "",
                  const std::string& fragment_defines = "");

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
