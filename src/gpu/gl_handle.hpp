// Move-only owners of OpenGL object names: each deletes its object when destroyed or assigned
// over, so a throw between creating two objects leaks neither and no class has to list its
// objects in a destructor. The context must still be current when they go, and alive:
// Renderer::Impl declares its context first, so it is destroyed after everything drawn with it.
#pragma once
#include <epoxy/gl.h>

#include <utility>

namespace inkshade::gpu {

// `Kind` names how an object of one type is made (create(args...), returning its name) and
// freed (destroy(name)).
template <class Kind>
class GlHandle {
public:
    GlHandle() = default;  // no object (name 0)
    template <class... Args>
    static GlHandle create(Args... args) {
        return GlHandle(Kind::create(args...));
    }
    ~GlHandle() { reset(); }
    GlHandle(GlHandle&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
    GlHandle& operator=(GlHandle&& other) noexcept {
        if (this != &other) {
            reset();
            id_ = std::exchange(other.id_, 0);
        }
        return *this;
    }
    GlHandle(const GlHandle&) = delete;
    GlHandle& operator=(const GlHandle&) = delete;

    GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    // Deletes the object now (no-op without one).
    void reset() {
        if (id_) Kind::destroy(id_);
        id_ = 0;
    }

private:
    explicit GlHandle(GLuint id) : id_(id) {}
    GLuint id_ = 0;
};

// Object kinds: the direct-state-access constructors of GL 4.5, which make the object at once
// (glGen* only reserves a name until its first bind).
struct BufferKind {
    static GLuint create() {
        GLuint id = 0;
        glCreateBuffers(1, &id);
        return id;
    }
    static void destroy(GLuint id) { glDeleteBuffers(1, &id); }
};

struct VertexArrayKind {
    static GLuint create() {
        GLuint id = 0;
        glCreateVertexArrays(1, &id);
        return id;
    }
    static void destroy(GLuint id) { glDeleteVertexArrays(1, &id); }
};

struct TextureKind {
    static GLuint create(GLenum target) {
        GLuint id = 0;
        glCreateTextures(target, 1, &id);
        return id;
    }
    static void destroy(GLuint id) { glDeleteTextures(1, &id); }
};

// A view of all levels of a 2D texture's immutable storage in another format of its class
// (GL_SRGB8_ALPHA8 seen as GL_RGBA8): glTextureView wants a name from glGenTextures that was
// never bound, not one glCreateTextures already made.
struct TextureViewKind {
    static GLuint create(GLuint original, GLenum internal_format, GLuint levels) {
        GLuint id = 0;
        glGenTextures(1, &id);
        glTextureView(id, GL_TEXTURE_2D, original, internal_format, 0, levels, 0, 1);
        return id;
    }
    static void destroy(GLuint id) { glDeleteTextures(1, &id); }
};

struct RenderbufferKind {
    static GLuint create() {
        GLuint id = 0;
        glCreateRenderbuffers(1, &id);
        return id;
    }
    static void destroy(GLuint id) { glDeleteRenderbuffers(1, &id); }
};

struct FramebufferKind {
    static GLuint create() {
        GLuint id = 0;
        glCreateFramebuffers(1, &id);
        return id;
    }
    static void destroy(GLuint id) { glDeleteFramebuffers(1, &id); }
};

struct QueryKind {
    static GLuint create(GLenum target) {
        GLuint id = 0;
        glCreateQueries(target, 1, &id);
        return id;
    }
    static void destroy(GLuint id) { glDeleteQueries(1, &id); }
};

struct ShaderKind {
    static GLuint create(GLenum type) { return glCreateShader(type); }
    static void destroy(GLuint id) { glDeleteShader(id); }
};

struct ProgramKind {
    static GLuint create() { return glCreateProgram(); }
    static void destroy(GLuint id) { glDeleteProgram(id); }
};

using GlBuffer = GlHandle<BufferKind>;
using GlVertexArray = GlHandle<VertexArrayKind>;
using GlTexture = GlHandle<TextureKind>;          // create(GL_TEXTURE_2D, ...)
using GlTextureView = GlHandle<TextureViewKind>;  // create(original, GL_RGBA8, levels)
using GlRenderbuffer = GlHandle<RenderbufferKind>;
using GlFramebuffer = GlHandle<FramebufferKind>;
using GlQuery = GlHandle<QueryKind>;    // create(GL_TIMESTAMP, ...)
using GlShader = GlHandle<ShaderKind>;  // create(GL_VERTEX_SHADER, ...)
using GlProgram = GlHandle<ProgramKind>;

}  // namespace inkshade::gpu
