// Object-space occluding contours (line type `contour`): zero crossings of g = n·v inside each
// face. The simplest real-time method marks whole mesh edges whose endpoints' n·v differ in sign
// (the product of the two is negative); here the crossing is interpolated along each such edge,
// so the contour is a smooth polyline that runs across faces.
#pragma once
#include <cstdint>
#include <vector>

#include "inkshade/camera.hpp"
#include "inkshade/mesh.hpp"

namespace inkshade::geometry {

// Key of the undirected mesh edge (i, j): min index in the high 32 bits, max in the low.
constexpr uint64_t edge_key(uint32_t i, uint32_t j) {
    return i < j ? (uint64_t(i) << 32) | j : (uint64_t(j) << 32) | i;
}

// Key of the chain node at mesh vertex v, for lines made of whole mesh edges (creases,
// borders): edge_key(v, v), which no proper edge (i ≠ j) has.
constexpr uint64_t vertex_key(uint32_t v) { return edge_key(v, v); }

// Key of a segment end strictly inside face f (a line trimmed by a threshold there); `end`
// (0 or 1) tells the two ends of one face apart. The high word exceeds the low word, which
// edge and vertex keys never do, so such an end meets no other segment and ends its chain.
constexpr uint64_t face_interior_key(uint32_t f, uint32_t end) { return (uint64_t(0xffffffffu - end) << 32) | f; }

// Key of the point where a mesh edge pierces a face (line type `intersection`): `id` numbers
// the distinct (edge, pierced face) pairs of one extraction. High word 0xfffffffc: no edge,
// vertex or face-interior key has it (nor split points, 0xfffffffd, visibility.cpp).
constexpr uint64_t pierce_key(uint32_t id) { return (uint64_t(0xfffffffcu) << 32) | id; }

// No face (LineSegment::face_b of a line that lies on one surface only).
constexpr uint32_t kNoFace = 0xffffffffu;

// One straight piece of a line, shared by every line type (contour, suggestive, crease,
// border, ridge) so one chainer and one visibility test serve them all. The ends carry node
// keys: for isolines (contour, suggestive, ridge) the mesh edge the end lies on, computed from
// that edge alone so that the segments of two faces sharing the edge have bit-identical
// endpoints and strengths there; for edge lines (crease, border) vertex_key of the end vertex;
// face_interior_key for an end where a threshold cut the line inside a face. For contours, on
// a consistently oriented mesh, walking a → b keeps the front-facing side (g ≥ 0) on the left
// seen from the outside (the face's counter-clockwise side).
struct LineSegment {
    glm::vec3 a{0.0f}, b{0.0f};
    uint64_t edge_a = 0, edge_b = 0;             // node keys of a and b (edge_a != edge_b)
    uint32_t face = 0;                           // the face the segment crosses (edge lines: lowest incident face)
    float strength_a = 1.0f, strength_b = 1.0f;  // in [0, 1], for fading; contours and creases 1
    // The second face an intersection line lies on (the other surface), else kNoFace.
    uint32_t face_b = kNoFace;
    // Which of its type's isolines the segment is on, for types that draw several level sets
    // of one function (isophotes, topographic lines: the level's index). Chaining joins only
    // ends of one isoline: two levels crossing the same mesh edge share its node key.
    uint32_t isoline = 0;
    // An intersection whose two objects differ in priority (intersection_priority.hpp): it
    // belongs to `face`'s object alone, so a line set selects it by `face` only.
    bool owned = false;
};

// The contour's name for the shared segment type.
using ContourSegment = LineSegment;

// Unit vector from a point towards the viewer: to the eye (perspective) or −view direction
// (orthographic); zero at the eye itself. The v of every view-dependent line.
class ViewVector {
public:
    explicit ViewVector(const Camera& camera);
    glm::dvec3 at(const glm::vec3& p) const;

private:
    glm::dvec3 eye_;
    glm::dvec3 ortho_dir_;
    bool orthographic_;
};

// Where the linear interpolant of per-vertex values `g` vanishes on the edge (i, j), whose
// values must differ in sign (g ≥ 0 counting as positive). Computed from the ordered pair
// (min, max) so every face sharing the edge gets the same bits; t runs from min to max index.
struct EdgeCrossing {
    double t = 0.0;
    glm::vec3 p{0.0f};
};
EdgeCrossing edge_zero_crossing(const Mesh& mesh, const std::vector<float>& g, uint32_t i, uint32_t j);

// g per vertex: n·v with v the unit vector from the vertex to the eye (perspective) or
// −view direction (orthographic). Non-finite values become 0.
std::vector<float> view_dot_normal(const Mesh& mesh, const std::vector<glm::vec3>& normals, const Camera& camera);

// Contour segments (strength 1) in face order (deterministic, parallel over faces). `normals`
// holds one normal per vertex (throws std::invalid_argument otherwise). A vertex with g = 0 counts as
// positive (symbolic perturbation), so every face has zero or exactly one segment. Faces with
// out-of-range indices, and crossings that would join an edge to itself (repeated index), give
// no segment.
std::vector<LineSegment> extract_contours(const Mesh& mesh, const std::vector<glm::vec3>& normals,
                                          const Camera& camera);

// A mesh edge between a front-facing and a back-facing face (by face normal against the
// vector to the eye at the face centroid): the polygon silhouette, without interpolation.
struct SilhouetteEdge {
    uint32_t v0 = 0, v1 = 0;  // v0 < v1
};

// Edges (sorted by (v0, v1)) whose incident faces include both a front- and a back-facing one;
// non-manifold edges count too. Degenerate faces (zero normal) and edges of a repeated index
// are ignored.
std::vector<SilhouetteEdge> mesh_silhouette_edges(const Mesh& mesh, const Camera& camera);

}  // namespace inkshade::geometry
