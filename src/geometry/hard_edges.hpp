// Which edges auto-smooth splits the shading normal at (auto_smooth.hpp). On a CAD part an
// edge whose faces meet at more than the angle is a crease; on a dense scan the noise alone
// tilts neighbouring faces past 30° in many places, where a split would shade noise facets flat
// and draw contour pieces along them that a smooth surface (rtsc's vertex normals) has not.
// So an edge is hard only when its two sides still meet at more than the angle once each is
// averaged over the faces around it.
#pragma once
#include <cstdint>
#include <vector>

#include "geometry/vertex_faces.hpp"

namespace inkshade::geometry {

// The hard edges of a mesh and what auto-smooth reads with them.
struct HardEdgeFlags {
    // Bit k of flags[f] is set when the edge from corner k to corner k + 1 of face f is hard:
    // an edge of three or more faces, or an edge of two non-degenerate faces whose unit
    // normals `fn` have a dot product below cos_limit (the first test) and whose sides do too
    // (the second: the two sides' mean normals differ by more than the angle plus the sides'
    // scatter).
    std::vector<uint8_t> flags;
    // The stars of the vertices of the faces the first test saw, the only ones a hard edge can
    // touch; the other vertices' stars are empty (vertex_faces), so the table grows with the
    // faces near hard edges, not with the mesh.
    VertexFaces stars;
};

// A side's normal is the area-weighted mean normal of the faces with a corner at a corner of
// the edge's two faces, the two faces themselves left out, that lie on its side of the plane
// through the edge bisecting the two faces: split by position, not by normal, so a scan's
// noise averages out on both sides alike, while the flat sides of a CAD crease keep their
// normals (and no scatter). Its scatter: the area-weighted mean angle of those faces from it.
// Left out too: faces more than the angle from both faces (a third side at a corner), and
// faces more than twice the angle from their side's face but within it of the other's (the
// other side reached round a thin part). A side with none left is its face alone. Triangles
// must index existing vertices; fn has one entry per face (face_normals).
HardEdgeFlags hard_edge_flags(const Mesh& mesh, const std::vector<glm::vec3>& fn, float cos_limit);

}  // namespace inkshade::geometry
