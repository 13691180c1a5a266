// The stylised strokes of an object-space line layer: its per-layer stroke parameters
// (docs/lines.md, "Stylised strokes") read once from the settings, and the finishing of one
// level's image chains into strokes: split (chain_split.hpp) → widths (stroke_thickness.hpp) and
// colours (stroke_color.hpp) per point → sketchy passes (sketch_passes.hpp) → dashes
// (dash_pattern.hpp). Caps and joins are how writers and the GPU draw a stroke's ends and
// corners (stroke_ends).
#pragma once
#include <cstdint>
#include <vector>

#include "geometry/chain_split.hpp"
#include "geometry/sketch_passes.hpp"
#include "geometry/stroke_color.hpp"
#include "geometry/stroke_thickness.hpp"
#include "inkshade/line_drawing.hpp"

namespace inkshade::geometry {

enum class StrokeCap { Butt, Round, Square };
enum class StrokeJoin { Miter, Round, Bevel };

struct StrokeModifiers {
    ChainSplitOptions split;
    StrokeThickness thickness;
    ColorAlong color_along = ColorAlong::None;
    glm::vec3 color{0.0f}, color_end{0.0f};
    SketchOptions sketch;
    std::vector<float> dash;  // on, off, ... pixels; empty = solid

    // The modifiers of a layer's settings. Throws InputError (naming the type) for a dash
    // pattern that adds up to under 1 px or a max-length under 1 px (0 is off).
    static StrokeModifiers of(const LineSettings& settings);

    // Whether the view's depth range is read (depth factors or colour by depth).
    bool reads_depth() const;
};

// The strokes of one occlusion level of a layer (`paths` in image pixels). `stream` is mixed
// into the noise of every path so layers and levels do not share their noise.
std::vector<LinePath> style_strokes(std::vector<LinePath> paths, const StrokeModifiers& modifiers,
                                    const ViewDepthRange& depth, uint32_t stream);

// The width to draw at each point of `path` of a layer with `settings`: path.width when the
// modifiers set it, else the layer's width (times the strength with `taper`).
std::vector<float> drawn_widths(const LinePath& path, const LineSettings& settings);

struct StrokeEnds {
    StrokeCap cap = StrokeCap::Round;
    StrokeJoin join = StrokeJoin::Round;
};
StrokeEnds stroke_ends(const LineSettings& settings);

// SVG's names: "butt", "round", "square"; "miter", "round", "bevel".
const char* cap_name(StrokeCap cap);
const char* join_name(StrokeJoin join);

}  // namespace inkshade::geometry
