// Hidden-line removal for object-space lines (vector lines get a visibility test per segment,
// raster lines a depth test): each line segment is sampled densely enough in the image
// (≤ 1 px apart), every sample is tested by a ray from the eye towards it against the mesh
// (Embree 3), and segments are split where visibility changes, the transition found by
// bisection to sub-pixel precision. This is the ray-cast counterpart of Freestyle's and rtsc's
// tests, exact up to the sampling instead of limited by a depth buffer's resolution.
#pragma once
#include <memory>
#include <utility>
#include <vector>

#include "geometry/contours.hpp"
#include "inkshade/camera.hpp"
#include "inkshade/mesh.hpp"

namespace inkshade::geometry {

// The mapping of a camera onto a width x height image, exactly as the renderer's
// projection(aspect) * view() and glViewport(0, 0, w, h): x right, y down from the top-left
// corner (image row j = height − 1 − GL row), depth as in the GL depth buffer ([0, 1]).
class ImageProjection {
public:
    ImageProjection(const Camera& camera, int width, int height);
    // (x px, y px, window depth). Undefined for points at or behind the eye's plane: check
    // clipped() first.
    glm::dvec3 project(const glm::vec3& p) const;
    // Outside the near/far range: the GL clipper removes such points from the render.
    bool clipped(const glm::vec3& p) const;
    // Distance from the eye plane along the view direction (positive in front).
    double view_depth(const glm::vec3& p) const;

    const Camera& camera() const { return camera_; }
    int width() const { return width_; }
    int height() const { return height_; }

private:
    Camera camera_;
    int width_, height_;
    glm::dmat4 clip_from_world_;
    glm::dvec3 eye_, forward_;
};

// One point to test (RayScene::occluded): the faces within `rings` rings of `near` are
// ignored, and hits closer than max(tolerance, clearance) to the point along the ray.
struct OcclusionQuery {
    glm::vec3 point{0.0f};
    const uint32_t* near = nullptr;
    int near_count = 0;
    int rings = 1;
    double clearance = 0.0;
};

// One spare vertex of capacity, written (zero) once, so that RayScene can share `positions`
// with Embree (which reads the last vertex with a 16-byte load) instead of copying them.
void reserve_embree_padding(std::vector<glm::vec3>& positions);

// Faces incident to a chosen set of vertices (CSR over those vertices only), from one scan of
// the triangles: what the two-ring test needs around the samples of one view, instead of a
// mesh-wide vertex → face table (140 MB at 10 M triangles, issue 9's memory budget). Triangles
// with an out-of-range index are left out.
class IncidentFaces {
public:
    IncidentFaces() = default;
    // `vertices` in any order, duplicates allowed; parallel scan (TBB).
    IncidentFaces(const Mesh& mesh, const std::vector<uint32_t>& vertices);

    // Faces incident to v, ascending ([first, last)); empty when v was not chosen.
    std::pair<const uint32_t*, const uint32_t*> faces(uint32_t v) const;

private:
    static constexpr uint32_t kNone = 0xffffffffu;
    std::vector<uint32_t> slot_;            // per mesh vertex: its index among the chosen, or kNone
    std::vector<uint32_t> offset_, faces_;  // faces_[offset_[i] .. offset_[i + 1]) of chosen vertex i
};

// An Embree scene of one mesh, built once (BVH of all triangles) and queried by many views.
// Degenerate triangles are never hit (Embree rejects zero-area and non-finite triangles);
// triangles with an out-of-range index are replaced by an empty one, so any Mesh is safe.
// The index buffer is shared with `mesh`, and so is the vertex buffer when `mesh.positions` has
// spare capacity (Embree reads the last vertex with a 16-byte load; MeshLineData reserves one
// more vertex for this), else vertices are copied: the mesh must outlive the scene unchanged.
class RayScene {
public:
    explicit RayScene(const Mesh& mesh);  // throws RuntimeError when Embree fails
    ~RayScene();
    RayScene(const RayScene&) = delete;
    RayScene& operator=(const RayScene&) = delete;

    // Ray-casting tolerance (world units): hits closer than this to the tested point along the
    // ray do not occlude it. 1e-4 × the bounding-box diagonal — far below a pixel at any
    // framing that shows the whole model (a 4096 px image of the model spans ~4e-4 of it per
    // pixel), yet above float rounding of coordinates (~1e-7 relative), so coincident copies of
    // a surface (z-fighting duplicates) do not hide each other's lines.
    double tolerance() const { return tolerance_; }

