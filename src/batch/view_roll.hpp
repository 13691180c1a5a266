// Roll of a batch view (random:N:SEED:roll=DEG): the camera turned about its view axis, by
// giving auto-framing the turned up vector, so that framing fits the turned image.
#pragma once
#include "inkshade/camera.hpp"

namespace inkshade::batch {

// Sets `camera.up` for an orbit view (azimuth and elevation, their defaults where unset; no
// eye) to the up vector frame_camera would use, turned by `degrees` about the view axis:
// counter-clockwise as seen from behind the camera, so the image turns clockwise. In the
// model's coordinates, whatever camera.up_axis is.
void roll_view(CameraOptions& camera, float degrees);

}  // namespace inkshade::batch
