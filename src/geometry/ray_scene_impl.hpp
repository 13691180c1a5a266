// What RayScene's two files share: the Embree scene (built in ray_scene.cpp) and the filter
// that counts occlusion levels on it (occlusion_levels.cpp), registered on the scene's
// geometry when it is built.
#pragma once
#include <embree3/rtcore.h>

#include <vector>

#include "geometry/visibility.hpp"

namespace inkshade::geometry {

struct RayScene::Impl {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    const Mesh* mesh = nullptr;
    std::vector<glm::uvec3> own_triangles;  // used when the mesh has out-of-range indices
    const glm::uvec3* triangles = nullptr;

    ~Impl() {
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }
};

// The occlusion filter (rtcSetGeometryOccludedFilterFunction): counts each crossing once and
// lets the ray go on until the cap is reached (RayScene::occlusion_levels).
void count_crossings(const RTCFilterFunctionNArguments* args);

}  // namespace inkshade::geometry
