#include "render/gbuffer.hpp"

#include "inkshade/error.hpp"

namespace inkshade::render {

namespace {

GLuint make_texture(int width, int height, GLenum format) {
    GLuint t = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &t);
    glTextureStorage2D(t, 1, format, width, height);
    glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return t;
}

}  // namespace

GBuffer::GBuffer(int width, int height) : width_(width), height_(height) {
    surface_ = make_texture(width, height, GL_RGBA32F);
    face_normal_ = make_texture(width, height, GL_RGBA8_SNORM);
    glCreateRenderbuffers(1, &depth_);
    glNamedRenderbufferStorage(depth_, GL_DEPTH_COMPONENT32F, width, height);
    glCreateFramebuffers(1, &fbo_);
    glNamedFramebufferTexture(fbo_, GL_COLOR_ATTACHMENT0, surface_, 0);
    glNamedFramebufferTexture(fbo_, GL_COLOR_ATTACHMENT1, face_normal_, 0);
    glNamedFramebufferRenderbuffer(fbo_, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
    if (glCheckNamedFramebufferStatus(fbo_, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw RuntimeError("cannot create the line passes' G-buffer (out of memory?)");
}

GBuffer::~GBuffer() {
    glDeleteFramebuffers(1, &fbo_);
    glDeleteTextures(1, &surface_);
    glDeleteTextures(1, &face_normal_);
    glDeleteRenderbuffers(1, &depth_);
}

void GBuffer::draw(const GpuMesh& mesh, const Camera& camera, bool face_normals, bool cull_back_faces) {
    auto& program = programs_[face_normals ? 1 : 0];
    if (!program)
        program = std::make_unique<gpu::ShaderProgram>(
            "lines/gbuffer.vert", "lines/gbuffer.frag",
            std::string("#define INKSHADE_GBUFFER_FACE_NORMALS ") + (face_normals ? "1" : "0") + "\n");
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glViewport(0, 0, width_, height_);
    const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(fbo_, face_normals ? 2 : 1, buffers);
    const GLfloat zero[4] = {0, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 0, zero);
    if (face_normals) glClearBufferfv(GL_COLOR, 1, zero);
    const GLfloat one = 1.0f;
    glClearBufferfv(GL_DEPTH, 0, &one);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);
    if (cull_back_faces) {
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
    } else {
        glDisable(GL_CULL_FACE);
    }

    gpu::ShaderProgram& p = *program;
    p.use();
    const float aspect = float(width_) / float(height_);
    p.set("u_view_proj", camera.projection(aspect) * camera.view());
    p.set("u_view", camera.view());
    p.set("u_eye", camera.eye);
    p.set("u_view_dir", glm::normalize(camera.target - camera.eye));
    p.set("u_orthographic", camera.orthographic ? 1 : 0);
    mesh.draw();
    glDisable(GL_CULL_FACE);
}

void GBuffer::bind_textures(GLuint surface_unit, GLuint face_normal_unit) const {
    glBindTextureUnit(surface_unit, surface_);
    glBindTextureUnit(face_normal_unit, face_normal_);
}

}  // namespace inkshade::render
