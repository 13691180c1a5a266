// "Did you mean ...?" for names a user can get slightly wrong (styles, shading models, line
// types, colours, subcommands, options), and the case-insensitive matching of such names. One
// implementation for every part: core includes nothing, so every part may include this.
#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace inkshade {

// ASCII lower case: the canonical spelling of a registered name.
std::string lower_ascii(std::string_view text);

// Whether a and b are the same name but for the case of ASCII letters.
bool equal_ignoring_case(std::string_view a, std::string_view b);

// Damerau-Levenshtein distance (optimal string alignment: insertions, deletions, substitutions
// and transpositions of neighbours each count one), ignoring the case of ASCII letters.
size_t edit_distance(std::string_view a, std::string_view b);

// The candidate closest to `name` by edit_distance, when it is close enough to be a slip of the
// keyboard (at most max(1, name length / 3) edits, and not every character replaced); empty
// when none is, or when `name` matches a candidate exactly. Ties go to the earlier candidate.
std::string closest_name(std::string_view name, const std::vector<std::string>& candidates);

// " (did you mean 'x'?)" for closest_name(name, candidates), or empty: appended to the messages
// that reject an unknown name.
std::string did_you_mean(std::string_view name, const std::vector<std::string>& candidates);

}  // namespace inkshade
