// The names a glTF file gives its animations, morph targets and VRM expressions, as the errors
// for a name the file does not have list them.
#pragma once
#include <string>
#include <vector>

#include "core/name_suggestion.hpp"

namespace inkshade::io {

// One-line, printable text of a name from the file (at most 80 characters).
inline std::string printable_name(const std::string& name) {
    std::string out;
    for (char c : name) {
        out += (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) ? '?' : c;
        if (out.size() >= 80) return out + "...";
    }
    return out;
}

// "'walk', 'run'" (with `indexed`: "0 'walk', 1 'run'"), at most 20, or "none".
inline std::string name_list(const std::vector<std::string>& names, bool indexed = false) {
    if (names.empty()) return "none";
    std::string out;
    for (size_t i = 0; i < names.size() && i < 20; ++i)
        out += (i ? ", " : "") + (indexed ? std::to_string(i) + " " : std::string()) + "'" + printable_name(names[i]) +
               "'";
    if (names.size() > 20) out += ", ... (" + std::to_string(names.size()) + " in all)";
    return out;
}

// "no WHAT 'NAME' (did you mean 'X'?); its WHATs: ...": the problem of a name not in `names`.
inline std::string unknown_name(const std::string& what, const std::string& name, const std::vector<std::string>& names,
                                bool indexed = false) {
    return "no " + what + " '" + printable_name(name) + "'" + did_you_mean(name, names) + "; its " + what +
           "s: " + name_list(names, indexed);
}

// The index of `name` in `names`: exactly, else ignoring case; -1 when absent.
inline int find_name(const std::vector<std::string>& names, const std::string& name) {
    for (size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return int(i);
    for (size_t i = 0; i < names.size(); ++i)
        if (equal_ignoring_case(names[i], name)) return int(i);
    return -1;
}

}  // namespace inkshade::io
