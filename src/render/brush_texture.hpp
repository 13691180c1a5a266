// A brush of GPU strokes (render/stroke_pass.hpp): a grey image whose u runs along the stroke
// (repeated every brush length of arc length) and v across it, edge to edge; a texel is the
// fraction of the stroke's coverage kept. The shipped brushes are the PNGs of data/brushes/
// (made by scripts/make-brushes), embedded into the binary.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace inkshade::render {

struct BrushImage {
    int width = 0;              // along the stroke
    int height = 0;             // across it
    std::vector<uint8_t> grey;  // width * height, row-major, top row (one edge) first
};

// The shipped brush `name` (geometry::brush_names() other than "none"), decoded once; null
// for "none" or an unknown name.
const BrushImage* shipped_brush(const std::string& name);

}  // namespace inkshade::render
