// Temporal coherence of stylised strokes: a stroke parameter u per path that follows the
// previous frame's, so what varies along a stroke (dashes, the brush texture, width noise,
// sketch jitter) stays on the surface in a turntable or an animation instead of restarting at
// each chain's start, which moves from frame to frame (Kalnins, Davidson, Markosian & Finkelstein
// 2003, "Coherent Stylized Silhouettes"). As there, the previous frame's samples are carried to
// the new frame by the surface: their 3D points projected with the new camera; each sample of a
// new path votes for the u of the nearest such sample, and the path takes the u the largest
// consistent group of votes agrees on. Kalnins fit a stretch per path as well; here u is rigid,
// u = offset + arc length (scale 1), so a dash keeps its length in pixels.
#pragma once
#include <functional>
#include <vector>

#include "inkshade/line_drawing.hpp"

namespace inkshade::geometry {

struct CoherenceOptions {
    float radius_px = 8.0f;          // a vote comes from a previous sample at most this far away
    float min_direction_cos = 0.7f;  // |cos| of the angle between the two samples' image directions
    float spacing_px = 2.0f;         // samples along the paths, old and new
    float window_px = 8.0f;          // votes within ±window of one another agree
    float min_fraction = 0.2f;       // a path follows a previous one when this share of its samples agree
};

// Where the previous frame's surface points fall in this frame's image (pixels).
using ProjectPoint = std::function<glm::vec2(const glm::vec3&)>;

// Sets `u` on each of `paths` (one level of one layer, in image pixels; `world` per point when
// the previous frame's points are to be projected, else their image points are used). A path
// matched to a previous one gets u = offset + arc length with the offset the votes agree on,
// and may be reversed (votes against its direction) or, when closed, start anew where its
// previous match started, so the seam does not move; a path without enough votes gets u = arc
// length from its start. `previous`: the same layer's paths of the previous frame, with u.
void parameterise_paths(std::vector<LinePath>& paths, const std::vector<LinePath>& previous,
                        const ProjectPoint& project, const CoherenceOptions& options = {});

// The path with its points in the reverse order (closed: starting at the same point), every
// per-point attribute with them but u, which is dropped: it must increase along a path.
LinePath reversed(const LinePath& path);

// A closed path starting at arc length s (a point inserted there unless it is a vertex), still
// closed; attributes interpolated, u (when set) kept increasing as rotated() keeps it.
LinePath rotated_at(const LinePath& path, double s);

}  // namespace inkshade::geometry
