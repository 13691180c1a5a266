// roll_view (batch/view_roll.hpp).
#include "batch/view_roll.hpp"

#include <cmath>

namespace inkshade::batch {

void roll_view(CameraOptions& camera, float degrees) {
    // In the camera math's frame (+y up), as frame_camera places an orbit view.
    const glm::mat3 to_model = up_axis_rotation(camera.up_axis.value_or(UpAxis::PosY));
    const float az = glm::radians(camera.azimuth_degrees.value_or(kDefaultAzimuth));
    const float el = glm::radians(camera.elevation_degrees.value_or(kDefaultElevation));
    const glm::vec3 back(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az));  // towards the eye
    glm::vec3 up = camera.up ? glm::transpose(to_model) * *camera.up : glm::vec3(0, 1, 0);
    // frame_camera's fallback for an up vector along the view axis (safe_up).
    if (glm::length(glm::cross(back, up)) <= 1e-4f * glm::length(up))
        up = std::abs(back.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, -1);
    // Rodrigues' rotation about `back` (the camera's +z) of the up vector made perpendicular to it.
    const glm::vec3 u = glm::normalize(up - glm::dot(up, back) * back);
    const float a = glm::radians(degrees);
    camera.up = to_model * (std::cos(a) * u + std::sin(a) * glm::cross(back, u));
}

}  // namespace inkshade::batch
