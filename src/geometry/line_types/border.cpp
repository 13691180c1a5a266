// `border`: mesh boundary edges, the edges of exactly one face (extract_creases).
#include "geometry/line_types/object_line_registry.hpp"

namespace inkshade::geometry {

namespace {

std::vector<LineSegment> extract(MeshLineData& data, const LineView&, const LineSettings&) { return data.borders(); }

const ObjectLineRegistration registration{{.name = "border",
                                           .summary = "borders: mesh boundary edges (edges of exactly one face)",
                                           .params = object_line_params(glm::vec3(0.0f), 1.5f, {}, 0.0f)},
                                          extract,
                                          {.adjacency = true}};

}  // namespace

}  // namespace inkshade::geometry
