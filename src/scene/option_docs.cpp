// The option table of docs/cli.md, written from the scene option table (inkshade/options.hpp);
// tests/docs checks that the page holds exactly these rows.
#include <cmath>

#include "inkshade/options.hpp"

namespace inkshade {

namespace {

std::string cell(const std::string& text) {
    std::string out;
    for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
    return out;
}

std::string range_cell(const OptionSpec& s) {
    if (!s.choices.empty()) {
        std::string out;
        for (const std::string& c : s.choices) out += (out.empty() ? "" : ", ") + ("`" + c + "`");
        return out;
    }
    if (!s.has_range()) return "";
    auto bound = [](double v) { return std::isinf(v) ? std::string("∞") : format_option({}, float(v)); };
    return std::string(s.min_open ? "(" : "[") + bound(s.min) + ", " + bound(s.max) +
           (s.max_open || std::isinf(s.max) ? ")" : "]");
}

}  // namespace

std::string format_option_table_markdown() {
    std::string out =
        "| option | default | range | render | lines | view | batch | Python | meaning |\n"
        "|---|---|---|:-:|:-:|:-:|:-:|:-:|---|\n";
    for (const OptionSpec& s : scene_options()) {
        std::string dflt = option_default(s, kRender);
        const std::string dataset = option_default(s, kBatch);
        if (dataset != dflt) dflt += " (batch, Python: " + dataset + ")";
        auto mark = [&](unsigned front) { return std::string(s.takes(front) ? "✓" : ""); };
        out += "| " + cell("`--" + s.name + (s.value.empty() ? "" : " " + s.value) + "`") + " | " + cell(dflt) + " | " +
               cell(range_cell(s)) + " | " + mark(kRender) + " | " + mark(kLines) + " | " + mark(kView) + " | " +
               mark(kBatch) + " | " + mark(kPython) + " | " + cell(s.help) + " |\n";
    }
    return out;
}

}  // namespace inkshade
