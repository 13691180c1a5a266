#include "gpu/gl_state.hpp"

namespace inkshade::gpu {

CapabilityScope::CapabilityScope(GLenum cap, bool enabled) : cap_(cap), was_enabled_(glIsEnabled(cap)) {
    if (enabled)
        glEnable(cap);
    else
        glDisable(cap);
}

CapabilityScope::~CapabilityScope() {
    if (was_enabled_)
        glEnable(cap_);
    else
        glDisable(cap_);
}

DepthScope::DepthScope(std::optional<GLenum> func, bool write) : test_(GL_DEPTH_TEST, func.has_value()) {
    glGetIntegerv(GL_DEPTH_FUNC, &func_);
    glGetBooleanv(GL_DEPTH_WRITEMASK, &write_);
    if (func) glDepthFunc(*func);
    glDepthMask(write ? GL_TRUE : GL_FALSE);
}

DepthScope::~DepthScope() {
    glDepthFunc(GLenum(func_));
    glDepthMask(write_);
}

CullScope::CullScope(std::optional<GLenum> face) : cull_(GL_CULL_FACE, face.has_value()) {
    glGetIntegerv(GL_CULL_FACE_MODE, &face_);
    if (face) glCullFace(*face);
}

CullScope::~CullScope() { glCullFace(GLenum(face_)); }

BlendScope::BlendScope(std::optional<BlendFunc> func) : blend_(GL_BLEND, func.has_value()) {
    glGetIntegerv(GL_BLEND_SRC_RGB, &factors_[0]);
    glGetIntegerv(GL_BLEND_DST_RGB, &factors_[1]);
    glGetIntegerv(GL_BLEND_SRC_ALPHA, &factors_[2]);
    glGetIntegerv(GL_BLEND_DST_ALPHA, &factors_[3]);
    if (func) glBlendFuncSeparate(func->src_rgb, func->dst_rgb, func->src_alpha, func->dst_alpha);
}

BlendScope::~BlendScope() {
    glBlendFuncSeparate(GLenum(factors_[0]), GLenum(factors_[1]), GLenum(factors_[2]), GLenum(factors_[3]));
}

ViewportScope::ViewportScope(const glm::ivec4& box) {
    glGetIntegerv(GL_VIEWPORT, box_);
    glViewport(box.x, box.y, box.z, box.w);
}

ViewportScope::~ViewportScope() { glViewport(box_[0], box_[1], box_[2], box_[3]); }

ScissorScope::ScissorScope(const glm::ivec4& box) : test_(GL_SCISSOR_TEST, true) {
    glGetIntegerv(GL_SCISSOR_BOX, box_);
    glScissor(box.x, box.y, box.z, box.w);
}

ScissorScope::~ScissorScope() { glScissor(box_[0], box_[1], box_[2], box_[3]); }

namespace {

void get_stencil(GLint out[6], bool back) {
    glGetIntegerv(back ? GL_STENCIL_BACK_FUNC : GL_STENCIL_FUNC, &out[0]);
    glGetIntegerv(back ? GL_STENCIL_BACK_REF : GL_STENCIL_REF, &out[1]);
    glGetIntegerv(back ? GL_STENCIL_BACK_VALUE_MASK : GL_STENCIL_VALUE_MASK, &out[2]);
    glGetIntegerv(back ? GL_STENCIL_BACK_FAIL : GL_STENCIL_FAIL, &out[3]);
    glGetIntegerv(back ? GL_STENCIL_BACK_PASS_DEPTH_FAIL : GL_STENCIL_PASS_DEPTH_FAIL, &out[4]);
    glGetIntegerv(back ? GL_STENCIL_BACK_PASS_DEPTH_PASS : GL_STENCIL_PASS_DEPTH_PASS, &out[5]);
}

void set_stencil(GLenum face, const GLint s[6]) {
    glStencilFuncSeparate(face, GLenum(s[0]), s[1], GLuint(s[2]));
    glStencilOpSeparate(face, GLenum(s[3]), GLenum(s[4]), GLenum(s[5]));
}

}  // namespace

StencilScope::StencilScope(const StencilFunc& func) : test_(GL_STENCIL_TEST, true) {
    get_stencil(front_, false);
    get_stencil(back_, true);
    glStencilFunc(func.func, func.ref, func.mask);
    glStencilOp(func.stencil_fail, func.depth_fail, func.depth_pass);
}

StencilScope::~StencilScope() {
    set_stencil(GL_FRONT, front_);
    set_stencil(GL_BACK, back_);
}

PolygonOffsetScope::PolygonOffsetScope(float factor, float units) : fill_(GL_POLYGON_OFFSET_FILL, true) {
    glGetFloatv(GL_POLYGON_OFFSET_FACTOR, &factor_);
    glGetFloatv(GL_POLYGON_OFFSET_UNITS, &units_);
    glPolygonOffset(factor, units);
}

PolygonOffsetScope::~PolygonOffsetScope() { glPolygonOffset(factor_, units_); }

}  // namespace inkshade::gpu
