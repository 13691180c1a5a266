// Tight framing, the geometry behind frame_camera: where a camera of fixed orientation goes so
// that the projection of a set of points fills a given part of the image. The points are given
// in the view's axes, relative to an origin: x right, y up, z along the view (away from the eye).
#pragma once
#include <span>
#include <utility>

#include <glm/glm.hpp>

namespace inkshade::framing {

// Perspective. `reach`: the tangents of the half fields of view (x, y) the points may fill.
// The eye (in the points' axes) from which their projection reaches `reach` on both sides of
// the limiting image axis and is centred on the other, at least `clearance` before the nearest
// point. Exact: a point projects to (x - e) / (z - ez), and the eye is the solution of the
// linear constraints |x - e| <= reach (z - ez) with the greatest ez.
glm::vec3 centred_eye(std::span<const glm::vec3> points, glm::vec2 reach, float clearance);

// Perspective with the eye on the z axis (the view axis through the origin): the distance behind
// the origin at which the farthest point meets `reach`, at least `clearance` before the nearest.
float distance_on_axis(std::span<const glm::vec3> points, glm::vec2 reach, float clearance);

// Orthographic: the least and greatest x and y of the points.
std::pair<glm::vec2, glm::vec2> extent(std::span<const glm::vec3> points);

}  // namespace inkshade::framing
