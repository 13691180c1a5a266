// `silhouette`: the contour pieces that separate an object from the background or from another
// object behind it (Freestyle's ContourUP1D: the occludee is not the contour's own shape).
#include "geometry/line_types/contour_pieces.hpp"

namespace inkshade::geometry {

namespace {

std::vector<LineSegment> extract(MeshLineData& data, const LineView& view, const LineSettings&) {
    return contour_pieces(data, view, [](Behind b) { return b != Behind::SameObject; });
}

const ObjectLineRegistration registration{
    {.name = "silhouette",
     .summary = "silhouettes: the contour where the background or another object lies behind it (not an "
                "object's folds over itself; Freestyle's contour)",
     .params = object_line_params(glm::vec3(0.0f), 2.0f, {}, 1.0f)},
    extract,
    {.contour_folds = true}};

}  // namespace

}  // namespace inkshade::geometry
