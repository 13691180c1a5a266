// Hidden-line removal for object-space lines (vector lines get a visibility test per segment,
// raster lines a depth test): each line segment is sampled densely enough in the image
// (≤ 1 px apart), every sample's occlusion level (how many surfaces lie in front of it) is
// counted by a ray from the eye towards it against the mesh (Embree 3), and segments are split
// where the level changes, the change found by bisection to sub-pixel precision. A line's own
// faces are told apart by topology (PointOn), never by a distance; its own surface less than a
// pixel's depth in front by topology within a ball of 2 px (own_neighbourhood.hpp).
// docs/lines.md has the method and its limits.
#pragma once
#include <atomic>
#include <memory>
#include <optional>
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
    // The clip-space w of p (perspective: its view depth; orthographic: 1).
    double clip_w(const glm::vec3& p) const;
    // World size of one pixel at p's depth (orthographic: everywhere): the depth a pixel spans
    // there (docs/lines.md, Visibility).
    double pixel_size(const glm::vec3& p) const;

    const Camera& camera() const { return camera_; }
    int width() const { return width_; }
    int height() const { return height_; }

private:
    Camera camera_;
    int width_, height_;
    glm::dmat4 clip_from_world_;
    glm::dvec3 eye_, forward_;
    double pixel_per_depth_;  // perspective: pixel size per unit of view depth
};

// What a tested point lies on. The faces that contain the point can never lie in front of it,
// and a grazing ray may graze them, so they are not occluders — decided by topology, never by
// a distance: `face` and `face_b` always, plus the faces that contain the mesh edge (u, v)
// (Edge), the vertex u (Vertex), or share an edge with `face` or `face_b` (FaceNeighbours: an
// intersection line's end, where a mesh edge pierces a face).
struct PointOn {
    enum Kind : uint8_t { Faces, Edge, Vertex, FaceNeighbours };
    Kind kind = Faces;
    uint32_t face = kNoFace, face_b = kNoFace;
    uint32_t u = kNoFace, v = kNoFace;

    static PointOn in_face(uint32_t f, uint32_t g = kNoFace) { return {Faces, f, g}; }
    static PointOn on_edge(uint32_t a, uint32_t b) { return {Edge, kNoFace, kNoFace, a, b}; }
    static PointOn at_vertex(uint32_t a) { return {Vertex, kNoFace, kNoFace, a}; }
};

// One point to test (RayScene::occlusion_levels).
struct OcclusionQuery {
    glm::vec3 point{0.0f};
    PointOn on;
    // A sample of an occluding contour: its fold (RayScene::occlusion_levels) within this
    // distance of the ray (world units; 0 = not a contour sample), and the interpolated unit
    // normal at the point.
    float fold_band = 0.0f;
    glm::vec3 normal{0.0f};
    // The point's own surface (docs/lines.md, Visibility): a hit less than `own_depth` in front
    // of the point along the ray (world units) on a face of its own neighbourhood
    // (own_neighbourhood.hpp: the faces within `own_radius` joined by edges to the faces that
    // contain it) does not count. 0: every hit counts.
    float own_depth = 0.0f;
    float own_radius = 0.0f;
    // Contour samples: a hit on a face that touches (shares a vertex with, smoothly) the face
    // the point lies on does not count while it is less than
    // `slope_depth` × that face's depth slope (tan of its angle to the plane normal to the ray,
    // at most kMaxOwnSlope) in front (world units; 0 = off). An interpolated contour lies on the smooth surface its
    // normals describe, which on a coarse part runs a little way past the polygon outline, onto the back face behind
    // it; rtsc draws it there, its mesh pushed back by glPolygonOffset(5, 30).
    float slope_depth = 0.0f;
};

// The steepest face slope the own-surface rule takes (OcclusionQuery::slope_depth): 84°
// from the image plane; steeper faces cover less than a tenth of their depth in the image.
constexpr float kMaxOwnSlope = 10.0f;

// One spare vertex of capacity, written (zero) once, so that RayScene can share `positions`
// with Embree (which reads the last vertex with a 16-byte load) instead of copying them.
void reserve_embree_padding(std::vector<glm::vec3>& positions);

