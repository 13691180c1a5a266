// A pre-lexer for style files: walks the TOML grammar far enough to refuse the inputs toml++
// 3.3 (Debian 12) mishandles, before toml++ sees them (found by fuzzing; toml_prelexer.cpp says
// what they are). Everything else, syntax errors included, is left for toml++ to report.
#pragma once
#include <string>
#include <string_view>

namespace inkshade::styles {

// Throws InputError(source, "line N: ...") for a non-ASCII character outside strings and
// comments, or more than 128 dots on a line outside strings and comments.
void check_toml_text(std::string_view text, const std::string& source);

}  // namespace inkshade::styles
