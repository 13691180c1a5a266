// What object-space line types extract from: one mesh (positions, triangles, unit vertex
// normals, face materials) and what is derived from it alone — edge adjacency, curvature, creases,
// intersections — computed on first use and kept, so later views of the same mesh pay only
// per-view work. The one exception is a large adjacency (over kKeepAdjacencyBytes): only
// creases and borders read it, so it is dropped once they are classified and rebuilt if
// another crease angle is asked for.
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geometry/adjacency.hpp"
#include "geometry/creases.hpp"
#include "geometry/curvature.hpp"
#include "geometry/hard_edge_contours.hpp"
#include "geometry/hatching.hpp"
#include "geometry/ridges.hpp"
#include "inkshade/mesh.hpp"

namespace inkshade::geometry {

// The mesh-wide data a line type reads besides positions and normals.
struct MeshLineNeeds {
    bool adjacency = false;                              // creases, borders
    bool curvature = false;                              // suggestive contours, ridges, valleys
    float crease_angle = CreaseOptions{}.angle_degrees;  // classified by prepare() with adjacency
    bool intersections = false;                          // intersection lines
};

class MeshLineData {
public:
    // Copies positions and triangles (so the caller's mesh may go away); keeps the mesh's
    // normals when sane (renormalised), else computes angle-weighted ones.
    explicit MeshLineData(const Mesh& mesh);
    // The same, taking positions, triangles and normals from `mesh` (the rest is dropped).
    explicit MeshLineData(Mesh&& mesh);
    // Shares `mesh`, whose normals must already be unit (ensure_vertex_normals; when they are
    // not even sane, a copy is made as above). Only positions, triangles, normals and face materials are read.
    explicit MeshLineData(std::shared_ptr<const Mesh> mesh);

    // Positions, triangles, unit normals, face materials, materials (names and colours) and
    // loose line segments (colours or uvs are there when shared, unread).
    const Mesh& mesh() const { return *mesh_; }
    const std::vector<glm::vec3>& normals() const { return mesh_->normals; }

    // Drops everything derived from the mesh (recomputed when next needed).
    void release_derived();

    // Adjacency past this size (about 2.6 M triangles) is dropped after crease classification.
    static constexpr size_t kKeepAdjacencyBytes = size_t(64) << 20;

    // Computes what `needs` asks for and is not cached yet, the two at once when both are
    // missing: adjacency is a serial counting sort and curvature a parallel loop, so on a
    // first view the sort runs beside the curvature threads instead of after them. With
    // adjacency, creases are classified at needs.crease_angle. `then` runs on the adjacency's
    // side after it (dropped when large): LineExtractor builds its ray scene there, beside the
    // curvature but never beside a 10 M-triangle adjacency (issue 9's memory budget).
    // Intersection lines, which read nothing else, are a third task up to
    // kOverlapTriangles; above it they wait for their extractor, so their BVH is never held
    // beside the adjacency.
    void prepare(MeshLineNeeds needs, const std::function<void()>& then = {});
    static constexpr size_t kOverlapTriangles = size_t(1) << 20;

    const EdgeAdjacency& adjacency();
    const Curvature& curvature();  // Rusinkiewicz 2004, from normals()
    // The automatic feature size of the curvature-based lines (rtsc's, feature_size.hpp), kept
    // with the curvature.
    float feature_size();
    // Crease classification at `angle_degrees` (the last angle asked for is kept).
    const CreaseLines& creases(float angle_degrees);
    // Border edges: from the cached crease classification whatever its angle (borders do
    // not depend on it), computed at the default angle when there is none yet.
    const std::vector<LineSegment>& borders();
    // Ridges and valleys with these options (the last options asked for are kept).
    const RidgeLines& ridges(const RidgeOptions& options);
    // The hard edges the contour reads on a mesh with hard edges (hard_edge_table).
    const HardEdgeTable& hard_edges();
    // Where two surfaces of the mesh cross (extract_intersections; view-independent).
    const std::vector<LineSegment>& intersections();
    // The object of each face (connected_objects.hpp), for silhouette and external-contour.
    const std::vector<uint32_t>& face_objects();
    // Hatching strokes with these options (trace_hatching; the last options asked for are kept).
    const Hatching& hatching(const HatchOptions& options);
    // normals() smoothed at each of `sigmas` (multiscale_normals; the last widths asked for are
    // kept): the shading-scales AOV's.
    const std::vector<std::vector<glm::vec3>>& smoothed_normals(const std::vector<float>& sigmas);

    // Names and milliseconds of the lazy computations done since the last call (for
    // LineExtractor's timings), then cleared.
    std::vector<std::pair<std::string, double>> take_setup_timings();

private:
    using TimingLog = std::vector<std::pair<std::string, double>>;
    const EdgeAdjacency& adjacency(TimingLog& log);
    const Curvature& curvature(TimingLog& log);
    const CreaseLines& creases(float angle_degrees, TimingLog& log);
    const std::vector<LineSegment>& intersections(TimingLog& log);

    std::shared_ptr<const Mesh> mesh_;
    std::optional<EdgeAdjacency> adjacency_;
    std::optional<Curvature> curvature_;
    float feature_size_ = 1.0f;  // with curvature_
    std::optional<CreaseLines> creases_;
    float crease_angle_ = 0.0f;
    std::optional<RidgeLines> ridges_;
    RidgeOptions ridge_options_;
    std::optional<std::vector<LineSegment>> intersections_;
    std::optional<HardEdgeTable> hard_edges_;
    std::optional<Hatching> hatching_;
    std::optional<std::vector<uint32_t>> face_objects_;
    HatchOptions hatch_options_;
    std::optional<std::vector<std::vector<glm::vec3>>> smoothed_normals_;
    std::vector<float> smoothing_sigmas_;
    TimingLog setup_timings_;
};

}  // namespace inkshade::geometry
