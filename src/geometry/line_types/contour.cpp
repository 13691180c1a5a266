// `contour`: occluding contours, the zero set of n·v interpolated across faces
// (extract_contours; with the pieces of hard edges where the facing flips on a mesh with hard
// edges, extract_hard_edge_contours), optionally with the whole-edge polygon silhouette added.
#include "geometry/hard_edge_contours.hpp"
#include "geometry/line_types/object_line_registry.hpp"

namespace inkshade::geometry {

namespace {

std::vector<LineSegment> extract(MeshLineData& data, const LineView& view, const LineSettings& settings) {
    std::vector<LineSegment> segments = data.mesh().has_hard_edges()
                                            ? extract_hard_edge_contours(data.mesh(), data.hard_edges(), view.camera)
                                            : extract_contours(data.mesh(), data.normals(), view.camera);
    if (line_number(settings, "silhouette-edges") != 0.0f) {
        const auto& p = data.mesh().positions;
        for (const SilhouetteEdge& e : mesh_silhouette_edges(data.mesh(), view.camera))
            segments.push_back({.a = p[e.v0],
                                .b = p[e.v1],
                                .edge_a = vertex_key(e.v0),
                                .edge_b = vertex_key(e.v1),
                                .face = 0xffffffffu});
    }
    return segments;
}

const ObjectLineRegistration registration{
    {.name = "contour",
     .summary = "occluding contours: zero crossings of n·v interpolated along mesh edges (the simple method marks "
                "whole edges)",
     .params = object_line_params(
         glm::vec3(0.0f), 1.5f,
         {bool_param("silhouette-edges", false,
                     "also draw whole mesh edges between a front- and a back-facing face (the "
                     "polygon silhouette, not interpolated: jagged on coarse meshes but exactly the polygon outline)")},
         1.0f)},
    extract,
    {.contour_folds = true}};

}  // namespace

}  // namespace inkshade::geometry
