// Level sets of a per-vertex function: per face, the levels between its smallest and largest
// value by binary search, so a face pays for the levels that cross it only (a fine mesh with
// hundreds of topographic lines costs about what one level does).
#include "geometry/isolines.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "geometry/face_segments.hpp"
#include "inkshade/error.hpp"

namespace inkshade::geometry {

std::vector<LineSegment> extract_isolines(const Mesh& mesh, const std::vector<float>& f,
                                          const std::vector<double>& levels, const std::vector<float>* facing) {
    const size_t n = mesh.positions.size();
    if (f.size() != n || (facing && facing->size() != n))
        throw std::invalid_argument("extract_isolines: need one value per vertex");
    if (levels.empty()) return {};

    // The point where f = level on edge (i, j), from the ordered pair alone.
    auto on_edge = [&](uint32_t i, uint32_t j, double level) {
        if (j < i) std::swap(i, j);
        const double fi = f[i], fj = f[j];
        const double t = std::clamp((level - fi) / (fj - fi), 0.0, 1.0);
        const glm::dvec3 pi(mesh.positions[i]), pj(mesh.positions[j]);
        return glm::vec3(pi + t * (pj - pi));
    };

    const auto& tris = mesh.triangles;
    return collect_face_segments(tris.size(), [&](size_t face, std::vector<LineSegment>& out) {
        const glm::uvec3 t = tris[face];
        if (t.x >= n || t.y >= n || t.z >= n || t.x == t.y || t.y == t.z || t.z == t.x) return;
        if (facing && (*facing)[t.x] <= 0.0f && (*facing)[t.y] <= 0.0f && (*facing)[t.z] <= 0.0f) return;
        const double v[3] = {f[t.x], f[t.y], f[t.z]};
        if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2])) return;
        const double lo = std::min({v[0], v[1], v[2]}), hi = std::max({v[0], v[1], v[2]});
        // The levels in (lo, hi]: below them the lowest vertex, at or above them the highest.
        const auto first = std::upper_bound(levels.begin(), levels.end(), lo);
        const auto last = std::upper_bound(first, levels.end(), hi);
        for (auto it = first; it != last; ++it) {
            const double level = *it;
            const bool above[3] = {v[0] >= level, v[1] >= level, v[2] >= level};
            // The vertex on its own side of the level, and its two edges.
            const int k = above[1] == above[2] ? 0 : (above[0] == above[2] ? 1 : 2);
            const uint32_t vk = t[k], vnext = t[(k + 1) % 3], vprev = t[(k + 2) % 3];
            LineSegment seg;
            seg.a = on_edge(vk, vnext, level);
            seg.b = on_edge(vprev, vk, level);
            seg.edge_a = edge_key(vk, vnext);
            seg.edge_b = edge_key(vprev, vk);
            // As extract_contours: the side at or above the level on the left of a → b.
            if (!above[k]) {
                std::swap(seg.a, seg.b);
                std::swap(seg.edge_a, seg.edge_b);
            }
            seg.face = uint32_t(face);
            seg.isoline = uint32_t(it - levels.begin());
            out.push_back(seg);
        }
    });
}

glm::dvec3 camera_to_world(const Camera& camera, const glm::dvec3& direction, const char* what) {
    const double len = glm::length(direction);
    if (!(len > 0.0) || !std::isfinite(len)) throw InputError(std::string(what) + ": direction has no length");
    // The rows of the view matrix's rotation are the camera's axes in world coordinates.
    const glm::dmat3 rotation(glm::dmat4(camera.view()));
    const glm::dvec3 world = glm::transpose(rotation) * (direction / len);
    const double world_len = glm::length(world);
    // A camera without a frame (eye at its target, up along the view) draws nothing sensible
    // anyway; the direction is then taken as given.
    if (!(world_len > 0.5) || !std::isfinite(world_len)) return direction / len;
    return world / world_len;
}

}  // namespace inkshade::geometry
