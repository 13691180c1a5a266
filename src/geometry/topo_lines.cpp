// Topographic lines: heights per vertex, the levels inside the bounding sphere, their level sets.
#include "geometry/topo_lines.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "geometry/face_segments.hpp"
#include "geometry/feature_size.hpp"
#include "geometry/isolines.hpp"
#include "inkshade/error.hpp"
#include "inkshade/params.hpp"

namespace inkshade::geometry {
namespace {

glm::dvec3 height_axis(const Camera& camera, const TopoOptions& options) {
    const glm::dvec3 d(options.direction);
    if (!options.world) return camera_to_world(camera, d, "topo");
    const double len = glm::length(d);
    if (!(len > 0.0) || !std::isfinite(len)) throw InputError("topo: direction has no length");
    return d / len;
}

}  // namespace

std::vector<double> topo_levels(const Mesh& mesh, const Camera& camera, const TopoOptions& options) {
    const glm::dvec3 axis = height_axis(camera, options);
    const BoundingSphere sphere = bounding_sphere(mesh);
    const double r = sphere.radius, middle = glm::dot(glm::dvec3(sphere.center), axis);
    if (!(r > 0.0) || !std::isfinite(r) || !std::isfinite(middle)) return {};
    // Heights base + (k + offset) · step inside [middle − r, middle + r].
    double step, base;
    if (options.spacing > 0.0f) {
        step = options.spacing;
        base = 0.0;
    } else {
        step = 2.0 * r / std::max(options.count, 1);
        base = middle - r;
    }
    const double shift = base + double(options.offset) * step;
    const double k_first = std::ceil((middle - r - shift) / step), k_last = std::floor((middle + r - shift) / step);
    if (!(k_last - k_first < double(kMaxTopoLines)))
        throw InputError("topo: spacing " + format_number(float(step)) + " gives more than " +
                         std::to_string(kMaxTopoLines) + " lines across the model");
    std::vector<double> levels;
    for (double k = k_first; k <= k_last; ++k) levels.push_back(shift + k * step);
    return levels;
}

std::vector<LineSegment> extract_topo_lines(const Mesh& mesh, const std::vector<glm::vec3>& normals,
                                            const Camera& camera, const TopoOptions& options) {
    if (normals.size() != mesh.positions.size())
        throw std::invalid_argument("extract_topo_lines: need one normal per vertex");
    const std::vector<double> levels = topo_levels(mesh, camera, options);
    if (levels.empty()) return {};
    const glm::dvec3 axis = height_axis(camera, options);
    const size_t n = mesh.positions.size();
    std::vector<float> height(n);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, kFaceGrain), [&](const auto& range) {
        for (size_t i = range.begin(); i != range.end(); ++i)
            height[i] = float(glm::dot(glm::dvec3(mesh.positions[i]), axis));
    });
    if (options.back_faces) return extract_isolines(mesh, height, levels);
    const std::vector<float> facing = view_dot_normal(mesh, normals, camera);
    return extract_isolines(mesh, height, levels, &facing);
}

}  // namespace inkshade::geometry
