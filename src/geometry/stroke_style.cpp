#include "geometry/stroke_style.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/dash_pattern.hpp"
#include "geometry/line_types/object_line_registry.hpp"
#include "geometry/stroke_noise.hpp"
#include "inkshade/error.hpp"

namespace inkshade::geometry {

namespace {

glm::vec2 pair_of(const LineSettings& s, const std::string& name) {
    const ParamValue& v = line_param(s, name);
    return v.size() >= 2 ? glm::vec2(v[0], v[1]) : glm::vec2(v.at(0));
}

glm::vec3 color_of(const LineSettings& s, const std::string& name) {
    const ParamValue& v = line_param(s, name);
    return {v.at(0), v.at(1), v.at(2)};
}

}  // namespace

StrokeModifiers StrokeModifiers::of(const LineSettings& s) {
    StrokeModifiers m;
    m.split.split_angle_degrees = line_number(s, "split-angle");
    m.split.max_length_px = line_number(s, "max-length");
    m.split.cusps = line_number(s, "split-cusps") != 0.0f;
    if (m.split.max_length_px > 0.0f && m.split.max_length_px < 1.0f)
        throw InputError(s.type + ": max-length must be 0 (off) or at least 1 px, got " +
                         format_number(m.split.max_length_px));

    StrokeThickness& t = m.thickness;
    t.width = stroke_of(s).width;
    t.strength_scales = line_number(s, "taper") != 0.0f;
    t.taper_in_px = line_number(s, "taper-in");
    t.taper_out_px = line_number(s, "taper-out");
    t.depth_factors = pair_of(s, "depth-width");
    t.curvature_factors = pair_of(s, "curvature-width");
    t.curvature_radius_px = line_number(s, "curvature-radius");
    t.level_factor = line_number(s, "level-width");
    t.calligraphy = line_number(s, "calligraphy");
    t.nib_angle_degrees = line_number(s, "nib-angle");
    t.noise = line_number(s, "noise");
    t.noise_period_px = line_number(s, "noise-period");
    t.seed = uint32_t(line_number(s, "seed"));

    m.color_along = ColorAlong(int(line_number(s, "color-along")));
    m.color = stroke_of(s).color;
    m.color_end = color_of(s, "color-end");

    m.sketch.passes = int(line_number(s, "sketch-passes"));
    m.sketch.jitter_px = line_number(s, "sketch-jitter");
    m.sketch.period_px = t.noise_period_px;
    m.sketch.seed = t.seed;

    const ParamValue& dash = line_param(s, "dash");
    double sum = 0.0;
    for (float v : dash) sum += double(v);
    if (sum > 0.0) {
        if (sum < 1.0)
            throw InputError(s.type + ": dash lengths must add up to at least 1 px (or be 0 for solid), got " +
                             format_param_value(*line_type(s.type).param("dash"), dash));
        m.dash.assign(dash.begin(), dash.end());
    }
    return m;
}

bool StrokeModifiers::reads_depth() const {
    return thickness.depth_factors.x != thickness.depth_factors.y || color_along == ColorAlong::Depth;
}

std::vector<LinePath> style_strokes(std::vector<LinePath> strokes, const StrokeModifiers& m,
                                    const ViewDepthRange& depth, uint32_t stream) {
    // Each stage only when asked for: the default layer keeps its paths without a copy.
    if (m.split.split_angle_degrees > 0.0f || m.split.max_length_px > 0.0f || m.split.cusps)
        strokes = split_chains(strokes, m.split);
    const bool widths = m.thickness.varies();
    if (widths || m.color_along != ColorAlong::None)
        for (size_t k = 0; k < strokes.size(); ++k) {
            LinePath& p = strokes[k];
            // A coherent stroke's noise is one per layer, read at its u (not its index here).
            const auto index = uint32_t(p.u.empty() ? k : 0);
            if (widths) p.width = stroke_widths(p, m.thickness, depth, noise_stream(stream, index));
            p.color = stroke_colors(p, m.color_along, m.color, m.color_end, depth);
        }
    if (m.sketch.passes > 1 || m.sketch.jitter_px > 0.0f) {
        SketchOptions sketch = m.sketch;
        sketch.seed = noise_stream(m.sketch.seed, stream);
        strokes = sketch_passes(strokes, sketch);
    }
    if (!m.dash.empty()) strokes = dash_paths(strokes, m.dash);
    return strokes;
}

std::vector<float> drawn_widths(const LinePath& path, const LineSettings& settings) {
    const size_t n = path.points.size();
    if (path.width.size() == n) return path.width;
    const float w = stroke_of(settings).width;
    std::vector<float> out(n, w);
    if (line_param(settings, "taper").at(0) != 0.0f && path.strength.size() == n)
        for (size_t i = 0; i < n; ++i)
            out[i] = w * std::clamp(std::isfinite(path.strength[i]) ? path.strength[i] : 1.0f, 0.0f, 1.0f);
    return out;
}

StrokeEnds stroke_ends(const LineSettings& settings) {
    return {StrokeCap(int(line_number(settings, "cap"))), StrokeJoin(int(line_number(settings, "join")))};
}

const char* cap_name(StrokeCap cap) {
    switch (cap) {
        case StrokeCap::Butt: return "butt";
        case StrokeCap::Square: return "square";
        default: return "round";
    }
}

const char* join_name(StrokeJoin join) {
    switch (join) {
        case StrokeJoin::Miter: return "miter";
        case StrokeJoin::Bevel: return "bevel";
        default: return "round";
    }
}

}  // namespace inkshade::geometry
