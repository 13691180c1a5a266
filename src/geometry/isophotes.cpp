// Isophotes: n·l per vertex for the light turned into world coordinates, then its level sets.
#include "geometry/isophotes.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geometry/face_segments.hpp"
#include "geometry/isolines.hpp"

namespace inkshade::geometry {

std::vector<double> isophote_levels(const IsophoteOptions& options) {
    std::vector<double> levels;
    if (options.levels > 0) {
        for (int k = 1 - options.levels; k < options.levels; ++k) levels.push_back(double(k) / options.levels);
        return levels;
    }
    for (float v : options.values)
        if (std::isfinite(v)) levels.push_back(std::clamp(double(v), -1.0, 1.0));
    std::sort(levels.begin(), levels.end());
    levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
    return levels;
}

std::vector<LineSegment> extract_isophotes(const Mesh& mesh, const std::vector<glm::vec3>& normals,
                                           const Camera& camera, const IsophoteOptions& options) {
    const size_t n = mesh.positions.size();
    if (normals.size() != n) throw std::invalid_argument("extract_isophotes: need one normal per vertex");
    const glm::dvec3 light = camera_to_world(camera, glm::dvec3(options.direction), "isophote");
    std::vector<float> ndotl(n);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, kFaceGrain), [&](const auto& range) {
        for (size_t i = range.begin(); i != range.end(); ++i) ndotl[i] = float(glm::dot(glm::dvec3(normals[i]), light));
    });
    if (options.back_faces) return extract_isolines(mesh, ndotl, isophote_levels(options));
    const std::vector<float> facing = view_dot_normal(mesh, normals, camera);
    return extract_isolines(mesh, ndotl, isophote_levels(options), &facing);
}

}  // namespace inkshade::geometry
