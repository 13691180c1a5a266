// Line types: a registry of named line types, each with a parameter table (inkshade/params.hpp)
// like the shading models. A style lists the line types it draws ([[lines]] tables); each type
// registers itself from the file that implements it, so adding one touches nothing else.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "inkshade/params.hpp"

namespace inkshade {

enum class LineSpace {
    Image,   // raster lines found per pixel on the GPU (hull, rim-contour, edges, ...)
    Object,  // vector polylines from the mesh (contour, suggestive, crease, ...): SVG and strokes
};

struct LineType {
    std::string name;     // as written in [[lines]] type = "..." and --lines
    std::string summary;  // one line: what it draws and where the definition comes from
    LineSpace space = LineSpace::Image;
    std::vector<ParamSpec> params;  // stroke_params(...) first, then the type's own

    const ParamSpec* param(const std::string& name) const;
};

// The stroke parameters every line type has: "color", "opacity" and "width" (pixels).
std::vector<ParamSpec> stroke_params(glm::vec3 color, float width_px);

// The deepest occlusion level counted (how many surfaces lie in front of a line; 0 = visible):
// an object-space type's min-level and max-level go up to it, a level of it means "this deep or
// deeper".
constexpr int kMaxOcclusionLevel = 253;

// Which faces a line set draws on (docs/styles.md, "Line sets"): a face is selected when it
// matches every criterion given (a list matches when any of its glob patterns does, `*` any
// run of characters, `?` one character); no criterion selects every face. `invert` selects the
// faces that do not match instead (Freestyle's exclusive selection).
struct FaceSelection {
    std::vector<std::string> materials;  // Mesh::materials[...].name
    std::vector<std::string> objects;    // Mesh::object_names (glTF node, OBJ `o`/`g`)
    // Mesh::face_marks: 0 selects unmarked faces, -1 any marked face (1..255), else that mark.
    std::optional<int> face_mark;
    bool invert = false;
    bool everything() const { return materials.empty() && objects.empty() && !face_mark && !invert; }
    bool operator==(const FaceSelection&) const = default;
};

// One line type of a style with its parameter values (missing names take the defaults), and
// the line set it belongs to: its name ("" for the style's own [[lines]]) and face selection.
// An object-space line is drawn where it lies on a selected face (docs/styles.md).
struct LineSettings {
    std::string type;
    ParamValues params;
    std::string lineset;
    FaceSelection faces;
};

// The line sets `lines` draws, in order, each once: their names ("" for lines of no line set,
// the style's own [[lines]]).
std::vector<std::string> line_set_names(const std::vector<LineSettings>& lines);

// "*" and "?" glob matching of a whole name (case-sensitive, as names in files are).
bool glob_match(std::string_view pattern, std::string_view name);

// The stroke every line type has, resolved from its settings (defaults filled in).
struct Stroke {
    glm::vec3 color{0.0f};
    float opacity = 1.0f;
    float width = 1.0f;  // pixels
};
Stroke stroke_of(const LineSettings& settings);

// All registered line types, alphabetically.
std::vector<const LineType*> line_types();
// Throws InputError("unknown line type 'x' (choose ...)") when absent.
const LineType& line_type(const std::string& name);

// The value of parameter `name` of `settings` (given or default); throws std::logic_error when
// the type has no such parameter (a programming error, not bad input).
const ParamValue& line_param(const LineSettings& settings, const std::string& name);

// Registration helper: `static const LineTypeRegistration reg{{...}};` in the type's file.
struct LineTypeRegistration {
    explicit LineTypeRegistration(LineType type);
};

}  // namespace inkshade
