#include "inkshade/orbit_controls.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace inkshade {

void orbit(Camera& camera, float yaw_degrees, float pitch_degrees, UpAxis up_axis) {
    // In the camera math's frame (+y up), then back to the model's.
    const glm::mat3 to_model = up_axis_rotation(up_axis);
    glm::vec3 offset = glm::transpose(to_model) * (camera.eye - camera.target);
    const float dist = glm::length(offset);
    if (!(dist > 0.0f)) return;
    // Pitch as an elevation change, clamped to +-89 degrees so up never aligns with the view.
    float elevation = glm::degrees(std::asin(std::clamp(offset.y / dist, -1.0f, 1.0f)));
    float new_elevation = std::clamp(elevation + pitch_degrees, -89.0f, 89.0f);
    float azimuth = glm::degrees(std::atan2(offset.x, offset.z)) + yaw_degrees;
    float az = glm::radians(azimuth), el = glm::radians(new_elevation);
    camera.eye = camera.target +
                 to_model * (dist * glm::vec3(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)));
    camera.up = to_model * glm::vec3(0.0f, 1.0f, 0.0f);
}

void pan(Camera& camera, float dx_pixels, float dy_pixels, int viewport_height) {
    const glm::vec3 forward = camera.target - camera.eye;
    const float dist = glm::length(forward);
    if (!(dist > 0.0f) || viewport_height <= 0) return;
    const glm::vec3 f = forward / dist;
    const glm::vec3 right = glm::normalize(glm::cross(f, camera.up));
    const glm::vec3 up = glm::cross(right, f);
    // World units per pixel at the target's depth.
    const float view_height =
        camera.orthographic ? camera.ortho_height : 2.0f * dist * std::tan(0.5f * glm::radians(camera.fov_degrees));
    const float scale = view_height / float(viewport_height);
    const glm::vec3 move = (-dx_pixels * right + dy_pixels * up) * scale;
    camera.eye += move;
    camera.target += move;
}

void zoom(Camera& camera, float factor, const BoundingBox& box) {
    if (!(factor > 0.0f) || !std::isfinite(factor)) return;
    const glm::vec3 offset = camera.eye - camera.target;
    const float dist = glm::length(offset);
    const float min_dist = 1e-3f * std::max(box.diagonal(), 1e-6f);
    const float new_dist = std::max(dist * factor, min_dist);
    if (dist > 0.0f) camera.eye = camera.target + offset * (new_dist / dist);
    camera.ortho_height = std::max(camera.ortho_height * factor, min_dist);
    fit_clip_planes(camera, box);
}

}  // namespace inkshade
