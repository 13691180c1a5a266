#include "render/edge_length.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace inkshade::render {

float typical_edge_length(const Mesh& mesh) {
    const size_t n = mesh.triangles.size();
    if (n == 0) return 0.0f;
    constexpr size_t kSamples = 65536;
    const size_t stride = (n + kSamples - 1) / kSamples;
    std::vector<float> areas;
    areas.reserve(n / stride + 1);
    for (size_t i = 0; i < n; i += stride) {
        const glm::uvec3& t = mesh.triangles[i];
        const glm::vec3 &a = mesh.positions[t.x], &b = mesh.positions[t.y], &c = mesh.positions[t.z];
        areas.push_back(0.5f * glm::length(glm::cross(b - a, c - a)));
    }
    auto mid = areas.begin() + std::ptrdiff_t(areas.size() / 2);
    std::nth_element(areas.begin(), mid, areas.end());
    return std::sqrt(4.0f * *mid / std::sqrt(3.0f));  // area = (sqrt(3) / 4) side^2
}

}  // namespace inkshade::render
