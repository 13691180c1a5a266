#include "geometry/orientation.hpp"

#include <tbb/parallel_sort.h>

#include <cstdint>
#include <vector>

namespace inkshade::geometry {

bool is_closed_outward(const Mesh& mesh) {
    if (mesh.triangles.empty()) return false;
    // One key per directed edge: the undirected pair (low, high) with the direction in bit 0.
    // A closed, consistently oriented mesh has each pair exactly twice, once per direction.
    std::vector<uint64_t> keys;
    keys.reserve(mesh.triangles.size() * 3);
    double volume6 = 0.0;
    for (const glm::uvec3& t : mesh.triangles) {
        for (int k = 0; k < 3; ++k) {
            uint64_t a = t[k], b = t[(k + 1) % 3];
            if (a == b) return false;  // degenerate face: not a clean surface
            keys.push_back(a < b ? (a << 33) | (b << 1) : (b << 33) | (a << 1) | 1u);
        }
        const glm::dvec3 p0(mesh.positions[t.x]), p1(mesh.positions[t.y]), p2(mesh.positions[t.z]);
        volume6 += glm::dot(p0, glm::cross(p1, p2));
    }
    if (!(volume6 > 0.0)) return false;
    tbb::parallel_sort(keys.begin(), keys.end());
    for (size_t i = 0; i < keys.size(); i += 2) {
        // keys[i] must be the forward copy and keys[i+1] its reverse twin.
        if (i + 1 >= keys.size() || (keys[i] & 1u) || keys[i + 1] != (keys[i] | 1u)) return false;
    }
    return true;
}

}  // namespace inkshade::geometry
