#include "geometry/section_cut.hpp"

#include "geometry/visibility.hpp"

namespace inkshade::geometry {

Mesh section_ray_mesh(const Mesh& mesh, const SectionPlane& plane, double tolerance) {
    Mesh out;
    out.positions = mesh.positions;
    reserve_embree_padding(out.positions);
    out.triangles = mesh.triangles;
    const size_t n = mesh.positions.size();
    for (glm::uvec3& t : out.triangles) {
        if (t.x >= n || t.y >= n || t.z >= n) continue;
        const auto removed = [&](uint32_t v) { return plane.distance(mesh.positions[v]) > tolerance; };
        if (removed(t.x) && removed(t.y) && removed(t.z)) t = glm::uvec3(t.x);
    }
    return out;
}

void clip_to_section(std::vector<LineSegment>& segments, const SectionPlane& plane, double tolerance) {
    std::vector<LineSegment> kept;
    kept.reserve(segments.size());
    // Each cut end its own key, above the ids an extraction of intersection lines numbers from 0,
    // so it is a free chain end (two cut ends in one face must not join).
    uint32_t cuts = 0x80000000u;
    for (LineSegment s : segments) {
        const double da = plane.distance(s.a) - tolerance, db = plane.distance(s.b) - tolerance;
        if (da > 0.0 && db > 0.0) continue;
        if (da > 0.0 || db > 0.0) {
            // The crossing of the plane (shifted by the tolerance); strengths interpolated.
            const double t = da / (da - db);
            const glm::vec3 p = glm::vec3(glm::dvec3(s.a) + t * (glm::dvec3(s.b) - glm::dvec3(s.a)));
            const float strength = float(s.strength_a + t * (s.strength_b - s.strength_a));
            if (da > 0.0) {
                s.a = p, s.strength_a = strength, s.edge_a = pierce_key(cuts++);
            } else {
                s.b = p, s.strength_b = strength, s.edge_b = pierce_key(cuts++);
            }
        }
        kept.push_back(s);
    }
    segments = std::move(kept);
}

}  // namespace inkshade::geometry