// The faces on either side of the edges of the faces around a chosen set of vertices, from
// one scan of the triangles: what the fold walks of one view's contours cross
// (RayScene::occlusion_levels), instead of a mesh-wide edge table (500 MB at 10 M triangles).
// Triangles with an out-of-range index are left out.
class EdgeNeighbours {
public:
    EdgeNeighbours() = default;
    // `vertices` in any order, duplicates allowed; parallel scans (TBB).
    EdgeNeighbours(const Mesh& mesh, const std::vector<uint32_t>& vertices);

    // The one face other than `face` that has the edge (a, b); kNoFace on a border, a
    // non-manifold edge, or an edge of no face around the chosen vertices.
    uint32_t across(uint32_t face, uint32_t a, uint32_t b) const;
    size_t size() const { return size_; }  // edges

private:
    // Open addressing (linear probing) on the edge key: a walk step is one or two loads.
    static constexpr uint64_t kEmpty = ~uint64_t(0);  // no edge key (high word > low word)
    static constexpr uint32_t kMany = 0xfffffffeu;    // face[1] of a non-manifold edge
    struct Slot {
        std::atomic<uint64_t> key{kEmpty};
        std::atomic<uint32_t> face[2] = {kNoFace, kNoFace};
    };
    std::unique_ptr<Slot[]> slots_;
    size_t capacity_ = 0, size_ = 0;
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

    // Numerical tolerance (world units): a hit this close to the tested point along the ray is
    // taken to be at the point. 1e-5 × the bounding-box diagonal: above float rounding of
    // coordinates and ray parameters (~1e-7 relative), so a coincident copy of a surface (an
    // unwelded seam, z-fighting duplicates) does not hide its lines, yet 100× below a plate
    // 1e-3 of the model in front of another. It is not what keeps a line's own faces from
    // hiding it: that is PointOn, by topology.
    double tolerance() const { return tolerance_; }

    // Occlusion levels (quantitative invisibility, Appel 1967): for each query, the number of
    // surface crossings on the straight path from the viewer to the point (from the eye, or
    // from the near plane along the view direction when orthographic; starting at the near
    // plane either way, as GL clips), up to `cap` (a level ≥ cap is reported as cap, and the
    // ray stops there: cap 1 answers "hidden or not" at the cost of one occlusion ray).
    //   - Faces that contain the point (PointOn) do not count, nor hits within tolerance().
    //   - Hits at one point of the ray on faces sharing a vertex count once (a ray through a
    //     shared edge or vertex of an occluder crosses one surface, not two).
    //   - A contour sample's own fold does not count either. An interpolated contour (n·v = 0
    //     from vertex normals) is where the ray grazes the smooth surface the normals describe;
    //     the polygon mesh deviates from that surface, so near the point the mesh's cross-section
    //     in the plane of the ray and the normal wiggles across the ray's line (the contour often
    //     lies on a back-facing face just inside the polygon outline, behind a thin cap). Those
    //     crossings are found exactly: walking the cross-section both ways from the point while
    //     it stays within `fold_band` of the ray's line (a quarter pixel: what the image cannot
    //     tell from the line), the faces where it meets the line are the fold's. A surface that
    //     comes back to the ray after leaving that band — the tube of a torus in front of its
    //     inner contour, the sheet that hides a contour past a T-junction — counts. The walk
    //     crosses edges through `around` (contour_surroundings) and stops after 256 faces or
    //     where `around` has no neighbour (a border, a non-manifold edge, outside it).
    //   - A point's own surface a little in front of it does not count either: a hit less than
    //     OcclusionQuery::own_depth in front of the point, on a face joined to the point's own
    //     faces by edges within own_radius of it (own_neighbourhood.hpp). Such hits are held
    //     until the ray is traced, and only rays that have them run the point query. A sheet of
    //     another part, or of this part joined only farther away (a hem, a separate plate),
    //     hides the point at any distance beyond tolerance().
    //   - An interpolated contour sample is not hidden by a face touching its own that lies
    //     less than OcclusionQuery::slope_depth times that face's depth slope in
    //     front (rtsc's polygon offset, limited to the faces around the point).
    void occlusion_levels(const ImageProjection& view, const OcclusionQuery* queries, size_t count, uint8_t* levels,
                          int cap = 1, const EdgeNeighbours* around = nullptr) const;
    // One query; true when its level is ≥ 1.
    bool occluded(const ImageProjection& view, const glm::vec3& p, const PointOn& on = {}) const;

