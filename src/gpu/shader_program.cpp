#include "gpu/shader_program.hpp"

#include <glm/gtc/type_ptr.hpp>

#include "gpu/shader_source.hpp"
#include "inkshade/error.hpp"

namespace inkshade::gpu {

namespace {

std::string first_line(const std::string& log) {
    std::string line = log.substr(0, log.find('\n'));
    return line.empty() ? "unknown error" : line;
}

GlShader compile(GLenum type, const std::string& path, const std::string& defines) {
    std::string src = shader_source(path);
    // Defines right after the #version line, so they precede everything else.
    size_t eol = src.find('\n');
    if (src.rfind("#version", 0) == 0 && eol != std::string::npos) src.insert(eol + 1, defines);
    GlShader shader = GlShader::create(type);
    const char* text = src.c_str();
    glShaderSource(shader.id(), 1, &text, nullptr);
    glCompileShader(shader.id());
    GLint ok = 0;
    glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
    if (!ok) {
        GLint len = 0;
        glGetShaderiv(shader.id(), GL_INFO_LOG_LENGTH, &len);
        std::string log(size_t(std::max(len, 1)), '\0');
        glGetShaderInfoLog(shader.id(), len, nullptr, log.data());
        throw RuntimeError("shader " + path + " does not compile: " + first_line(log));
    }
    return shader;
}

}  // namespace

ShaderProgram::ShaderProgram(const std::string& vertex_path, const std::string& fragment_path,
                             const std::string& defines, const std::string& fragment_defines) {
    // The shaders are deleted when they go out of scope, after the link (GL frees them with the
    // program they are attached to).
    const GlShader vs = compile(GL_VERTEX_SHADER, vertex_path, defines);
    const GlShader fs = compile(GL_FRAGMENT_SHADER, fragment_path, defines + fragment_defines);
    program_ = GlProgram::create();
    const GLuint id = program_.id();
    glAttachShader(id, vs.id());
    glAttachShader(id, fs.id());
    glLinkProgram(id);
    GLint ok = 0;
    glGetProgramiv(id, GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint len = 0;
        glGetProgramiv(id, GL_INFO_LOG_LENGTH, &len);
        std::string log(size_t(std::max(len, 1)), '\0');
        glGetProgramInfoLog(id, len, nullptr, log.data());
        throw RuntimeError("program " + vertex_path + " + " + fragment_path + " does not link: " + first_line(log));
    }
}

GLint ShaderProgram::location(const std::string& name) {
    auto it = locations_.find(name);
    if (it != locations_.end()) return it->second;
    GLint loc = glGetUniformLocation(program_.id(), name.c_str());
    locations_.emplace(name, loc);
    return loc;
}

void ShaderProgram::set(const std::string& name, float v) { glProgramUniform1f(id(), location(name), v); }
void ShaderProgram::set(const std::string& name, int v) { glProgramUniform1i(id(), location(name), v); }
void ShaderProgram::set(const std::string& name, const glm::vec2& v) {
    glProgramUniform2fv(id(), location(name), 1, glm::value_ptr(v));
}
void ShaderProgram::set(const std::string& name, const glm::ivec2& v) {
    glProgramUniform2i(id(), location(name), v.x, v.y);
}
void ShaderProgram::set(const std::string& name, const glm::vec3& v) {
    glProgramUniform3fv(id(), location(name), 1, glm::value_ptr(v));
}
void ShaderProgram::set(const std::string& name, const glm::vec4& v) {
    glProgramUniform4fv(id(), location(name), 1, glm::value_ptr(v));
}
void ShaderProgram::set(const std::string& name, const glm::mat3& v) {
    glProgramUniformMatrix3fv(id(), location(name), 1, GL_FALSE, glm::value_ptr(v));
}
void ShaderProgram::set(const std::string& name, const glm::mat4& v) {
    glProgramUniformMatrix4fv(id(), location(name), 1, GL_FALSE, glm::value_ptr(v));
}
void ShaderProgram::set_array(const std::string& name, const std::vector<float>& v) {
    glProgramUniform1fv(id(), location(name), GLsizei(v.size()), v.data());
}

}  // namespace inkshade::gpu
