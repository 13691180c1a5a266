// The outline of a stroke whose width varies along it, as a filled shape: SVG strokes have one
// width, so a variable-width stroke is written as the area between its two offset curves
// (each point moved by half its width along the normal, corners joined as the stroke's join
// asks), closed by its caps. A loop's outline is two rings, the outer and the inner offset.
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "geometry/stroke_style.hpp"

namespace inkshade::io {

struct StrokeOutline {
    // Open: both sides from the stroke's start to its end (left = +normal, the normal being the
    // direction turned by +90° in image coordinates); closed: two rings, not repeating their
    // first point.
    std::vector<glm::vec2> left, right;
    bool closed = false;
};

// `widths` per point of `points` (pixels). Corners turning by more than kOutlineJoinDegrees are
// joined on their outer side as `join` asks (miter up to SVG's default miter limit 4, else
// bevel); smaller turns and the inner side take the offset along the bisector.
StrokeOutline stroke_outline(const std::vector<glm::vec2>& points, const std::vector<float>& widths, bool closed,
                             geometry::StrokeJoin join);

constexpr double kOutlineJoinDegrees = 5.0;
constexpr double kMiterLimit = 4.0;

}  // namespace inkshade::io
