// Where a point of a line lies in depth, from near (0) to far (1) across the model: what the
// depth modifiers of a stroke (thickness and colour by depth; Freestyle's "Distance from
// Camera" modifiers) read. The range is the model's bounding sphere seen along the view
// direction, so every line type of a view, and a turning model's views, share one scale.
#pragma once
#include "inkshade/camera.hpp"

namespace inkshade::geometry {

struct ViewDepthRange {
    bool orthographic = false;
    float near_plane = 0.1f, far_plane = 100.0f;  // the camera's, to undo the window depth
    double nearest = 0.0, farthest = 1.0;         // view depths (along the view direction)

    // The range of a sphere (centre, radius) seen by `camera`.
    static ViewDepthRange of_sphere(const Camera& camera, glm::vec3 centre, float radius);

    // The view depth of a window depth in [0, 1] (the GL depth buffer's: non-linear in
    // perspective, linear in orthographic projection).
    double view_depth(float window_depth) const;
    // 0 at `nearest`, 1 at `farthest`, clamped.
    float fraction(float window_depth) const;
};

}  // namespace inkshade::geometry
