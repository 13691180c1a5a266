// Piecewise cubic Bézier curves fitted to a polyline within a distance, after Schneider 1990,
// "An Algorithm for Automatically Fitting Digitized Curves" (Graphics Gems): chord-length
// parameters, least-squares control points along fixed end tangents, Newton–Raphson
// reparameterisation, and a split at the worst point when the fit is still too far. The SVG
// writer draws lines with them: far fewer numbers than the polyline at the same accuracy.
#pragma once
#include <vector>

#include <glm/glm.hpp>

namespace inkshade::io {

struct CubicBezier {
    glm::dvec2 p0, p1, p2, p3;
    glm::dvec2 at(double t) const;
};

// Cubic pieces, end to start, from the first to the last point of the open polyline `points`
// (a loop passes its first point again at the end). Every point of the polyline lies within
// `max_error` pixels of the curve at its parameter, and the curve halfway between two points'
// parameters within `max_error` of the segment between them. Vertices where the direction turns
// by more than kBezierCornerDegrees stay corners (a piece ends there). Repeated points are
// skipped; fewer than two distinct points give no piece.
std::vector<CubicBezier> fit_beziers(const std::vector<glm::vec2>& points, double max_error);

constexpr double kBezierCornerDegrees = 60.0;

}  // namespace inkshade::io
