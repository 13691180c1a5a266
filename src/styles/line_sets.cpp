#include "styles/line_sets.hpp"

#include <algorithm>
#include <optional>

#include "inkshade/error.hpp"

namespace inkshade::styles {

namespace {

// The keys of a [[lineset]] table besides the stroke and visibility defaults of its lines.
const std::vector<std::string> kSelectionKeys = {"name",   "materials", "objects", "face-mark",
                                                 "invert", "order",     "lines"};

bool is_name_char(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_';
}

// Names become SVG ids and file names (STEM.lineset-NAME.png): letters, digits, '-', '_'.
std::string set_name(const toml::table& table, const std::string& source) {
    const std::optional<std::string> name = table["name"].value<std::string>();
    if (!name) throw InputError(source, "every [[lineset]] needs name = \"NAME\"");
    if (name->empty() || name->size() > 64 || !std::all_of(name->begin(), name->end(), is_name_char))
        throw InputError(source, "lineset name '" + *name + "': use 1 to 64 letters, digits, '-' or '_'");
    return *name;
}

std::vector<std::string> patterns(const toml::table& table, const char* key, const std::string& where) {
    std::vector<std::string> out;
    const toml::node* node = table.get(key);
    if (!node) return out;
    if (auto one = node->value<std::string>()) return {*one};
    const toml::array* list = node->as_array();
    if (!list) throw InputError(where + key + ": expected a name pattern or a list of them");
    for (const toml::node& e : *list) {
        auto s = e.value<std::string>();
        if (!s) throw InputError(where + key + ": expected a list of name patterns");
        out.push_back(*s);
    }
    if (out.empty()) throw InputError(where + key + ": an empty list selects nothing (leave it out to select all)");
    return out;
}

// face-mark = true (any mark), false (unmarked) or N in 1..255 (that mark).
std::optional<int> face_mark(const toml::table& table, const std::string& where) {
    const toml::node* node = table.get("face-mark");
    if (!node) return std::nullopt;
    if (auto b = node->value_exact<bool>()) return *b ? -1 : 0;
    auto n = node->value_exact<int64_t>();
    if (!n || *n < 1 || *n > 255) throw InputError(where + "face-mark: expected true, false or a mark in 1..255");
    return int(*n);
}

FaceSelection selection(const toml::table& table, const std::string& where) {
    FaceSelection s;
    s.materials = patterns(table, "materials", where);
    s.objects = patterns(table, "objects", where);
    s.face_mark = face_mark(table, where);
    if (const toml::node* n = table.get("invert")) {
        auto b = n->value_exact<bool>();
        if (!b) throw InputError(where + "invert: expected true or false");
        s.invert = *b;
    }
    return s;
}

// The set's keys besides its selection: parameters its lines take when they do not set them.
void apply_defaults(const toml::table& table, std::vector<LineSettings>& lines, const std::string& where,
                    const ParseParam& parse_param) {
    for (const auto& [key, node] : table) {
        const std::string k(key.str());
        if (std::find(kSelectionKeys.begin(), kSelectionKeys.end(), k) != kSelectionKeys.end()) continue;
        bool used = false;
        for (LineSettings& l : lines) {
            const ParamSpec* spec = line_type(l.type).param(k);
            if (!spec) continue;
            used = true;
            if (!l.params.contains(spec->name)) l.params[spec->name] = parse_param(*spec, node);
        }
        if (!used) throw InputError(where + "unknown key '" + k + "' (no line type of the set has it)");
    }
}

struct ParsedSet {
    int64_t order = 0;
    std::vector<LineSettings> lines;
};

ParsedSet parse_set(const toml::table& table, const std::string& source, const ParseLine& parse_line,
                    const ParseParam& parse_param) {
    const std::string name = set_name(table, source);
    const std::string where = "lineset '" + name + "': ";
    ParsedSet set;
    if (const toml::node* n = table.get("order")) {
        auto o = n->value_exact<int64_t>();
        if (!o) throw InputError(source, where + "order: expected an integer");
        set.order = *o;
    }
    const FaceSelection faces = selection(table, source + ": " + where);
    const toml::array* lines = table["lines"].as_array();
    if (!lines || lines->empty()) throw InputError(source, where + "needs [[lineset.lines]] tables");
    for (const toml::node& entry : *lines) {
        const toml::table* t = entry.as_table();
        if (!t) throw InputError(source, where + "lines must be an array of tables ([[lineset.lines]])");
        LineSettings l = parse_line(*t);
        for (const LineSettings& other : set.lines)
            if (other.type == l.type) throw InputError(source, where + "line type '" + l.type + "' is listed twice");
        l.lineset = name;
        l.faces = faces;
        set.lines.push_back(std::move(l));
    }
    apply_defaults(table, set.lines, source + ": " + where, parse_param);
    return set;
}

}  // namespace

void parse_line_sets(const toml::table& root, const std::string& source, std::vector<LineSettings>& lines,
                     const ParseLine& parse_line, const ParseParam& parse_param) {
    const toml::node* node = root.get("lineset");
    if (!node) return;
    const toml::array* sets = node->as_array();
    if (!sets) throw InputError(source, "lineset must be an array of tables ([[lineset]])");
    std::vector<ParsedSet> parsed;
    std::vector<std::string> names;
    for (const toml::node& entry : *sets) {
        const toml::table* table = entry.as_table();
        if (!table) throw InputError(source, "lineset must be an array of tables ([[lineset]])");
        parsed.push_back(parse_set(*table, source, parse_line, parse_param));
        const std::string& name = parsed.back().lines.front().lineset;
        if (std::find(names.begin(), names.end(), name) != names.end())
            throw InputError(source, "lineset name '" + name + "' is used twice");
        names.push_back(name);
    }
    std::stable_sort(parsed.begin(), parsed.end(),
                     [](const ParsedSet& a, const ParsedSet& b) { return a.order < b.order; });
    for (ParsedSet& set : parsed) lines.insert(lines.end(), set.lines.begin(), set.lines.end());
}

namespace {

void write_patterns(std::ostream& out, const char* key, const std::vector<std::string>& list, const Quote& quote) {
    if (list.empty()) return;
    out << key << " = [";
    for (size_t i = 0; i < list.size(); ++i) out << (i ? ", " : "") << quote(list[i]);
    out << "]\n";
}

}  // namespace

void write_line_sets(std::ostream& out, const std::vector<LineSettings>& lines, const Quote& quoted,
                     const WriteParams& write_params) {
    int order = 0;
    for (size_t i = 0; i < lines.size(); ++i) {
        const LineSettings& l = lines[i];
        if (l.lineset.empty()) continue;
        if (i == 0 || lines[i - 1].lineset != l.lineset) {
            out << "\n[[lineset]]\nname = " << quoted(l.lineset) << "\norder = " << ++order << "\n";
            write_patterns(out, "materials", l.faces.materials, quoted);
            write_patterns(out, "objects", l.faces.objects, quoted);
            if (l.faces.face_mark)
                out << "face-mark = "
                    << (*l.faces.face_mark < 0    ? std::string("true")
                        : *l.faces.face_mark == 0 ? std::string("false")
                                                  : std::to_string(*l.faces.face_mark))
                    << "\n";
            if (l.faces.invert) out << "invert = true\n";
        }
        out << "\n[[lineset.lines]]\ntype = " << quoted(l.type) << "\n";
        write_params(out, l);
    }
}

void check_image_space_lines(const std::vector<LineSettings>& lines, const std::string& source) {
    for (size_t i = 0; i < lines.size(); ++i) {
        const LineSettings& l = lines[i];
        if (line_type(l.type).space != LineSpace::Image) continue;
        if (!l.faces.everything())
            throw InputError(source, "lineset '" + l.lineset + "': image-space line type '" + l.type +
                                         "' cannot be limited to some faces (it is found per pixel)");
        for (size_t j = 0; j < i; ++j)
            if (lines[j].type == l.type)
                throw InputError(source,
                                 "image-space line type '" + l.type + "' is drawn twice (in " +
                                     (lines[j].lineset.empty() ? "[[lines]]" : "lineset '" + lines[j].lineset + "'") +
                                     " too)");
    }
}

}  // namespace inkshade::styles
