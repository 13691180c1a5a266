#include "geometry/line_types/contour_pieces.hpp"

#include "geometry/hard_edge_contours.hpp"

namespace inkshade::geometry {

std::vector<LineSegment> occluding_contours(MeshLineData& data, const Camera& camera) {
    return data.mesh().has_hard_edges() ? extract_hard_edge_contours(data.mesh(), camera)
                                        : extract_contours(data.mesh(), data.normals(), camera);
}

std::vector<LineSegment> contour_pieces(MeshLineData& data, const LineView& view, bool (*keep)(Behind)) {
    std::vector<LineSegment> contours = occluding_contours(data, view.camera);
    const std::vector<Behind> behind =
        behind_contours(data.mesh(), data.normals(), view.camera, view.scene, contours, data.face_objects());
    std::vector<LineSegment> kept;
    for (size_t i = 0; i < contours.size(); ++i)
        if (keep(behind[i])) kept.push_back(contours[i]);
    return kept;
}

}  // namespace inkshade::geometry
