#include "inkshade/camera.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "core/tight_framing.hpp"

namespace inkshade {

glm::mat4 Camera::view() const { return glm::lookAt(eye, target, up); }

glm::mat4 Camera::projection(float aspect) const {
    if (orthographic) {
        float h = 0.5f * ortho_height, w = h * aspect;
        return glm::ortho(-w, w, -h, h, near_plane, far_plane);
    }
    return glm::perspective(glm::radians(fov_degrees), aspect, near_plane, far_plane);
}

namespace {

glm::vec3 orbit_direction(float azimuth_deg, float elevation_deg) {
    float az = glm::radians(azimuth_deg), el = glm::radians(elevation_deg);
    return {std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)};
}

// An up vector that is not parallel to the viewing direction.
glm::vec3 safe_up(const glm::vec3& forward, const glm::vec3& up) {
    if (glm::length(glm::cross(forward, up)) > 1e-4f * glm::length(up)) return up;
    return std::abs(forward.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, -1);
}

}  // namespace

namespace {
constexpr std::pair<const char*, UpAxis> kAxisNames[] = {
    {"x", UpAxis::PosX},  {"-x", UpAxis::NegX}, {"y", UpAxis::PosY},  {"-y", UpAxis::NegY}, {"z", UpAxis::PosZ},
    {"-z", UpAxis::NegZ}, {"+x", UpAxis::PosX}, {"+y", UpAxis::PosY}, {"+z", UpAxis::PosZ}};
}  // namespace

std::optional<UpAxis> up_axis_named(std::string_view name) {
    for (const auto& [text, axis] : kAxisNames)
        if (name == text) return axis;
    return std::nullopt;
}

const char* up_axis_name(UpAxis axis) {
    for (const auto& [text, a] : kAxisNames)
        if (a == axis) return text;
    return "y";
}

glm::mat3 up_axis_rotation(UpAxis axis) {
    const glm::vec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
    // Columns: where +x, +y and +z of the camera frame go; each a right-handed rotation.
    switch (axis) {
        case UpAxis::PosX: return {-y, x, z};
        case UpAxis::NegX: return {y, -x, z};
        case UpAxis::PosY: return {x, y, z};
        case UpAxis::NegY: return {-x, -y, z};
        case UpAxis::PosZ: return {x, z, -y};
        case UpAxis::NegZ: return {x, -z, y};
    }
    return {x, y, z};
}

