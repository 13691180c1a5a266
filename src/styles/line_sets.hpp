// A style file's [[lineset]] tables (docs/styles.md, "Line sets"): each a face selection, the
// stroke and visibility defaults of its lines, an order, and its own [[lineset.lines]]. They are
// flattened into Style::lines, each LineSettings carrying its set's name and selection, so every
// consumer of a style's lines (renderer, line drawing, masks, viewer) takes them unchanged.
#pragma once
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#define TOML_EXCEPTIONS 1
#include <toml++/toml.h>

#include "inkshade/lines.hpp"

namespace inkshade::styles {

using ParseLine = std::function<LineSettings(const toml::table&)>;
using ParseParam = std::function<ParamValue(const ParamSpec&, const toml::node&)>;
using WriteParams = std::function<void(std::ostream&, const LineSettings&)>;
using Quote = std::function<std::string(const std::string&)>;  // a TOML string of the text

// Appends the lines of the root's [[lineset]] tables to `lines`, line sets in `order` (ties in
// file order) after the style's own [[lines]]. Throws InputError("SOURCE: problem") for an
// unknown key, a missing or repeated name, a bad selection, a type listed twice in one set, or
// an image-space type in a set that does not select every face.
void parse_line_sets(const toml::table& root, const std::string& source, std::vector<LineSettings>& lines,
                     const ParseLine& parse_line, const ParseParam& parse_param);

// The lines of named line sets as [[lineset]] tables that parse_line_sets reads back (their
// order is the order written).
void write_line_sets(std::ostream& out, const std::vector<LineSettings>& lines, const Quote& quote,
                     const WriteParams& write_params);

// Throws InputError("SOURCE: ...") when an image-space line type is drawn twice in the style
// (its GPU pass has one setting) or in a line set that selects only some faces (image-space
// lines are found per pixel, on no face).
void check_image_space_lines(const std::vector<LineSettings>& lines, const std::string& source);

}  // namespace inkshade::styles
