#include "geometry/contour_backgrounds.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>

#include "geometry/connected_objects.hpp"

namespace inkshade::geometry {

namespace {

// The vertex normal interpolated at p, a point of triangle t (barycentric coordinates).
glm::dvec3 normal_at(const Mesh& mesh, const std::vector<glm::vec3>& normals, const glm::uvec3& t,
                     const glm::dvec3& p) {
    const glm::dvec3 a(mesh.positions[t.x]), b(mesh.positions[t.y]), c(mesh.positions[t.z]);
    const glm::dvec3 e0 = b - a, e1 = c - a, d = p - a;
    const double d00 = glm::dot(e0, e0), d01 = glm::dot(e0, e1), d11 = glm::dot(e1, e1);
    const double d20 = glm::dot(d, e0), d21 = glm::dot(d, e1), den = d00 * d11 - d01 * d01;
    if (!(std::abs(den) > 0.0)) return glm::dvec3(normals[t.x] + normals[t.y] + normals[t.z]);
    const double v = (d11 * d20 - d01 * d21) / den, w = (d00 * d21 - d01 * d20) / den;
    return (1.0 - v - w) * glm::dvec3(normals[t.x]) + v * glm::dvec3(normals[t.y]) + w * glm::dvec3(normals[t.z]);
}

struct ViewRay {
    glm::dvec3 origin, direction;  // direction unit
    double t_point;                // where the ray passes the offset point
};

// The viewer's ray through q: from the eye, or along the view axis from the eye's plane.
ViewRay ray_through(const Camera& camera, const glm::dvec3& forward, const glm::dvec3& q) {
    const glm::dvec3 eye(camera.eye);
    if (camera.orthographic) {
        const double along = glm::dot(q - eye, forward);
        return {q - along * forward, forward, along};
    }
    const double length = glm::length(q - eye);
    return {eye, (q - eye) / length, length};
}

Behind classify(const Mesh& mesh, const std::vector<glm::vec3>& normals, const Camera& camera,
                const glm::dvec3& forward, const RayScene& scene, const LineSegment& s,
                const std::vector<uint32_t>& objects) {
    const glm::dvec3 m = 0.5 * (glm::dvec3(s.a) + glm::dvec3(s.b));
    const glm::dvec3 eye(camera.eye);
    const glm::dvec3 v = camera.orthographic ? -forward : glm::normalize(eye - m);
    glm::dvec3 n = normal_at(mesh, normals, mesh.triangles[s.face], m);
    n -= glm::dot(n, v) * v;
    const double length = glm::length(n);
    if (!(length > 0.0) || !std::isfinite(length)) return Behind::SameObject;
    const double scale = camera.orthographic ? double(camera.ortho_height) : glm::length(eye - m);
    const ViewRay ray = ray_through(camera, forward, m + (kBehindOffset * scale / length) * n);
    const auto hit = scene.first_hit(ray.origin, ray.direction, ray.t_point * (1.0 - 1e-4));
    if (!hit) return Behind::Nothing;
    const uint32_t own = objects[s.face], other = objects[hit->face];
    return own != kNoObject && other == own ? Behind::SameObject : Behind::OtherObject;
}

}  // namespace

std::vector<Behind> behind_contours(const Mesh& mesh, const std::vector<glm::vec3>& normals, const Camera& camera,
                                    const RayScene& scene, const std::vector<LineSegment>& contours,
                                    const std::vector<uint32_t>& objects) {
    const glm::dvec3 forward = glm::normalize(glm::dvec3(camera.target) - glm::dvec3(camera.eye));
    std::vector<Behind> behind(contours.size(), Behind::SameObject);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, contours.size(), 1024), [&](const auto& range) {
        for (size_t i = range.begin(); i != range.end(); ++i) {
            const LineSegment& s = contours[i];
            if (s.face < mesh.triangles.size() && s.face < objects.size())
                behind[i] = classify(mesh, normals, camera, forward, scene, s, objects);
        }
    });
    return behind;
}

}  // namespace inkshade::geometry
