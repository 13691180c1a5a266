// gpu/gl_state.hpp: every scope sets its state for its lifetime and puts back what it found,
// whatever that was.
#include "gpu/gl_state.hpp"
#include "render/render_fixture.hpp"

namespace inkshade::test {
namespace {

GLint get_int(GLenum name) {
    GLint v = 0;
    glGetIntegerv(name, &v);
    return v;
}

glm::ivec4 get_box(GLenum name) {
    GLint v[4] = {0, 0, 0, 0};
    glGetIntegerv(name, v);
    return {v[0], v[1], v[2], v[3]};
}

TEST(GlState, CapabilityScopeRestoresEitherValue) {
    shared_renderer();
    for (bool before : {false, true}) {
        if (before)
            glEnable(GL_DITHER);
        else
            glDisable(GL_DITHER);
        for (bool inside : {false, true}) {
            {
                const gpu::CapabilityScope s(GL_DITHER, inside);
                EXPECT_EQ(bool(glIsEnabled(GL_DITHER)), inside);
            }
            EXPECT_EQ(bool(glIsEnabled(GL_DITHER)), before);
        }
    }
    glEnable(GL_DITHER);  // GL's default
}

TEST(GlState, DepthCullAndBlendScopesRestoreTheirState) {
    shared_renderer();
    glDisable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT_AND_BACK);
    glBlendFuncSeparate(GL_ONE, GL_ZERO, GL_ZERO, GL_ONE);
    {
        const gpu::DepthScope depth(GL_LEQUAL, /*write=*/false);
        const gpu::CullScope cull(std::nullopt);
        const gpu::BlendScope blend(
            gpu::BlendFunc{GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA});
        EXPECT_TRUE(glIsEnabled(GL_DEPTH_TEST));
        EXPECT_EQ(get_int(GL_DEPTH_FUNC), GL_LEQUAL);
        GLboolean write = GL_TRUE;
        glGetBooleanv(GL_DEPTH_WRITEMASK, &write);
        EXPECT_EQ(write, GL_FALSE);
        EXPECT_FALSE(glIsEnabled(GL_CULL_FACE));
        EXPECT_TRUE(glIsEnabled(GL_BLEND));
        EXPECT_EQ(get_int(GL_BLEND_SRC_RGB), GL_SRC_ALPHA);
        EXPECT_EQ(get_int(GL_BLEND_DST_ALPHA), GL_ONE_MINUS_SRC_ALPHA);
    }
    EXPECT_FALSE(glIsEnabled(GL_DEPTH_TEST));
    EXPECT_EQ(get_int(GL_DEPTH_FUNC), GL_GREATER);
    GLboolean write = GL_FALSE;
    glGetBooleanv(GL_DEPTH_WRITEMASK, &write);
    EXPECT_EQ(write, GL_TRUE);
    EXPECT_TRUE(glIsEnabled(GL_CULL_FACE));
    EXPECT_EQ(get_int(GL_CULL_FACE_MODE), GL_FRONT_AND_BACK);
    EXPECT_FALSE(glIsEnabled(GL_BLEND));
    EXPECT_EQ(get_int(GL_BLEND_SRC_RGB), GL_ONE);
    EXPECT_EQ(get_int(GL_BLEND_DST_RGB), GL_ZERO);
    EXPECT_EQ(get_int(GL_BLEND_SRC_ALPHA), GL_ZERO);
    EXPECT_EQ(get_int(GL_BLEND_DST_ALPHA), GL_ONE);
    // Back to GL's defaults for the other tests.
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glBlendFunc(GL_ONE, GL_ZERO);
}

TEST(GlState, ViewportScissorStencilAndOffsetScopesRestoreTheirState) {
    shared_renderer();
    glViewport(1, 2, 30, 40);
    glScissor(3, 4, 5, 6);
    {
        const gpu::ViewportScope viewport({0, 0, 8, 9});
        const gpu::ScissorScope scissor({7, 8, 9, 10});
        const gpu::StencilScope stencil({GL_EQUAL, 1, 0x0f, GL_KEEP, GL_ZERO, GL_INCR});
        const gpu::PolygonOffsetScope offset(2.0f, 4.0f);
        EXPECT_EQ(get_box(GL_VIEWPORT), glm::ivec4(0, 0, 8, 9));
        EXPECT_TRUE(glIsEnabled(GL_SCISSOR_TEST));
        EXPECT_EQ(get_box(GL_SCISSOR_BOX), glm::ivec4(7, 8, 9, 10));
        EXPECT_TRUE(glIsEnabled(GL_STENCIL_TEST));
        EXPECT_EQ(get_int(GL_STENCIL_FUNC), GL_EQUAL);
        EXPECT_EQ(get_int(GL_STENCIL_BACK_PASS_DEPTH_PASS), GL_INCR);
        EXPECT_TRUE(glIsEnabled(GL_POLYGON_OFFSET_FILL));
    }
    EXPECT_EQ(get_box(GL_VIEWPORT), glm::ivec4(1, 2, 30, 40));
    EXPECT_FALSE(glIsEnabled(GL_SCISSOR_TEST));
    EXPECT_EQ(get_box(GL_SCISSOR_BOX), glm::ivec4(3, 4, 5, 6));
    EXPECT_FALSE(glIsEnabled(GL_STENCIL_TEST));
    EXPECT_EQ(get_int(GL_STENCIL_FUNC), GL_ALWAYS);
    EXPECT_EQ(get_int(GL_STENCIL_BACK_PASS_DEPTH_PASS), GL_KEEP);
    EXPECT_FALSE(glIsEnabled(GL_POLYGON_OFFSET_FILL));
    GLfloat factor = -1.0f;
    glGetFloatv(GL_POLYGON_OFFSET_FACTOR, &factor);
    EXPECT_EQ(factor, 0.0f);
}

}  // namespace
}  // namespace inkshade::test