    // True when the straight path from the viewer to `p` (from the eye, or from the near plane
    // along the view direction when orthographic; starting at the near plane either way, as
    // GL clips) crosses a triangle before reaching p − tolerance. Triangles within `rings`
    // (1 or 2) face rings of the vertices `near_vertices` are ignored: 1 = faces incident to
    // them (the faces the point lies on), 2 = also faces sharing a vertex with those.
    //
    // Why rings and not a larger distance: a contour point lies where the surface turns away
    // from the ray, so the ray grazes the surface there and, on a piecewise-linear mesh, may
    // cut a nearby face well before p (interpolated n·v = 0 is not where the faces' own
    // normals flip; near the slivers at a UV sphere's pole the cut face is two rings away, at
    // a depth up to an edge length before p). No distance tolerance small enough to keep real
    // occluders catches that; excluding the point's neighbourhood does, and still lets thin
    // features (the two sides of a sheet) hide each other's lines away from their rim.
    // `clearance` (world units) raises the tolerance for this test: hits closer than that to p
    // along the ray do not count. `incident`: as for the batch call below.
    bool occluded(const ImageProjection& view, const glm::vec3& p, const uint32_t* near_vertices, int near_count,
                  int rings = 1, double clearance = 0.0, const IncidentFaces* incident = nullptr) const;
    // The same for `count` queries at once, as one ray stream (rtcOccluded1M); hidden[i] = 1
    // where query i is occluded. Two-ring queries look up the faces of their near vertices in
    // `incident`, which must cover them; without it, one is built for these queries (a scan
    // of all triangles: pass one when testing many batches, as split_by_visibility does).
    void occluded(const ImageProjection& view, const OcclusionQuery* queries, size_t count, uint8_t* hidden,
                  const IncidentFaces* incident = nullptr) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    double tolerance_ = 0.0;
};

struct VisibilityOptions {
    // Largest image distance between two tested samples of a segment (pixels): a ~1 px gap
    // misses only occluders thinner than a pixel, which the PNG would not show either.
    float sample_spacing_px = 1.0f;
    // Bisection of a visibility change stops when the bracket is this short (pixels).
    float transition_precision_px = 0.01f;
    // Face rings ignored around each sample (RayScene::occluded) of isolines (contour,
    // suggestive: contours graze the surface). Segments along mesh edges (vertex keys at both
    // ends: creases, borders, silhouette edges) lie exactly on their faces and use one ring.
    int exclusion_rings = 2;
    // Isoline samples also ignore hits closer along the ray than this times the longest edge
    // of the segment's face. Rings are not a metric: at the slivers around a UV sphere's pole
    // a grazing ray cuts a face three narrow columns away, 0.4 edge lengths before the point.
    // Real occluders that close are missed only within about an edge length of a T-junction.
    float isoline_clearance = 1.0f;
};

// The segments' parts, split where visibility changes. Parts keep the original node keys at
// unsplit ends, so chain_segments joins them as before; a split point gets a node key of its
// own (it ends a chain). Strength is interpolated linearly at split points. Parts outside the
// near/far range are dropped (the renderer clips them too). Output order follows the input.
struct VisibilitySplit {
    std::vector<LineSegment> visible;
    std::vector<LineSegment> hidden;
};

// Tests segments of `mesh` (the mesh of `scene`) seen through `view`; parallel over segments
// (TBB), deterministic. The near vertices of a sample come from its node keys: the edge's two
// vertices, the crease vertex, or the three vertices of the segment's face for points inside
// a face. Two-ring samples look their near vertices up in `incident` (incident_faces_of these
// segments, or of several lists that include them); without it, one is built here.
VisibilitySplit split_by_visibility(const RayScene& scene, const Mesh& mesh, const ImageProjection& view,
                                    const std::vector<LineSegment>& segments, const VisibilityOptions& options = {},
                                    const IncidentFaces* incident = nullptr);

// The faces around every near vertex of the two-ring samples of these segment lists (one scan
// of the triangles, about 30 ms at 10 M): build it once per view for all line types.
IncidentFaces incident_faces_of(const Mesh& mesh, const std::vector<const std::vector<LineSegment>*>& lists,
                                const VisibilityOptions& options = {});

}  // namespace inkshade::geometry
