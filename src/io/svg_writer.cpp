// SVG 1.1 output of a LineDrawing (the object-space lines, hidden parts removed), laid out for
// Inkscape and Illustrator: one layer (<g inkscape:groupmode="layer">) per line type holding
// the stroke style, one <path> per polyline; a line set's layers (ids NAME-TYPE) nested in a
// layer of its own, <g id="lineset-NAME">.
//
// Variable strength: SVG strokes have one width and one opacity, so a polyline whose strength
// varies (suggestive contours fade in from their trim points) is split into runs of segments
// whose strength, quantised to eighths, is equal; each run is a <path> with the layer's
// opacity (or, with taper, width) times its level. Runs share their end points, so the line
// stays continuous; eighths keep the visible steps below what a 1–2 px stroke shows. Runs of
// level 0 are left out. A polyline of full strength is one path, closed with Z when it is a loop.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <map>
#include <numeric>
#include <string>
#include <system_error>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "geometry/brush_names.hpp"
#include "geometry/stroke_style.hpp"
#include "inkshade/line_drawing.hpp"
#include "io/atomic_file.hpp"
#include "io/bezier_fit.hpp"
#include "io/stroke_outline.hpp"

namespace inkshade {

namespace {

constexpr int kLevels = 8;

// Compact decimal: two decimals, trailing zeros dropped ("12.5", "3", never "-0").
// std::to_chars rounds the exact binary value to two decimals, ties to even, as printf's "%.2f"
// does, at a fraction of its cost (printf was half of the SVG writing); printf stays for what
// does not fit the buffer.
void append_number(std::string& out, double v) {
    char buf[64];
    if (std::abs(v) < 0.005) v = 0.0;
    char* end = nullptr;
    if (const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, 2);
        r.ec == std::errc() && std::isfinite(v))
        end = r.ptr;
    else
        end = buf + std::min(size_t(std::snprintf(buf, sizeof buf, "%.2f", v)), sizeof buf - 1);
    if (std::memchr(buf, '.', size_t(end - buf))) {
        while (end[-1] == '0') --end;
        if (end[-1] == '.') --end;
    }
    out.append(buf, end);
}

std::string number(double v) {
    std::string s;
    append_number(s, v);
    return s;
}

std::string hex_color(glm::vec3 c) {
    char buf[8];
    auto byte = [](float x) { return int(std::lround(255.0f * std::clamp(std::isfinite(x) ? x : 0.0f, 0.0f, 1.0f))); };
    std::snprintf(buf, sizeof buf, "#%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b));
    return buf;
}

std::string xml_escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default: out += c;
        }
    }
    return out;
}

bool finite_path(const LinePath& p) {
    for (const glm::vec2& q : p.points)
        if (!std::isfinite(q.x) || !std::isfinite(q.y)) return false;
    return p.points.size() >= 2;
}

// The points of p from index `first`, `count` segments on (indices modulo the size, for loops),
// with their widths and colours when `widths` / p.color are given.
struct Run {
    std::vector<glm::vec2> points;
    std::vector<float> widths;
    bool whole_loop = false;
};

Run run_of(const LinePath& p, const std::vector<float>& widths, size_t first, size_t count, bool whole_loop) {
    Run r;
    r.whole_loop = whole_loop;
    const size_t n = p.points.size();
    const size_t last = whole_loop ? count - 1 : count;
    for (size_t k = 0; k <= last; ++k) {
        r.points.push_back(p.points[(first + k) % n]);
        if (!widths.empty()) r.widths.push_back(widths[(first + k) % n]);
    }
    return r;
}

// SVG path data, compact: a command letter only where it changes ("M1 2 L3 4 5 6 C...").
class PathData {
public:
    void move(glm::dvec2 q) { command('M', {q}); }
    void line(glm::dvec2 q) { command('L', {q}); }
    void cubic(glm::dvec2 c1, glm::dvec2 c2, glm::dvec2 e) { command('C', {c1, c2, e}); }
    void close() {
        d_ += " Z";
        last_ = 'Z';
    }
    const std::string& text() const { return d_; }

private:
    void command(char c, std::initializer_list<glm::dvec2> pairs) {
        if (c != last_ || c == 'M') {
            if (!d_.empty()) d_ += ' ';
            d_ += c;
        } else {
            d_ += ' ';
        }
        last_ = c;
        bool first = true;
        for (glm::dvec2 q : pairs) {
            if (!first) d_ += ' ';
            first = false;
            append_number(d_, q.x);
            d_ += ' ';
            append_number(d_, q.y);
        }
    }
    std::string d_;
    char last_ = 0;
};

// How a curve begins: a new subpath, a line from the current point, or at the current point.
enum class Start { Move, Line, Here };

