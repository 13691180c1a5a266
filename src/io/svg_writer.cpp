// SVG 1.1 output of a LineDrawing (the object-space lines, hidden parts removed), laid out for
// Inkscape and Illustrator: one layer (<g inkscape:groupmode="layer">) per line type holding
// the stroke style, one <path> per polyline.
//
// Variable strength: SVG strokes have one width and one opacity, so a polyline whose strength
// varies (suggestive contours fade in from their trim points) is split into runs of segments
// whose strength, quantised to eighths, is equal; each run is a <path> with the layer's
// opacity (or, with taper, width) times its level. Runs share their end points, so the line
// stays continuous; eighths keep the visible steps below what a 1–2 px stroke shows. Runs of
// level 0 are left out. A polyline of full strength is one path, closed with Z when it is a loop.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <string>

#include "inkshade/line_drawing.hpp"
#include "io/atomic_file.hpp"

namespace inkshade {

namespace {

constexpr int kLevels = 8;

// Compact decimal: two decimals, trailing zeros dropped ("12.5", "3", never "-0").
void append_number(std::string& out, double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", std::abs(v) < 0.005 ? 0.0 : v);
    std::string s(buf);
    if (s.find('.') != std::string::npos) {
        while (s.back() == '0') s.pop_back();
        if (s.back() == '.') s.pop_back();
    }
    out += s;
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

// Path data "M x y L x y x y ..." through points[first .. first + count] (indices modulo the
// size, for loops); " Z" closes a whole loop instead of repeating its first point.
std::string path_data(const LinePath& p, size_t first, size_t count, bool close) {
    std::string d;
    const size_t n = p.points.size();
    const size_t last = close ? count - 1 : count;
    for (size_t k = 0; k <= last; ++k) {
        const glm::vec2 q = p.points[(first + k) % n];
        d += k == 0 ? "M" : (k == 1 ? " L" : " ");
        append_number(d, q.x);
        d += ' ';
        append_number(d, q.y);
    }
    if (close) d += " Z";
    return d;
}

// The strength level of segment k → k+1 of p.
int segment_level(const LinePath& p, size_t k) {
    if (p.strength.size() != p.points.size()) return kLevels;
    const size_t n = p.points.size();
    const float s = 0.5f * (p.strength[k] + p.strength[(k + 1) % n]);
    return int(std::lround(kLevels * std::clamp(std::isfinite(s) ? s : 1.0f, 0.0f, 1.0f)));
}

void write_paths(std::string& out, const LinePath& p, const Stroke& stroke, bool taper) {
    if (!finite_path(p)) return;
    const size_t n = p.points.size();
    const size_t segments = p.closed ? n : n - 1;
    // Runs of equal level, in order; a loop's runs start at segment 0.
    size_t k = 0;
    while (k < segments) {
        const int level = segment_level(p, k);
        size_t end = k + 1;
        while (end < segments && segment_level(p, end) == level) ++end;
        if (level > 0) {
            const bool whole_loop = p.closed && k == 0 && end == segments;
            out += "<path d=\"" + path_data(p, k, end - k, whole_loop) + "\"";
            if (level < kLevels) {
                const double f = double(level) / kLevels;
                out += taper ? " stroke-width=\"" + number(stroke.width * f) + "\""
                             : " stroke-opacity=\"" + number(stroke.opacity * f) + "\"";
            }
            out += "/>\n";
        }
        k = end;
    }
}

void write_layer(std::string& out, const std::string& id, const LineLayer& layer, const std::vector<LinePath>& paths,
                 bool hidden) {
    const Stroke stroke = stroke_of(layer.settings);
    const bool taper = line_param(layer.settings, "taper").at(0) != 0.0f;
    out += "<g id=\"" + xml_escape(id) + "\" inkscape:groupmode=\"layer\" inkscape:label=\"" + xml_escape(id) +
           "\" fill=\"none\" stroke=\"" + hex_color(stroke.color) + "\" stroke-opacity=\"" + number(stroke.opacity) +
           "\" stroke-width=\"" + number(stroke.width) + "\" stroke-linecap=\"round\" stroke-linejoin=\"round\"";
    if (hidden) {
        // Dashes scale with the stroke so thick hidden lines still read as dashed.
        const double w = std::max(double(stroke.width), 1.0);
        out += " stroke-dasharray=\"" + number(3.0 * w) + " " + number(2.0 * w) + "\"";
    }
    out += ">\n";
    for (const LinePath& p : paths) write_paths(out, p, stroke, taper);
    out += "</g>\n";
}

}  // namespace

std::string format_svg(const LineDrawing& drawing, glm::vec4 background) {
    const std::string w = std::to_string(drawing.width), h = std::to_string(drawing.height);
    std::string out;
    out += "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n";
    out +=
        "<svg xmlns=\"http://www.w3.org/2000/svg\" "
        "xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" version=\"1.1\" width=\"" +
        w + "\" height=\"" + h + "\" viewBox=\"0 0 " + w + " " + h + "\">\n";
    if (background.a > 0.0f)
        out += "<rect id=\"background\" x=\"0\" y=\"0\" width=\"" + w + "\" height=\"" + h + "\" fill=\"" +
               hex_color(glm::vec3(background)) + "\"" +
               (background.a < 1.0f ? " fill-opacity=\"" + number(background.a) + "\"" : std::string()) + "/>\n";
    // Each type's hidden layers (one per occlusion level that has paths, TYPE-hidden-N) go
    // below its visible one, the deepest lowest.
    for (const LineLayer& layer : drawing.layers) {
        std::map<int, std::vector<LinePath>, std::greater<int>> by_level;
        for (const LinePath& p : layer.hidden) by_level[std::max(p.level, 1)].push_back(p);
        for (const auto& [level, paths] : by_level)
            write_layer(out, layer.settings.type + "-hidden-" + std::to_string(level), layer, paths, true);
        write_layer(out, layer.settings.type, layer, layer.visible, false);
    }
    out += "</svg>\n";
    return out;
}

void write_svg(const std::string& path, const LineDrawing& drawing, glm::vec4 background) {
    io::write_file_atomic(path, format_svg(drawing, background));
}

}  // namespace inkshade