namespace {

// The framed points in the view's axes (x right, y up, z along the view) relative to `origin`:
// the model's points turned into the camera math's frame by `to_frame`, or the box's corners.
std::vector<glm::vec3> view_points(const BoundingBox& box, std::span<const glm::vec3> points, const glm::mat3& to_frame,
                                   const glm::vec3& origin, const glm::vec3& right, const glm::vec3& up,
                                   const glm::vec3& forward) {
    std::vector<glm::vec3> out;
    const auto add = [&](const glm::vec3& p) {
        const glm::vec3 q = p - origin;
        out.emplace_back(glm::dot(q, right), glm::dot(q, up), glm::dot(q, forward));
    };
    if (points.empty()) {
        for (int i = 0; i < 8; ++i)
            add({(i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y, (i & 4) ? box.max.z : box.min.z});
        return out;
    }
    out.reserve(points.size());
    for (const glm::vec3& p : points) add(to_frame * p);
    return out;
}

// frame_camera in the camera math's frame (+y up): `box` there, `points` turned by `to_frame`.
Camera frame_y_up(const BoundingBox& box, std::span<const glm::vec3> points, const glm::mat3& to_frame,
                  const CameraOptions& o, float aspect) {
    Camera cam;
    cam.fov_degrees = std::clamp(o.fov_degrees, 1.0f, 170.0f);
    cam.orthographic = o.orthographic;
    const float radius = std::max(0.5f * box.diagonal(), 1e-6f);
    cam.target = o.target.value_or(box.center());
    cam.up = o.up.value_or(glm::vec3(0, 1, 0));

    // The part of the image the model may fill, all but `margin` of the width and of the height
    // on each side, as tangents of the half fields of view.
    const float fill = 1.0f - 2.0f * std::clamp(o.margin, 0.0f, 0.49f);
    const float tan_v = std::tan(glm::radians(cam.fov_degrees) * 0.5f);
    const glm::vec2 reach = fill * glm::vec2(tan_v * aspect, tan_v);
    // Where the bounding sphere fits that part of the narrower field of view: the distance of an
    // orthographic eye, and of a perspective one that nothing else places.
    const float sphere_fit = radius / std::sin(std::atan(std::min(reach.x, reach.y)));

    glm::vec3 dir = o.eye ? glm::vec3(0.0f)
                          : orbit_direction(o.azimuth_degrees.value_or(kDefaultAzimuth),
                                            o.elevation_degrees.value_or(kDefaultElevation));
    if (o.eye)
        cam.eye = *o.eye;
    else
        cam.eye = cam.target + dir * o.distance.value_or(sphere_fit);
    if (glm::length(cam.eye - cam.target) < 1e-6f * radius)
        cam.eye = cam.target + glm::vec3(0, 0, sphere_fit), dir = {0, 0, 1};
    cam.up = safe_up(cam.target - cam.eye, cam.up);

    // Tight framing of the points (the model's vertices, or the box corners) seen from here.
    const glm::vec3 f = glm::normalize(cam.target - cam.eye);
    const glm::vec3 r = glm::normalize(glm::cross(f, cam.up)), u = glm::cross(r, f);
    const bool fit_eye = !cam.orthographic && !o.eye && !o.distance;
    const bool fit_height = cam.orthographic && !o.ortho_height;
    if (fit_eye || fit_height) {
        const std::vector<glm::vec3> seen = view_points(box, points, to_frame, cam.target, r, u, f);
        const bool centre = !o.eye && !o.target;  // else the view axis stays through the target
        const float clearance = 1e-2f * radius;   // the eye stays this far before the nearest point
        if (fit_eye && centre) {
            // The eye from which the limiting axis touches both margins and the other is centred;
            // the target becomes the point of the view axis nearest the box centre (the pivot).
            const glm::vec3 e = framing::centred_eye(seen, reach, clearance);
            cam.eye = cam.target + r * e.x + u * e.y + f * e.z;
            cam.target = cam.eye + f * glm::dot(box.center() - cam.eye, f);
        } else if (fit_eye) {
            cam.eye = cam.target - f * framing::distance_on_axis(seen, reach, clearance);
        } else {
            auto [lo, hi] = framing::extent(seen);
            if (centre) {
                const glm::vec2 mid = 0.5f * (lo + hi);
                cam.eye += r * mid.x + u * mid.y;
                cam.target += r * mid.x + u * mid.y;
                lo -= mid, hi -= mid;
            }
            const glm::vec2 half = glm::max(-lo, hi);
            cam.ortho_height = 2.0f * std::max({half.y, half.x / aspect, 1e-6f * radius}) / fill;
        }
    }
    if (o.ortho_height) cam.ortho_height = *o.ortho_height;
    fit_clip_planes(cam, box);
    if (o.near_plane) cam.near_plane = *o.near_plane;
    if (o.far_plane) cam.far_plane = *o.far_plane;
    return cam;
}

}  // namespace

Camera frame_camera(const BoundingBox& box, const CameraOptions& o, float aspect, std::span<const glm::vec3> points) {
    const UpAxis axis = o.up_axis.value_or(UpAxis::PosY);
    if (axis == UpAxis::PosY) return frame_y_up(box, points, glm::mat3(1.0f), o, aspect);
    // Frame the model in the camera math's frame (a signed permutation keeps the box
    // axis-aligned), then turn the camera back into the model's coordinates.
    const glm::mat3 to_model = up_axis_rotation(axis), to_frame = glm::transpose(to_model);
    const glm::vec3 a = to_frame * box.min, b = to_frame * box.max;
    const BoundingBox local{glm::min(a, b), glm::max(a, b)};
    CameraOptions lo = o;
    if (o.eye) lo.eye = to_frame * *o.eye;
    if (o.target) lo.target = to_frame * *o.target;
    if (o.up) lo.up = to_frame * *o.up;
    Camera cam = frame_y_up(local, points, to_frame, lo, aspect);
    cam.eye = to_model * cam.eye;
    cam.target = to_model * cam.target;
    cam.up = to_model * cam.up;
    return cam;
}

void fit_clip_planes(Camera& cam, const BoundingBox& box) {
    const float radius = std::max(0.5f * box.diagonal(), 1e-6f);
    const float dist = glm::length(cam.eye - cam.target);
    const float to_center = glm::length(cam.eye - box.center());
    cam.far_plane = to_center + 2.0f * radius;
    cam.near_plane = std::max(to_center - 2.0f * radius, 1e-3f * std::max(dist, radius));
    if (cam.orthographic) cam.near_plane = to_center - 2.0f * radius;  // may be negative: fine
}

glm::vec3 Light::direction_to_light(const glm::vec3& p) const {
    glm::vec3 d = type == LightType::Directional ? position - target : position - p;
    float len = glm::length(d);
    return len > 0.0f ? d / len : glm::vec3(0, 0, 1);
}

Light default_light(const BoundingBox& box, const Camera& camera) {
    glm::vec3 forward = glm::normalize(camera.target - camera.eye);
    glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
    glm::vec3 up = glm::cross(right, forward);
    glm::vec3 dir = glm::normalize(-0.6f * right + 0.8f * up - 1.0f * forward);
    Light light;
    light.target = box.center();
    light.position = box.center() + dir * 1.5f * std::max(box.diagonal(), 1e-6f);
    return light;
}

}  // namespace inkshade
