// What fuzz_style does with one input (replayed by tests/styles/fuzz_regressions_test.cpp):
// parse_style on the bytes (TOML through toml++, then every key and value checked); lines after
// a "\n#%%\n" marker are applied as --set overrides (apply_override). A style that parses must
// survive format_style -> parse_style unchanged (--save-style writes text that reads back to
// the same style, docs/styles.md).
#pragma once
#include <string>
#include <string_view>

#include "fuzz_common.hpp"
#include "inkshade/style.hpp"

namespace inkshade::fuzz {

// A style that parsed must survive format_style -> parse_style unchanged (--save-style).
inline void check_style_round_trip(const Style& style, const std::string& source) {
    const std::string text = format_style(style);
    Style again;
    try {
        again = parse_style(text, source);
    } catch (const InputError& e) {
        broken(std::string("format_style wrote text parse_style refuses: ") + e.what() + "\n" + text);
    }
    if (format_style(again) != text) broken("style changed on the way through format_style:\n" + text);
}

inline void style_input(std::string_view data) {
    const auto parts = split(data, "\n#%%\n", 2);
    const std::string source = "fuzz.toml";
    Style style;
    try {
        style = parse_style(parts[0], source);
    } catch (const InputError& e) {
        check_error(e, source);
        return;
    }
    if (parts.size() > 1) {
        std::string_view rest = parts[1];
        while (!rest.empty()) {
            const size_t nl = rest.find('\n');
            const std::string line(rest.substr(0, nl));
            rest.remove_prefix(nl == std::string_view::npos ? rest.size() : nl + 1);
            try {
                apply_override(style, line);
            } catch (const InputError& e) {
                const std::string what = e.what();
                if (what.find('\n') != std::string::npos || what.find('\r') != std::string::npos)
                    broken("multi-line override error: " + what);
            }
        }
    }
    check_style_round_trip(style, source);
}

}  // namespace inkshade::fuzz
