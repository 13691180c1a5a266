#include "io/gltf_skinning.hpp"

#include <cmath>

namespace inkshade::io {

void normalize_skin_weights(std::vector<float>& weights) {
    for (size_t v = 0; v + 3 < weights.size(); v += 4) {
        const double sum = std::abs(double(weights[v])) + std::abs(double(weights[v + 1])) +
                           std::abs(double(weights[v + 2])) + std::abs(double(weights[v + 3]));
        if (sum > 0.0) {
            for (size_t k = 0; k < 4; ++k) weights[v + k] = float(double(weights[v + k]) / sum);
        } else {
            weights[v] = 1.0f;  // three.js: a zero sum gives (1, 0, 0, 0)
        }
    }
}

void skin_vertices(std::vector<float>& positions, std::vector<float>& normals, const std::vector<float>& joints,
                   const std::vector<float>& weights, const std::vector<glm::dmat4>& joint_matrices,
                   const std::string& where, int skin, const GltfFloatReader& reader) {
    const size_t n = positions.size() / 3;
    for (size_t v = 0; v < n; ++v) {
        glm::dmat4 blend(0.0);
        for (size_t k = 0; k < 4; ++k) {
            const double w = weights[4 * v + k];
            if (w == 0.0) continue;  // unused slots may hold any joint index
            const float joint = joints[4 * v + k];
            if (!(joint >= 0.0f) || size_t(joint) >= joint_matrices.size())
                reader.fail("JOINTS_0 of " + where + " has joint " + std::to_string(static_cast<long long>(joint)) +
                            " at vertex " + std::to_string(v) + " but skin " + std::to_string(skin) + " has " +
                            std::to_string(joint_matrices.size()) + " joints");
            blend += w * joint_matrices[size_t(joint)];
        }
        const glm::dvec4 p = blend * glm::dvec4(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2], 1.0);
        positions[3 * v] = float(p.x);
        positions[3 * v + 1] = float(p.y);
        positions[3 * v + 2] = float(p.z);
        if (normals.size() == positions.size()) {
            const glm::dvec3 m = glm::dmat3(blend) * glm::dvec3(normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]);
            const double len = glm::length(m);
            const glm::dvec3 u = len > 0.0 ? m / len : m;  // zero stays zero: load_mesh repairs it
            normals[3 * v] = float(u.x);
            normals[3 * v + 1] = float(u.y);
            normals[3 * v + 2] = float(u.z);
        }
    }
}

}  // namespace inkshade::io
