#include "geometry/loose_lines.hpp"

namespace inkshade::geometry {

std::vector<LineSegment> extract_loose_lines(const Mesh& mesh) {
    std::vector<LineSegment> segments;
    segments.reserve(mesh.line_segments.size());
    const size_t nv = mesh.positions.size();
    for (const glm::uvec2& l : mesh.line_segments) {
        if (l.x >= nv || l.y >= nv || l.x == l.y) continue;
        LineSegment s;
        s.a = mesh.positions[l.x], s.b = mesh.positions[l.y];
        s.edge_a = vertex_key(l.x), s.edge_b = vertex_key(l.y);
        s.face = kNoFace;
        segments.push_back(s);
    }
    return segments;
}

}  // namespace inkshade::geometry
