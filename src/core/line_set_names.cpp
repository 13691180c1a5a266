// The line sets of a style's flattened lines (inkshade/lines.hpp): a line set's lines are
// consecutive, but the names are compared with all seen so far so the answer never repeats one.
#include <algorithm>

#include "inkshade/lines.hpp"

namespace inkshade {

std::vector<std::string> line_set_names(const std::vector<LineSettings>& lines) {
    std::vector<std::string> names;
    for (const LineSettings& l : lines)
        if (std::find(names.begin(), names.end(), l.lineset) == names.end()) names.push_back(l.lineset);
    return names;
}

}  // namespace inkshade
