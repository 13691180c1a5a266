// A drawing sheet: the paper a line drawing is laid out on (ISO 216 A sizes) and the drawing's
// scale (ISO 5455, "paper length : model length"), and the style's line unit. The sheet fixes
// the image's aspect, an orthographic camera's extent at a scale, and the SVG's size in mm.
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>

#include "inkshade/error.hpp"
#include "inkshade/scene.hpp"
#include "io/text_scanner.hpp"
#include "scene/option_name.hpp"

namespace inkshade {

namespace {

constexpr float kMaxPaperMm = 100000.0f;  // 100 m: a banner, not a typo's 1e30
// CSS pixels: what a length in mm is without a sheet (SVG user units at 96 per inch).
constexpr float kCssPixelsPerMm = 96.0f / 25.4f;

bool parse_positive(std::string_view text, float& out) {
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
    return !text.empty() && ec == std::errc() && ptr == text.data() + text.size() && std::isfinite(out) && out > 0.0f;
}

// Scales a length parameter of a line type from millimetres on paper to image pixels.
void scale_lengths(LineSettings& l, const char* param, float px_per_mm) {
    ParamValue value = line_param(l, param);
    for (float& v : value) v *= px_per_mm;
    l.params[param] = value;
}

}  // namespace

glm::vec2 parse_paper(const std::string& option, const std::string& text) {
    // ISO 216 A series, portrait width x height in mm.
    static constexpr std::array<std::pair<const char*, glm::vec2>, 6> kSizes = {{{"A0", {841, 1189}},
                                                                                 {"A1", {594, 841}},
                                                                                 {"A2", {420, 594}},
                                                                                 {"A3", {297, 420}},
                                                                                 {"A4", {210, 297}},
                                                                                 {"A5", {148, 210}}}};
    std::string name = text;
    bool portrait = false;
    for (const std::string suffix : {"-portrait", "-landscape"})
        if (name.size() > suffix.size() && name.ends_with(suffix)) {
            portrait = suffix == "-portrait";
            name.resize(name.size() - suffix.size());
            break;
        }
    for (const auto& [n, size] : kSizes)
        if (name.size() == 2 && std::toupper(static_cast<unsigned char>(name[0])) == 'A' && name[1] == n[1])
            return portrait ? size : glm::vec2(size.y, size.x);  // landscape unless asked
    // WxH in mm, as given (no orientation suffix).
    if (const size_t x = text.find('x'); x != std::string::npos && name == text) {
        glm::vec2 mm;
        if (parse_positive(std::string_view(text).substr(0, x), mm.x) &&
            parse_positive(std::string_view(text).substr(x + 1), mm.y) && mm.x <= kMaxPaperMm && mm.y <= kMaxPaperMm)
            return mm;
    }
    throw InputError(option + ": expected A0..A5 (landscape; -portrait for upright) or WxH in mm, got " +
                     io::quote_token(text));
}

float parse_drawing_scale(const std::string& option, const std::string& text) {
    const size_t colon = text.find(':');
    float paper = 0.0f, model = 0.0f;
    if (colon == std::string::npos || !parse_positive(std::string_view(text).substr(0, colon), paper) ||
        !parse_positive(std::string_view(text).substr(colon + 1), model) || !std::isfinite(paper / model) ||
        !(paper / model > 0.0f))
        throw InputError(option + ": expected PAPER:MODEL lengths such as 1:2 or 5:1, got " + io::quote_token(text));
    return paper / model;
}

void apply_drawing_sheet(const SceneRequest& r, Scene& scene) {
    auto name = [&](const char* option) { return option_name(r.names, option); };
    if (r.paper.empty()) {
        if (!r.drawing_scale.empty())
            throw InputError(name("scale") + ": a drawing's scale needs its sheet: give " + name("paper") + " too");
    } else {
        const glm::vec2 mm = parse_paper(name("paper"), r.paper);
        // The longer side keeps the requested size's longer side; the other follows the sheet.
        const float side = float(std::max(r.size.x, r.size.y));
        const float px_per_mm = side / std::max(mm.x, mm.y);
        scene.options.width = std::clamp(int(std::lround(mm.x * px_per_mm)), 1, 16384);
        scene.options.height = std::clamp(int(std::lround(mm.y * px_per_mm)), 1, 16384);
        scene.paper_mm = mm;
        scene.size_from_camera = false;  // the sheet, not a file camera, gives the aspect
        if (!r.drawing_scale.empty()) {
            const float scale = parse_drawing_scale(name("scale"), r.drawing_scale);
            for (auto [set, option] :
                 {std::pair{!r.file_camera.empty(), "camera"}, std::pair{bool(r.camera.ortho_height), "ortho-height"},
                  std::pair{bool(r.camera.distance), "distance"}})
                if (set)
                    throw InputError(name("scale") + " and " + name(option) +
                                     " are alternatives: a drawing to scale sets the view's extent");
            // A drawing to scale is a parallel projection; model units are millimetres.
            scene.camera.orthographic = true;
            scene.camera.ortho_height = float(scene.options.height) / px_per_mm / scale;
        }
    }
    if (scene.style.lines_in_mm) {
        const float px_per_mm = scene.paper_mm ? float(scene.options.width) / scene.paper_mm->x : kCssPixelsPerMm;
        for (std::vector<LineSettings>* lines : {&scene.style.lines, &scene.vector_lines})
            for (LineSettings& l : *lines)
                for (const char* param : {"width", "dash", "hidden-dash"})
                    if (line_type(l.type).param(param)) scale_lengths(l, param, px_per_mm);
        scene.style.lines_in_mm = false;  // now in pixels, as every renderer reads them
    }
}

}  // namespace inkshade
