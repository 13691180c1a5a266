// Hatching strokes on a surface (line type `hatch`, shading model `hatching`): evenly spaced
// streamlines of a smoothed principal-curvature cross field, in two families (along the
// direction of larger |curvature|, and across it for cross-hatching) and several density
// levels, each level adding strokes halfway between those of the coarser ones. Hertzmann &
// Zorin 2000, "Illustrating Smooth Surfaces" (hatches along principal directions, density by
// tone); the even spacing is Jobard & Lefer 1997, "Creating Evenly-Spaced Streamlines of
// Arbitrary Density", carried from the plane onto the mesh by walking across its faces; the
// nested levels follow Praun et al. 2001, "Real-Time Hatching" (a tone level only adds strokes
// to the lighter levels'). The strokes depend on the mesh alone, so they stay on the surface
// when the camera moves; a view picks, by tone, which of them to draw (hatch_segments).
#pragma once
#include <cstdint>
#include <vector>

#include "geometry/adjacency.hpp"
#include "geometry/contours.hpp"
#include "geometry/curvature.hpp"
#include "inkshade/camera.hpp"
#include "inkshade/mesh.hpp"

namespace inkshade::geometry {

// Key of the id-th node of a view's hatch segments (high word 0xfffffff0, id below it): no
// edge key (high < low), vertex key (high == low), face-interior, pierce or split key
// (contours.hpp, visibility.cpp) has it, so hatch strokes chain only along themselves.
constexpr uint64_t hatch_node_key(uint32_t id) { return (uint64_t(0xfffffff0u) << 32) | id; }
constexpr uint32_t kMaxHatchNodes = 0xfffffff0u;

struct HatchOptions {
    // World distance between neighbouring level-0 strokes of one family; 0 = 1.5 % of the
    // bounding-box diagonal divided by `density`. Level k strokes are spacing / 2^k from their
    // neighbours.
    float spacing = 0.0f;
    float density = 1.0f;
    int levels = 2;     // density levels per family (1..4)
    bool cross = true;  // also the second family, across the first
    int smoothing = 8;  // smoothing iterations of the cross field
    uint32_t seed = 1;  // the order in which free seeds are tried
};

struct HatchStroke {
    // Points on mesh edges; points[i] and points[i + 1] bound a straight piece across
    // faces[i]. A closed stroke's last piece runs from its last point back to its first.
    std::vector<glm::vec3> points;
    std::vector<uint32_t> faces;
    // The mesh edge (edge_key) each point lies on, and where: the point is
    // lerp(position[low], position[high], t[i]) (low, high: the key's two vertices).
    std::vector<uint64_t> edges;
    std::vector<float> t;
    uint8_t family = 0;  // 0 along the direction of larger |curvature|, 1 across it
    uint8_t level = 0;
    bool closed = false;
};

struct Hatching {
    std::vector<HatchStroke> strokes;  // by family, then level, then in tracing order
    float spacing = 0.0f;              // level-0 spacing used (world)
};

// The per-vertex cross field: a unit tangent direction per vertex (the other family is
// normal × direction), the principal direction of larger |curvature| smoothed by
// `iterations` rounds of averaging with the neighbours as crosses (unit complex numbers
// e^{4iθ}), each weighted by its anisotropy |k1 − k2| / (|k1| + |k2|) (umbilic regions take
// their neighbours' directions, strongly curved ones keep theirs; Hertzmann & Zorin 2000,
// section 4.1). Zero for vertices without a usable tangent frame.
std::vector<glm::vec3> hatch_direction_field(const Mesh& mesh, const std::vector<glm::vec3>& normals,
                                             const Curvature& curvature, int iterations);

// Traces the strokes. `normals`: unit vertex normals; `curvature` and `adjacency` of the same
// mesh. Faces with an out-of-range index or zero area, non-manifold and border edges end a
// stroke. Deterministic for given inputs and seed.
Hatching trace_hatching(const Mesh& mesh, const std::vector<glm::vec3>& normals, const Curvature& curvature,
                        const EdgeAdjacency& adjacency, const HatchOptions& options = {});

// What one view draws of a hatching: a stroke piece of family f and level k is drawn where the
// tone (the Lambertian n·l of the interpolated vertex normal, clamped to [0, 1]) is below
// threshold[f * levels + k] and the surface faces the viewer; its strength fades from 1 to 0
// over `fade` below the threshold, and finer levels fade out where the surface turns away
// from the viewer (`thin`).
struct HatchView {
    glm::vec3 light{0.0f, 0.0f, 1.0f};  // world direction towards the light (unit)
    std::vector<float> thresholds;      // family-major, level-minor
    float fade = 0.05f;
    // Level k > 0 fades out where n·v falls below thin · 2^(k − 1) (0: never).
    float thin = 0.25f;
};

// The pieces drawn in `view`, as line segments whose ends carry the keys of hatch_node_key
// (each stroke's nodes apart from every other stroke's, so chaining follows the strokes) and
// lie on `face`.
std::vector<LineSegment> hatch_segments(const Mesh& mesh, const std::vector<glm::vec3>& normals,
                                        const Hatching& hatching, const Camera& camera, const HatchView& view);

}  // namespace inkshade::geometry