// `points` as a polyline, or with fitted cubic Béziers (pieces straight to 1/100 px as lines)
// unless the polyline's text is shorter (a coarse mesh's few-pixel segments: the points are
// already the most compact exact form); `close` ends the subpath with Z (a loop: its first point
// is passed again for the fit, not written again).
void append_curve(PathData& d, const std::vector<glm::vec2>& points, bool close, Start start,
                  const SvgOptions& options) {
    if (points.empty()) return;
    PathData poly = d;
    if (start == Start::Move) poly.move(glm::dvec2(points[0]));
    if (start == Start::Line) poly.line(glm::dvec2(points[0]));
    PathData fitted = poly;
    for (size_t k = 1; k < points.size(); ++k) poly.line(glm::dvec2(points[k]));
    if (close) poly.close();
    if (options.polylines || points.size() < 3) {
        d = std::move(poly);
        return;
    }
    std::vector<glm::vec2> fit = points;
    if (close) fit.push_back(points[0]);
    const std::vector<io::CubicBezier> pieces = io::fit_beziers(fit, options.max_error_px);
    for (size_t k = 0; k < pieces.size(); ++k) {
        const io::CubicBezier& b = pieces[k];
        const glm::dvec2 third = (b.p3 - b.p0) / 3.0;
        if (glm::length(b.p1 - (b.p0 + third)) < 0.005 && glm::length(b.p2 - (b.p3 - third)) < 0.005) {
            if (!(close && k + 1 == pieces.size())) fitted.line(b.p3);  // Z draws a loop's last line
            continue;
        }
        fitted.cubic(b.p1, b.p2, b.p3);
    }
    if (close) fitted.close();
    d = fitted.text().size() < poly.text().size() ? std::move(fitted) : std::move(poly);
}

// A stroke's cap from `a` (the left side's end) to `b` (the right side's), about the stroke's
// end point `centre` whose direction out of the stroke is `t` (unit).
void append_cap(PathData& d, glm::dvec2 a, glm::dvec2 b, glm::dvec2 centre, glm::dvec2 t, geometry::StrokeCap cap) {
    const double r = 0.5 * glm::length(b - a);
    if (r < 0.005 || cap == geometry::StrokeCap::Butt) {
        d.line(b);
        return;
    }
    if (cap == geometry::StrokeCap::Square) {
        d.line(a + t * r);
        d.line(b + t * r);
        d.line(b);
        return;
    }
    // Two quarter circles as cubics (control arms 0.5523 r put their midpoints on the circle).
    const double k = 0.5522847498 * r;
    const glm::dvec2 m = centre + t * r, towards_b = (b - a) / (2.0 * r);
    d.cubic(a + t * k, m - towards_b * k, m);
    d.cubic(m + towards_b * k, b + t * k, b);
}

// The filled outline of a variable-width run: left side, end cap, right side back, start cap.
std::string outline_data(const Run& run, const geometry::StrokeEnds& ends, bool open_ends, const SvgOptions& options) {
    const io::StrokeOutline o = io::stroke_outline(run.points, run.widths, run.whole_loop, ends.join);
    PathData d;
    if (o.left.size() < 2) return {};
    const std::vector<glm::vec2> right(o.right.rbegin(), o.right.rend());
    if (o.closed) {
        append_curve(d, o.left, true, Start::Move, options);
        append_curve(d, right, true, Start::Move, options);
        return d.text();
    }
    const geometry::StrokeCap cap = open_ends ? ends.cap : geometry::StrokeCap::Butt;
    auto direction = [](glm::vec2 from, glm::vec2 to) {
        const glm::dvec2 v = glm::dvec2(to) - glm::dvec2(from);
        const double l = glm::length(v);
        return l > 0.0 ? v / l : glm::dvec2(0.0);
    };
    const std::vector<glm::vec2>& pts = run.points;
    append_curve(d, o.left, false, Start::Move, options);
    append_cap(d, glm::dvec2(o.left.back()), glm::dvec2(o.right.back()), glm::dvec2(pts.back()),
               direction(pts[pts.size() - 2], pts.back()), cap);
    append_curve(d, right, false, Start::Here, options);
    append_cap(d, glm::dvec2(o.right.front()), glm::dvec2(o.left.front()), glm::dvec2(pts.front()),
               direction(pts[1], pts.front()), cap);
    d.close();
    return d.text();
}

// The strength level of segment k → k+1 of p.
int segment_level(const LinePath& p, size_t k) {
    if (p.strength.size() != p.points.size()) return kLevels;
    const size_t n = p.points.size();
    const float s = 0.5f * (p.strength[k] + p.strength[(k + 1) % n]);
    return int(std::lround(kLevels * std::clamp(std::isfinite(s) ? s : 1.0f, 0.0f, 1.0f)));
}

