// `external-contour`: the contour pieces with the background behind them (Freestyle's
// ExternalContourUP1D: no occludee), the outline of the drawing's figure.
#include "geometry/line_types/contour_pieces.hpp"

namespace inkshade::geometry {

namespace {

std::vector<LineSegment> extract(MeshLineData& data, const LineView& view, const LineSettings&) {
    return contour_pieces(data, view, [](Behind b) { return b == Behind::Nothing; });
}

const ObjectLineRegistration registration{
    {.name = "external-contour",
     .summary = "external contours: the contour where nothing but the background lies behind it (the figure's "
                "outline; Freestyle's external contour)",
     .params = object_line_params(glm::vec3(0.0f), 2.5f, {}, 1.0f)},
    extract,
    {.contour_folds = true}};

}  // namespace

}  // namespace inkshade::geometry
