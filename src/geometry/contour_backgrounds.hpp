// What lies behind an occluding contour (line types `silhouette` and `external-contour`, as
// Freestyle's ContourUP1D and ExternalContourUP1D tell them apart): just past the contour, on
// the side its surface turns away from, a ray from the viewer meets the background, another
// object (connected_objects.hpp) or the contour's own object again (an inner fold: the torus's
// inner rim over its far side).
#pragma once
#include <cstdint>
#include <vector>

#include "geometry/contours.hpp"
#include "geometry/visibility.hpp"
#include "inkshade/camera.hpp"
#include "inkshade/mesh.hpp"

namespace inkshade::geometry {

enum class Behind : uint8_t { Nothing, OtherObject, SameObject };

// Per segment of `contours` (extract_contours or extract_hard_edge_contours on `mesh`): the
// first surface behind the segment's midpoint m, found by a ray from the viewer through
// m + offset · n⊥, where n⊥ is the unit projection across the view of the normal interpolated
// at m (it points off the surface's outline) and offset = kBehindOffset × the distance from
// the eye (perspective) or × the view height (orthographic): about 2 px at 1024 px and 35°,
// clear of the polygon's own fold, below any gap a drawing shows. Only surfaces farther than
// m count, so the answer is the same for hidden pieces. `objects` is face_objects(mesh).
constexpr double kBehindOffset = 2e-3;
std::vector<Behind> behind_contours(const Mesh& mesh, const std::vector<glm::vec3>& normals, const Camera& camera,
                                    const RayScene& scene, const std::vector<LineSegment>& contours,
                                    const std::vector<uint32_t>& objects);

}  // namespace inkshade::geometry