// The colour of segment k → k+1 of p as SVG hex ("" when the path has no colours).
std::string segment_color(const LinePath& p, size_t k) {
    if (p.color.size() != p.points.size()) return {};
    const size_t n = p.points.size();
    return hex_color(0.5f * (p.color[k] + p.color[(k + 1) % n]));
}

struct LayerStyle {
    Stroke stroke;
    bool taper = false;
    geometry::StrokeEnds ends;
    std::string color;  // the layer's colour, hex
};

void write_paths(std::string& out, const LinePath& p, const LineSettings& settings, const LayerStyle& style,
                 const SvgOptions& options) {
    if (!finite_path(p)) return;
    const size_t n = p.points.size();
    const size_t segments = p.closed ? n : n - 1;
    const std::vector<float> widths = geometry::drawn_widths(p, settings);
    // Runs of equal opacity level (strength, when it does not set the width) and colour, in
    // order; a loop's runs start at segment 0. With taper the strength is in the widths.
    auto level_of = [&](size_t k) { return style.taper ? kLevels : segment_level(p, k); };
    size_t k = 0;
    while (k < segments) {
        const int level = level_of(k);
        const std::string color = segment_color(p, k);
        size_t end = k + 1;
        while (end < segments && level_of(end) == level && segment_color(p, end) == color) ++end;
        const bool whole_loop = p.closed && k == 0 && end == segments;
        const Run run = run_of(p, widths, k, end - k, whole_loop);
        float wmin = run.widths.front(), wmax = wmin;
        for (float w : run.widths) {
            wmin = std::min(wmin, w);
            wmax = std::max(wmax, w);
        }
        const double f = double(level) / kLevels;
        const std::string paint = color.empty() ? style.color : color;
        if (level > 0 && wmax >= 0.005f) {  // what rounds to width 0 is not drawn
            if (wmax - wmin <= 0.01f) {
                PathData d;
                append_curve(d, run.points, whole_loop, Start::Move, options);
                out += "<path d=\"" + d.text() + "\"";
                if (std::abs(wmax - style.stroke.width) > 0.005f) out += " stroke-width=\"" + number(wmax) + "\"";
                if (level < kLevels) out += " stroke-opacity=\"" + number(style.stroke.opacity * f) + "\"";
                if (paint != style.color) out += " stroke=\"" + paint + "\"";
                out += "/>\n";
            } else {
                // The run's own ends are the stroke's only where the path ends.
                const bool open_ends = !p.closed && k == 0 && end == segments;
                const std::string d = outline_data(run, style.ends, open_ends, options);
                if (!d.empty())
                    out += "<path d=\"" + d + "\" fill=\"" + paint + "\" fill-opacity=\"" +
                           number(style.stroke.opacity * f) + "\" stroke=\"none\"/>\n";
            }
        }
        k = end;
    }
}

void write_layer(std::string& out, const std::string& id, const LineLayer& layer, const std::vector<LinePath>& paths,
                 bool hidden, const SvgOptions& options) {
    LayerStyle style;
    style.stroke = stroke_of(layer.settings);
    style.taper = line_param(layer.settings, "taper").at(0) != 0.0f;
    style.ends = geometry::stroke_ends(layer.settings);
    style.color = hex_color(style.stroke.color);
    const Stroke& stroke = style.stroke;
    out += "<g id=\"" + xml_escape(id) + "\" inkscape:groupmode=\"layer\" inkscape:label=\"" + xml_escape(id) +
           "\" fill=\"none\" stroke=\"" + style.color + "\" stroke-opacity=\"" + number(stroke.opacity) +
           "\" stroke-width=\"" + number(stroke.width) + "\" stroke-linecap=\"" + geometry::cap_name(style.ends.cap) +
           "\" stroke-linejoin=\"" + geometry::join_name(style.ends.join) + "\"";
    // A raster brush has no SVG equivalent: the outline stays the stroke's, the brush is named
    // for tools that can draw it.
    if (const size_t brush = size_t(line_param(layer.settings, "brush").at(0)); brush > 0) {
        out += " data-brush=\"" + geometry::brush_names().at(brush) + "\"";
        if (const float length = line_param(layer.settings, "brush-length").at(0); length > 0.0f)
            out += " data-brush-length=\"" + number(length) + "\"";
    }
    // Hidden levels are dashed by the viewer unless the layer's own dash pattern already cut
    // its strokes into dashes.
    const auto total = [](const ParamValue& pattern) { return std::accumulate(pattern.begin(), pattern.end(), 0.0); };
    if (hidden && total(line_param(layer.settings, "dash")) <= 0.0) {
        const ParamValue& pattern = line_param(layer.settings, "hidden-dash");
        std::string dashes;
        if (total(pattern) > 0.0) {
            for (float v : pattern) dashes += (dashes.empty() ? "" : " ") + number(v);
        } else {
            // Dashes scale with the stroke so thick hidden lines still read as dashed.
            const double w = std::max(double(stroke.width), 1.0);
            dashes = number(3.0 * w) + " " + number(2.0 * w);
        }
        out += " stroke-dasharray=\"" + dashes + "\"";
    }
    out += ">\n";
    // Each path's text (its Bézier fit most of the work) is made on its own, in parallel, and
    // joined in the paths' order, so the file does not depend on the thread count.
    std::vector<std::string> texts(paths.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, paths.size(), 8), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t i = r.begin(); i != r.end(); ++i) write_paths(texts[i], paths[i], layer.settings, style, options);
    });
    size_t length = out.size() + 5;
    for (const std::string& t : texts) length += t.size();
    out.reserve(length);
    for (const std::string& t : texts) out += t;
    out += "</g>\n";
}

