// Back faces lose depth ties to front faces. Open and non-manifold meshes are drawn two-sided
// (the inside of a cup, a single-sided plane seen from below), but a scan's folds (tiny
// reversed triangles lying on the surface) must not show as dark specks where a front-facing
// surface is right behind them: front faces are drawn first, then back faces with every vertex
// moved away from the eye along its view ray by kBackFaceTolerancePx pixel footprints (plus a
// slope-scaled polygon offset of one pixel), so a back face shows only where no front face lies
// within that tolerance behind it (docs/shading.md).
#pragma once
#include <functional>
#include <optional>

#include "gpu/gl_state.hpp"
#include "gpu/shader_program.hpp"
#include "render/frame.hpp"

namespace inkshade::render {

// The tolerance along the view ray in pixel footprints (the world size of one pixel at that
// depth). Together with the polygon offset of one pixel of depth slope it covers any back face
// within one footprint of a front face along the surface normal, whatever the viewing angle
// θ (1 + tan θ >= 1 / cos θ).
constexpr float kBackFaceTolerancePx = 1.0f;

// The clip-space z offset that moves a point kBackFaceTolerancePx footprints farther along its
// view ray: a scaling about the eye by 1 + ε (perspective: ε = tolerance · 2 tan(fov/2) / H)
// or a shift by tolerance · ortho_height / H (orthographic), which leaves x, y and w unchanged
// and adds a constant to clip z. `height`: the image height in pixels.
float back_face_depth_push(const Camera& camera, float aspect, int height);

// With `program` bound (its vertex stage includes common/back_face_push.glsl): `draw` once for
// the front faces and, unless the frame culls back faces, once more for the back faces pushed
// back. Cull and polygon-offset state are as before afterwards.
void draw_front_then_back(const Frame& frame, gpu::ShaderProgram& program, const std::function<void()>& draw);
// The same, `draw` told whether it draws the back faces (a material may have none: glTF's
// single-sided materials).
void draw_front_then_back(const Frame& frame, gpu::ShaderProgram& program, const std::function<void(bool back)>& draw);

// A draw of back faces only (the hull and outline shells) that is compared against the depth
// the shading pass wrote: pushed as that pass pushed its back faces, while it lives.
class BackFacePushScope {
public:
    BackFacePushScope(const Frame& frame, gpu::ShaderProgram& program);
    BackFacePushScope(const BackFacePushScope&) = delete;
    BackFacePushScope& operator=(const BackFacePushScope&) = delete;

private:
    std::optional<gpu::PolygonOffsetScope> offset_;
};

}  // namespace inkshade::render
