// Orbit, pan and zoom of a Camera around its target: the mouse controls of `inkshade view`, as
// plain camera math (no window) so they are testable and reusable by other front ends.
#pragma once
#include "inkshade/camera.hpp"

namespace inkshade {

// Rotates the eye about the target: `yaw_degrees` about the model's up axis (+y unless given),
// `pitch_degrees` about the camera's right axis, the pitch clamped so the view never flips over
// the pole.
void orbit(Camera& camera, float yaw_degrees, float pitch_degrees, UpAxis up_axis = UpAxis::PosY);

// Moves eye and target together by (dx, dy) pixels of a viewport `viewport_height` pixels high,
// so the point under the cursor at the target's depth follows the cursor.
void pan(Camera& camera, float dx_pixels, float dy_pixels, int viewport_height);

// Moves the eye towards the target by `factor` (< 1 zooms in), and scales the orthographic
// height likewise; the distance stays above a small fraction of the model size.
void zoom(Camera& camera, float factor, const BoundingBox& box);

}  // namespace inkshade
