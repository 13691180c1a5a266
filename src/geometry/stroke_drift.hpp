// The drift of marks along coherent strokes between the frames of a sequence: how far, in
// pixels of arc length, a mark placed at u = k·period on a stroke moves along its matched stroke
// in the next frame beyond what the surface's motion explains — the swimming that a stroke
// parameterisation coherent in time removes (Kalnins et al. 2003, "Coherent Stylized
// Silhouettes"). For tests and benchmarks of stroke_coherence.hpp.
#pragma once
#include <string>
#include <vector>

#include "inkshade/line_drawing.hpp"

namespace inkshade::geometry {

enum class DriftExpectation {
    // A mark should stay where it is in the image: right when the lines themselves do not move,
    // as a sphere's contour seen from an orbit about its centre, the same circle every frame.
    SamePlace,
    // A mark should follow its surface point: projected with the next frame's camera, then the
    // nearest point of the next frame's strokes (a contour slides over the surface as the view
    // turns, so the surface point itself is off the new contour).
    Surface,
};

struct DriftOptions {
    std::string type = "contour";  // the layer measured (its visible strokes)
    float period_px = 20.0f;       // marks at u = k·period
    float radius_px = 8.0f;        // a mark whose expected place is farther from any stroke is unmatched
    DriftExpectation expect = DriftExpectation::SamePlace;
};

struct DriftReport {
    size_t marks = 0;            // marks placed, over every pair of consecutive frames
    size_t unmatched = 0;        // no stroke of the next frame near the expected place
    size_t lost = 0;             // the matched stroke of the next frame has no mark k
    std::vector<double> drifts;  // per measured mark, pixels of arc length
    double median_px = 0.0, p95_px = 0.0, max_px = 0.0;
};

// The drift over the consecutive frames of `frames` (each the StrokeSequence a draw left).
DriftReport measure_drift(const std::vector<StrokeSequence>& frames, const DriftOptions& options = {});

}  // namespace inkshade::geometry