    // The nearest surface along the ray origin + t direction, t in (t_min, ∞) (units of
    // `direction`), as its face and t; none when the ray leaves the mesh (ray_first_hit.cpp).
    struct Hit {
        uint32_t face = 0;
        double t = 0.0;
    };
    std::optional<Hit> first_hit(const glm::dvec3& origin, const glm::dvec3& direction, double t_min) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    double tolerance_ = 0.0;
};

struct VisibilityOptions {
    // Largest image distance between two tested samples of a segment (pixels): a ~1 px gap
    // misses only occluders thinner than a pixel, which the PNG would not show either.
    float sample_spacing_px = 1.0f;
    // Bisection of a change of level stops when the bracket is this short (pixels): 1/16 px,
    // below what an antialiased stroke shows, in four rounds from a 1 px bracket (each round
    // costs as much as all the samples of the line near the change: its rays graze the edge
    // of an occluder).
    float transition_precision_px = 0.0625f;
    // Levels are counted up to this (RayScene::occlusion_levels' cap, 1..kMaxOcclusionLevel):
    // 1 tells visible from hidden at the cost of one occlusion ray per sample (hidden parts
    // then all have level 1).
    int count_levels_to = 1;
    // The segments are occluding contours (line type `contour`): their samples inside faces
    // and on edges ignore their fold (RayScene::occlusion_levels) within this many pixels.
    bool contour = false;
    float contour_fold_px = 0.25f;
    // Chains shorter than this in the image (pixels), when nothing can join them to more (a
    // loop, or both ends free: Chain::component), are left out untested: every visible or hidden
    // piece of them would be shorter too, and the caller drops such pieces (the line setting
    // `min-length`). On a scan most suggestive contours are such specks.
    float min_length_px = 0.0f;
    // A sample's own surface in front of it by less than this many pixels' depth (the world size
    // of a pixel at the sample's depth) does not hide it; its own neighbourhood is the surface
    // within `own_radius_px` pixels joined to the faces it lies on (OcclusionQuery::own_depth).
    float own_depth_px = 1.0f;
    float own_radius_px = 2.0f;
    // Contour samples: their own neighbourhood hides them only when in front by more than this
    // many pixels of the occluding face's depth slope (OcclusionQuery::slope_depth): rtsc
    // draws its lines against the mesh pushed back by glPolygonOffset(5, 30).
    float contour_slope_px = 5.0f;
    // Segments that are not contours but lie on the interpolated surface (suggestive contours)
    // get the same allowance: rtsc's offset lets them through the faces around them alike.
    bool own_slope = false;
};

// The segments' parts, split where the occlusion level changes. Parts keep the original node
// keys at unsplit ends, so chain_segments joins them as before; a split point gets a node key
// of its own (it ends a chain). Strength is interpolated linearly at split points. Parts
// outside the near/far range are dropped (the renderer clips them too), and so are chains
// shorter than options.min_length_px. Output order follows the input.
struct VisibilitySplit {
    std::vector<LineSegment> visible;    // level 0
    std::vector<LineSegment> hidden;     // level ≥ 1
    std::vector<uint8_t> hidden_levels;  // per hidden part: its level (≤ count_levels_to)
};

// Tests segments of `mesh` (the mesh of `scene`) seen through `view`; parallel over segments
// (TBB), deterministic. What each sample lies on (PointOn) comes from its segment and node
// keys: the segment's face(s) inside it, the faces of the mesh edge or vertex at a keyed end,
// the faces of the edge a crease or border runs along. `around`: contour_surroundings of these
// segments or of a list that includes them; built here when null and options.contour is set.
VisibilitySplit split_by_visibility(const RayScene& scene, const Mesh& mesh, const ImageProjection& view,
                                    const std::vector<LineSegment>& segments, const VisibilityOptions& options = {},
                                    const EdgeNeighbours* around = nullptr);

// The edges of the faces that share a vertex with a face of the contour segments (the lists of
// every contour type of a view; one scan of the triangles): where its fold walks go.
EdgeNeighbours contour_surroundings(const Mesh& mesh, const std::vector<const std::vector<LineSegment>*>& contours);

}  // namespace inkshade::geometry
