// Line sets' face selections (inkshade/lines.hpp FaceSelection) applied to a mesh and to the
// segments its line types extract: a line set draws the parts of its lines that lie on the
// faces it selects, before visibility, so hidden-line removal still sees the whole mesh.
#pragma once
#include <cstdint>
#include <unordered_set>
#include <vector>

#include "geometry/contours.hpp"
#include "inkshade/lines.hpp"
#include "inkshade/mesh.hpp"

namespace inkshade::geometry {

// One byte per triangle, 1 where `selection` takes the face: its material name (face_materials,
// materials), object name (face_objects, object_names) and face mark (face_marks) each match
// when given. A face without a material, object or mark has the name "" and mark 0.
std::vector<uint8_t> selected_faces(const Mesh& mesh, const FaceSelection& selection);

// A selection resolved on one mesh, to filter segments with.
class SelectedFaces {
public:
    SelectedFaces(const Mesh& mesh, const FaceSelection& selection);
    // A segment is kept when it lies on a selected face: the face it crosses or, for an
    // intersection (unless its owner is decided by priority: LineSegment::owned) or a
    // hard-edge contour, its second face; for a line along a mesh edge
    // (crease, border, material boundary) either face of that edge, found by position as those
    // types find their edges (Freestyle selects an edge when either of its faces is selected).
    bool keeps(const LineSegment& s) const;
    // Drops the segments not kept, in place, order unchanged.
    void filter(std::vector<LineSegment>& segments) const;

private:
    std::vector<uint8_t> selected_;
    std::vector<uint32_t> canonical_;     // coincident vertices: one index (canonical_vertices)
    std::unordered_set<uint64_t> edges_;  // edge_key of canonical ends, of every selected face
};

}  // namespace inkshade::geometry
