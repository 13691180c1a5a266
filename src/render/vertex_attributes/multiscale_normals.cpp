// `multiscale-normals`: the mesh's vertex normals smoothed at several widths
// (geometry/multiscale_normals.hpp), finest first, read as v_scale_normal[] (exaggerated
// shading). A model that declares it has the parameters "scales" (compile-time Int: scales + 1
// widths, the coarsest for a base coat) and "sigma" (the finest width in typical edge lengths);
// widths double from scale to scale. Computed once per mesh and (scales, sigma).
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "geometry/multiscale_normals.hpp"
#include "render/frame.hpp"
#include "render/vertex_attribute.hpp"

namespace inkshade::render {

namespace {

constexpr int kMaxWidths = 9;  // locations 6-14 of the 16 GL guarantees

float param_value(const ShadingModel& model, const ParamValues& values, const char* name) {
    return value_or_default(*model.param(name), values).at(0);
}

int widths(const ShadingModel& model, const ParamValues& values) {
    return std::min(int(param_value(model, values, "scales")) + 1, kMaxWidths);
}

// sigma x the typical edge length, doubling.
std::vector<float> sigmas(const Frame& frame) {
    const float sigma = param_value(frame.model, frame.shading.params, "sigma");
    std::vector<float> out;
    for (int s = 0; s < widths(frame.model, frame.shading.params); ++s)
        out.push_back(std::ldexp(sigma * frame.edge_length, s));
    return out;
}

// Per vertex its normals side by side, finest first.
std::vector<float> scale_normals(const Frame& frame) {
    const auto normals = geometry::multiscale_normals(frame.cpu_mesh, frame.cpu_mesh.normals, sigmas(frame));
    const size_t n = frame.cpu_mesh.positions.size(), count = normals.size();
    std::vector<float> out(n * count * 3, 0.0f);
    for (size_t v = 0; v < n; ++v)
        for (size_t s = 0; s < count; ++s) {
            const glm::vec3 normal = v < normals[s].size() ? normals[s][v] : glm::vec3(0.0f, 0.0f, 1.0f);
            std::copy_n(&normal.x, 3, out.begin() + std::ptrdiff_t((v * count + s) * 3));
        }
    return out;
}

const VertexAttributeRegistration multiscale_normals_attribute{{
    .name = "multiscale-normals",
    .glsl = "scale_normal",
    .components = 3,
    .direction = true,
    .count = widths,
    .compute = scale_normals,
    .key = sigmas,
}};

}  // namespace

}  // namespace inkshade::render
