#include "geometry/plane_cuts.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>

#include "geometry/isolines.hpp"

namespace inkshade::geometry {

SectionPlane near_plane_of(const Camera& camera) {
    const glm::dvec3 forward = glm::normalize(glm::dvec3(camera.target) - glm::dvec3(camera.eye));
    return {.point = glm::vec3(glm::dvec3(camera.eye) + double(camera.near_plane) * forward),
            .normal = glm::vec3(-forward)};
}

std::vector<LineSegment> extract_plane_cut(const Mesh& mesh, const SectionPlane& plane, uint32_t isoline) {
    std::vector<float> d(mesh.positions.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, d.size(), 16384), [&](const auto& range) {
        for (size_t v = range.begin(); v != range.end(); ++v) d[v] = float(plane.distance(mesh.positions[v]));
    });
    std::vector<LineSegment> segments = extract_isolines(mesh, d, {0.0});
    for (LineSegment& s : segments) s.isoline = isoline;
    return segments;
}

}  // namespace inkshade::geometry
