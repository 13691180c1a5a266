// Splitting image chains into strokes (Freestyle's chain splitting: Operators.sequential_split
// by length, split at points of high curvature; Blender's line style "Split by angle" and "Max
// 2D length" settings): a sharp corner, a cusp of the projected line or a length limit ends a
// stroke, so the thickness modifiers, dashes and caps apply per stroke.
#pragma once
#include <vector>

#include "inkshade/line_drawing.hpp"

namespace inkshade::geometry {

struct ChainSplitOptions {
    // A vertex where the direction turns by more than this many degrees (between the segment
    // in and the segment out) ends a stroke there; 0 = never.
    float split_angle_degrees = 0.0f;
    // Strokes longer than this (pixels) are cut into equal pieces no longer; 0 = never.
    float max_length_px = 0.0f;
    // Split at cusps, where the image-space direction reverses: the direction over
    // kCuspChordPx before a vertex and the one after differ by more than kCuspTurnDegrees
    // (the most turning vertex of such a run). A projected contour has them where it turns
    // back behind its own surface (Koenderink 1984, "What does the occluding contour tell us
    // about solid shape?").
    bool cusps = false;
};

constexpr double kCuspChordPx = 2.0;
constexpr double kCuspTurnDegrees = 120.0;

// The strokes of `paths`: each split where `options` asks, pieces sharing their cut points;
// a closed path with a split point becomes open, starting at one.
std::vector<LinePath> split_chains(const std::vector<LinePath>& paths, const ChainSplitOptions& options);

}  // namespace inkshade::geometry
