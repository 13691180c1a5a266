// ImageProjection (visibility.hpp): a camera mapped onto image pixels as the renderer maps it.
#include "geometry/visibility.hpp"

#include <cmath>

namespace inkshade::geometry {

ImageProjection::ImageProjection(const Camera& camera, int width, int height)
    : camera_(camera), width_(width), height_(height) {
    // The same float matrices the renderer uploads, then evaluated in double.
    const float aspect = float(width) / float(height);
    clip_from_world_ = glm::dmat4(camera.projection(aspect)) * glm::dmat4(camera.view());
    eye_ = glm::dvec3(camera.eye);
    const glm::dvec3 f = glm::dvec3(camera.target) - eye_;
    const double len = glm::length(f);
    forward_ = len > 0.0 ? f / len : glm::dvec3(0, 0, -1);
    pixel_per_depth_ = 2.0 * std::tan(0.5 * glm::radians(double(camera.fov_degrees))) / height;
}

double ImageProjection::pixel_size(const glm::vec3& p) const {
    if (camera_.orthographic) return double(camera_.ortho_height) / height_;
    return view_depth(p) * pixel_per_depth_;
}

glm::dvec3 ImageProjection::project(const glm::vec3& p) const {
    const glm::dvec4 clip = clip_from_world_ * glm::dvec4(glm::dvec3(p), 1.0);
    const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
    // glViewport mapping, then y flipped: image row j = height − 1 − GL row.
    return {(ndc.x + 1.0) * 0.5 * width_, (1.0 - ndc.y) * 0.5 * height_, (ndc.z + 1.0) * 0.5};
}

double ImageProjection::clip_w(const glm::vec3& p) const {
    return (clip_from_world_ * glm::dvec4(glm::dvec3(p), 1.0)).w;
}

double ImageProjection::view_depth(const glm::vec3& p) const { return glm::dot(glm::dvec3(p) - eye_, forward_); }

bool ImageProjection::clipped(const glm::vec3& p) const {
    const double z = view_depth(p);
    return !(z >= double(camera_.near_plane) && z <= double(camera_.far_plane));
}

}  // namespace inkshade::geometry
