// Sketchy strokes: each stroke drawn several times, every pass a copy displaced by smooth
// seeded noise along its arc length, as an artist goes over a line again (Freestyle's
// SpatialNoiseShader and Blender's "Spatial Noise" and "Sinus Displacement" geometry
// modifiers; the repeated strokes after Markosian et al. 1997, "Real-Time Nonphotorealistic
// Rendering"). Deterministic: the same seed gives the same strokes.
#pragma once
#include <cstdint>
#include <vector>

#include "inkshade/line_drawing.hpp"

namespace inkshade::geometry {

struct SketchOptions {
    int passes = 1;           // copies of every stroke
    float jitter_px = 0.0f;   // the largest displacement of any point (pixels)
    float period_px = 50.0f;  // the noise's wavelength along the stroke
    uint32_t seed = 0;
};

// `paths` with every path replaced by `passes` displaced copies (in order: the copies of the
// first path, then of the second, ...). Each point moves by at most jitter_px. With one pass and
// no jitter the paths are returned unchanged.
std::vector<LinePath> sketch_passes(const std::vector<LinePath>& paths, const SketchOptions& options);

}  // namespace inkshade::geometry
