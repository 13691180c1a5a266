// Fixed-function GL state for the length of a scope: each scope sets one piece of state and puts
// back what it found when it ends, so a pass leaves the context as it found it and never
// depends on what an earlier pass left behind (every pass states the depth, cull and blend
// setup it draws with).
#pragma once
#include <epoxy/gl.h>

#include <optional>

#include <glm/glm.hpp>

namespace inkshade::gpu {

// glEnable / glDisable of one capability.
class CapabilityScope {
public:
    CapabilityScope(GLenum cap, bool enabled);
    ~CapabilityScope();
    CapabilityScope(const CapabilityScope&) = delete;
    CapabilityScope& operator=(const CapabilityScope&) = delete;

private:
    GLenum cap_;
    GLboolean was_enabled_;
};

// The depth test with `func` (std::nullopt: no depth test), depth writes on or off.
class DepthScope {
public:
    explicit DepthScope(std::optional<GLenum> func, bool write = true);
    ~DepthScope();
    DepthScope(const DepthScope&) = delete;
    DepthScope& operator=(const DepthScope&) = delete;

private:
    CapabilityScope test_;
    GLint func_ = GL_LESS;
    GLboolean write_ = GL_TRUE;
};

// Culling of `face` (GL_BACK, GL_FRONT), or of none (std::nullopt).
class CullScope {
public:
    explicit CullScope(std::optional<GLenum> face);
    ~CullScope();
    CullScope(const CullScope&) = delete;
    CullScope& operator=(const CullScope&) = delete;

private:
    CapabilityScope cull_;
    GLint face_ = GL_BACK;
};

// glBlendFuncSeparate's factors.
struct BlendFunc {
    GLenum src_rgb, dst_rgb, src_alpha, dst_alpha;
};

// Blending with `func`, or none (std::nullopt).
class BlendScope {
public:
    explicit BlendScope(std::optional<BlendFunc> func);
    ~BlendScope();
    BlendScope(const BlendScope&) = delete;
    BlendScope& operator=(const BlendScope&) = delete;

private:
    CapabilityScope blend_;
    GLint factors_[4] = {GL_ONE, GL_ZERO, GL_ONE, GL_ZERO};
};

// The viewport (x, y, width, height in window pixels).
class ViewportScope {
public:
    explicit ViewportScope(const glm::ivec4& box);
    ~ViewportScope();
    ViewportScope(const ViewportScope&) = delete;
    ViewportScope& operator=(const ViewportScope&) = delete;

private:
    GLint box_[4] = {0, 0, 0, 0};
};

// The scissor test on, with the window rectangle `box` (x, y, width, height; origin bottom left).
class ScissorScope {
public:
    explicit ScissorScope(const glm::ivec4& box);
    ~ScissorScope();
    ScissorScope(const ScissorScope&) = delete;
    ScissorScope& operator=(const ScissorScope&) = delete;

private:
    CapabilityScope test_;
    GLint box_[4] = {0, 0, 0, 0};
};

// glStencilFunc / glStencilOp for both faces.
struct StencilFunc {
    GLenum func;
    GLint ref;
    GLuint mask;
    GLenum stencil_fail, depth_fail, depth_pass;
};

// The stencil test on with `func`.
class StencilScope {
public:
    explicit StencilScope(const StencilFunc& func);
    ~StencilScope();
    StencilScope(const StencilScope&) = delete;
    StencilScope& operator=(const StencilScope&) = delete;

private:
    CapabilityScope test_;
    GLint front_[6] = {}, back_[6] = {};  // func, ref, mask, fail, depth fail, depth pass
};

// Depth offset of filled polygons (glPolygonOffset's `factor` and `units`).
class PolygonOffsetScope {
public:
    PolygonOffsetScope(float factor, float units);
    ~PolygonOffsetScope();
    PolygonOffsetScope(const PolygonOffsetScope&) = delete;
    PolygonOffsetScope& operator=(const PolygonOffsetScope&) = delete;

private:
    CapabilityScope fill_;
    GLfloat factor_ = 0.0f, units_ = 0.0f;
};

}  // namespace inkshade::gpu
