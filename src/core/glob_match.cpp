// Glob patterns of line-set selections ([[lineset]] materials and objects, docs/styles.md): `*`
// any run of characters, `?` one character, everything else itself, matched against the whole
// name. Iterative with one backtrack point (the last `*`), so a pattern costs O(pattern x name)
// at worst and never recurses.
#include "inkshade/lines.hpp"

namespace inkshade {

bool glob_match(std::string_view pattern, std::string_view name) {
    size_t p = 0, n = 0;
    size_t star = std::string_view::npos, resume = 0;  // the last `*` and where its match ends
    while (n < name.size()) {
        if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == name[n])) {
            ++p;
            ++n;
        } else if (p < pattern.size() && pattern[p] == '*') {
            star = p++;
            resume = n;
        } else if (star != std::string_view::npos) {
            p = star + 1;  // let the last `*` take one more character
            n = ++resume;
        } else {
            return false;
        }
    }
    while (p < pattern.size() && pattern[p] == '*') ++p;
    return p == pattern.size();
}

}  // namespace inkshade
