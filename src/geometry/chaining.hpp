// Chaining line segments into polylines by the node key each endpoint carries (a mesh edge for
// isolines, a vertex for crease and border edges), then the clean-ups a drawing wants: dropping
// tiny chains and smoothing.
#pragma once
#include <vector>

#include "geometry/contours.hpp"

namespace inkshade::geometry {

struct Polyline {
    std::vector<glm::vec3> points;  // a closed polyline does not repeat its first point
    std::vector<float> strength;    // per point, parallel to points (segment end strengths)
    // Per point when chain_segments is asked for them, else empty: the face of the segment
    // from the point to the next (the last point of an open polyline: of the segment ending
    // there); LineSegment::face.
    std::vector<uint32_t> faces;
    bool closed = false;
};

// A chain of segments, in walking order: segment `segments[i]` is walked b → a when
// `reversed[i]`. A closed chain comes back to the node it starts from.
struct Chain {
    std::vector<uint32_t> segments;
    std::vector<uint8_t> reversed;
    bool closed = false;
    // The chain is the whole of its connected piece of the segment graph: a loop, or open with
    // both end nodes free (no other segment there). Only such a chain bounds every polyline that
    // a subset of its segments can be chained into.
    bool component = false;
};

// The chains chain_segments makes (same order, same directions), as segment indices. Segments
// whose two ends share a key are left out.
std::vector<Chain> chain_order(const std::vector<LineSegment>& segments);

// Joins segments that share a node key, on the same LineSegment::isoline, into polylines, in
// O(n) (hash map from key to segment ends). A node with one segment end, or more than two
// (non-manifold, crease junction), ends a chain; chains through nodes of degree two only are
// closed loops. Output order is deterministic: first the open chains, in the order of the
// first segment end (by segment index, a before b) at a chain-ending node; then the loops, by
// their lowest segment index. Each polyline runs along its first segment's a → b direction
// (an open chain walked from that segment's b end is reversed), so on a consistently oriented
// mesh a contour keeps the front-facing side on its left. A point takes the strength of the
// segment end it came from. Segments whose two ends share a key are dropped. With `faces`, each
// polyline's Polyline::faces too.
std::vector<Polyline> chain_segments(const std::vector<LineSegment>& segments, bool faces = false);

// Polyline length in the units of its points, the closing step of a loop included.
float polyline_length(const Polyline& line);

// Removes polylines shorter than min_length (world units, or whatever the points are in — a
// caller may pass projected points to drop by pixels): the specks that noise in curvature
// leaves behind (DeCarlo et al. 2003 §4 discard short suggestive-contour pieces likewise).
// Order of the kept polylines is unchanged.
std::vector<Polyline> drop_short(std::vector<Polyline> polylines, float min_length);

// Laplacian smoothing of each polyline's points, `iterations` times, moving each point by
// `weight` (0..1) towards the midpoint of its neighbours; the two ends of an open polyline stay
// fixed so chains still meet at junctions. Removes the small zig-zag that per-face linear
// interpolation of noisy values leaves; a loop shrinks by about weight·(1 − cos(2π/n)) of its
// radius per iteration, negligible for the hundreds of points a contour has. Strengths are
// not changed.
void smooth_polylines(std::vector<Polyline>& polylines, int iterations, float weight = 0.5f);

}  // namespace inkshade::geometry