// The visible faces' regions, one path per material (outlines and holes, even-odd), in a
// layer under the strokes.
void write_fills(std::string& out, const std::vector<FillRegion>& fills) {
    if (fills.empty()) return;
    out +=
        "<g id=\"fills\" inkscape:groupmode=\"layer\" inkscape:label=\"fills\" stroke=\"none\" "
        "fill-rule=\"evenodd\">\n";
    for (const FillRegion& region : fills) {
        std::string d;
        for (const std::vector<glm::vec2>& ring : region.rings) {
            for (size_t i = 0; i < ring.size(); ++i)
                d += (i == 0 ? (d.empty() ? "M" : " M") : " L") + number(ring[i].x) + " " + number(ring[i].y);
            d += " Z";
        }
        out += "<path id=\"fill-" + std::to_string(region.material) + "\" fill=\"" + hex_color(region.color) +
               "\" d=\"" + d + "\"/>\n";
    }
    out += "</g>\n";
}

}  // namespace

std::string format_svg(const LineDrawing& drawing, glm::vec4 background, const SvgOptions& options) {
    const std::string w = std::to_string(drawing.width), h = std::to_string(drawing.height);
    // On a drawing sheet the document is the paper's size in mm; the viewBox stays in pixels.
    const bool sheet = drawing.paper_mm.x > 0.0f && drawing.paper_mm.y > 0.0f;
    const std::string size_w = sheet ? number(drawing.paper_mm.x) + "mm" : w;
    const std::string size_h = sheet ? number(drawing.paper_mm.y) + "mm" : h;
    std::string out;
    out += "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n";
    out +=
        "<svg xmlns=\"http://www.w3.org/2000/svg\" "
        "xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" version=\"1.1\" width=\"" +
        size_w + "\" height=\"" + size_h + "\" viewBox=\"0 0 " + w + " " + h + "\">\n";
    if (background.a > 0.0f)
        out += "<rect id=\"background\" x=\"0\" y=\"0\" width=\"" + w + "\" height=\"" + h + "\" fill=\"" +
               hex_color(glm::vec3(background)) + "\"" +
               (background.a < 1.0f ? " fill-opacity=\"" + number(background.a) + "\"" : std::string()) + "/>\n";
    write_fills(out, drawing.fills);
    // Each type's hidden layers (one per occlusion level that has paths, TYPE-hidden-N) go
    // below its visible one, the deepest lowest. A line set's consecutive layers share its group.
    const std::vector<LineLayer>& layers = drawing.layers;
    for (size_t i = 0; i < layers.size(); ++i) {
        const LineLayer& layer = layers[i];
        const std::string& set = layer.settings.lineset;
        if (!set.empty() && (i == 0 || layers[i - 1].settings.lineset != set))
            out += "<g id=\"lineset-" + xml_escape(set) + "\" inkscape:groupmode=\"layer\" inkscape:label=\"" +
                   xml_escape(set) + "\">\n";
        const std::string id = set.empty() ? layer.settings.type : set + "-" + layer.settings.type;
        std::map<int, std::vector<LinePath>, std::greater<int>> by_level;
        for (const LinePath& p : layer.hidden) by_level[std::max(p.level, 1)].push_back(p);
        for (const auto& [level, paths] : by_level)
            write_layer(out, id + "-hidden-" + std::to_string(level), layer, paths, true, options);
        write_layer(out, id, layer, layer.visible, false, options);
        if (!set.empty() && (i + 1 == layers.size() || layers[i + 1].settings.lineset != set)) out += "</g>\n";
    }
    out += "</svg>\n";
    return out;
}

void write_svg(const std::string& path, const LineDrawing& drawing, glm::vec4 background, const SvgOptions& options) {
    io::write_file_atomic(path, format_svg(drawing, background, options));
}

}  // namespace inkshade
