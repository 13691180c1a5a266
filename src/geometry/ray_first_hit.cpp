// RayScene::first_hit (visibility.hpp): one closest-hit ray on the scene's Embree BVH, for the
// line types that ask what lies behind a point (silhouette, external-contour). Only the
// occlusion rays carry the crossing filter, so this ray sees every face as it is.
#include <limits>

#include "geometry/ray_scene_impl.hpp"

namespace inkshade::geometry {

std::optional<RayScene::Hit> RayScene::first_hit(const glm::dvec3& origin, const glm::dvec3& direction,
                                                 double t_min) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh{};
    rh.ray.org_x = float(origin.x), rh.ray.org_y = float(origin.y), rh.ray.org_z = float(origin.z);
    rh.ray.dir_x = float(direction.x), rh.ray.dir_y = float(direction.y), rh.ray.dir_z = float(direction.z);
    rh.ray.tnear = float(t_min);
    rh.ray.tfar = std::numeric_limits<float>::infinity();
    rh.ray.mask = 0xffffffffu;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(impl_->scene, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    return Hit{.face = rh.hit.primID, .t = double(rh.ray.tfar)};
}

}  // namespace inkshade::geometry
