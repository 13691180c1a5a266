// gpu::GlHandle: each handle owns one GL object, deletes it when destroyed or assigned over,
// hands it on when moved and deletes nothing when empty or moved from.
#include "gpu/gl_handle.hpp"
#include "render/render_fixture.hpp"

namespace inkshade::test {
namespace {

TEST(GlHandle, EveryKindDeletesItsObjectOnDestruction) {
    shared_renderer();  // a current context
    GLuint buffer = 0, vao = 0, texture = 0, renderbuffer = 0, framebuffer = 0, query = 0, shader = 0, program = 0;
    {
        const auto b = gpu::GlBuffer::create();
        const auto v = gpu::GlVertexArray::create();
        const auto t = gpu::GlTexture::create(GL_TEXTURE_2D);
        const auto r = gpu::GlRenderbuffer::create();
        const auto f = gpu::GlFramebuffer::create();
        const auto q = gpu::GlQuery::create(GL_TIMESTAMP);
        const auto s = gpu::GlShader::create(GL_VERTEX_SHADER);
        const auto p = gpu::GlProgram::create();
        buffer = b.id(), vao = v.id(), texture = t.id(), renderbuffer = r.id(), framebuffer = f.id();
        query = q.id(), shader = s.id(), program = p.id();
        EXPECT_TRUE(glIsBuffer(buffer));
        EXPECT_TRUE(glIsVertexArray(vao));
        EXPECT_TRUE(glIsTexture(texture));
        EXPECT_TRUE(glIsRenderbuffer(renderbuffer));
        EXPECT_TRUE(glIsFramebuffer(framebuffer));
        EXPECT_TRUE(glIsQuery(query));
        EXPECT_TRUE(glIsShader(shader));
        EXPECT_TRUE(glIsProgram(program));
    }
    EXPECT_FALSE(glIsBuffer(buffer));
    EXPECT_FALSE(glIsVertexArray(vao));
    EXPECT_FALSE(glIsTexture(texture));
    EXPECT_FALSE(glIsRenderbuffer(renderbuffer));
    EXPECT_FALSE(glIsFramebuffer(framebuffer));
    EXPECT_FALSE(glIsQuery(query));
    EXPECT_FALSE(glIsShader(shader));
    EXPECT_FALSE(glIsProgram(program));
}

TEST(GlHandle, MoveHandsTheObjectOnAndAssignmentDeletesTheOldOne) {
    shared_renderer();
    gpu::GlBuffer a = gpu::GlBuffer::create();
    const GLuint first = a.id();
    gpu::GlBuffer b = std::move(a);
    EXPECT_EQ(b.id(), first);
    EXPECT_EQ(a.id(), 0u);  // NOLINT(bugprone-use-after-move): moved from on purpose
    EXPECT_FALSE(bool(a));
    EXPECT_TRUE(glIsBuffer(first));

    b = gpu::GlBuffer::create();
    EXPECT_FALSE(glIsBuffer(first));  // assigned over
    const GLuint second = b.id();
    EXPECT_TRUE(glIsBuffer(second));
    b.reset();
    EXPECT_FALSE(glIsBuffer(second));
    EXPECT_FALSE(bool(b));
    const gpu::GlBuffer empty;  // owns nothing, deletes nothing
    EXPECT_EQ(empty.id(), 0u);
}

}  // namespace
}  // namespace inkshade::test
