#include "render/frame.hpp"

#include <algorithm>

namespace inkshade::render {

const LineSettings* Frame::line(const std::string& type) const {
    const LineSettings* found = nullptr;
    for (const LineSettings& l : lines)
        if (l.type == type) found = &l;
    return found;
}

std::vector<LineSettings> object_lines_of(const std::vector<LineSettings>& lines, bool may_have_borders) {
    std::vector<LineSettings> out;
    const LineSettings* hull = nullptr;
    bool border = false;
    for (const LineSettings& l : lines) {
        if (line_type(l.type).space == LineSpace::Object) {
            out.push_back(l);
            // The strokes draw visible parts only (hidden ones are SVG-only): levels past 0 would
            // cost rays that go on past the first surface, for nothing.
            if (line_param(l, "min-level").at(0) == 0.0f) {
                out.back().params["max-level"] = {0.0f};
                out.back().params["hidden"] = {0.0f};
            }
        }
        if (l.type == "hull") hull = &l;
        border |= l.type == "border";
    }
    // An open border has no back face behind it for the hull to outline: the hull's `borders`
    // draws it as the object-space `border` type in the hull's stroke, with hidden parts removed.
    // Rims shorter than a few line widths are left out: a scan's sub-pixel folds and flaps have
    // borders too, and outlined they would be the specks the back-face rule keeps out.
    if (may_have_borders && hull && !border && line_param(*hull, "borders").at(0) != 0.0f) {
        const Stroke stroke = stroke_of(*hull);
        LineSettings b{.type = "border", .params = {}};
        b.params["color"] = {stroke.color.r, stroke.color.g, stroke.color.b};
        b.params["opacity"] = {stroke.opacity};
        b.params["width"] = {stroke.width};
        b.params["min-length"] = {std::max(4.0f * stroke.width, 16.0f)};
        out.push_back(std::move(b));
    }
    return out;
}

bool cull_back_faces(bool closed, const BoundingBox& b, const Camera& camera) {
    if (!closed) return false;
    const glm::mat4 view = camera.view();
    for (int i = 0; i < 8; ++i) {
        glm::vec3 p((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z);
        if (-(view * glm::vec4(p, 1.0f)).z <= camera.near_plane) return false;
    }
    return true;
}

}  // namespace inkshade::render
