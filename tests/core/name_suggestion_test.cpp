#include <gtest/gtest.h>

#include "core/name_suggestion.hpp"

namespace inkshade {
namespace {

TEST(EditDistance, CountsEditsAndTranspositions) {
    EXPECT_EQ(edit_distance("", ""), 0u);
    EXPECT_EQ(edit_distance("", "abc"), 3u);
    EXPECT_EQ(edit_distance("abc", ""), 3u);
    EXPECT_EQ(edit_distance("anime", "anime"), 0u);
    EXPECT_EQ(edit_distance("anmie", "anime"), 1u);     // transposition
    EXPECT_EQ(edit_distance("rendr", "render"), 1u);    // deletion
    EXPECT_EQ(edit_distance("renderr", "render"), 1u);  // insertion
    EXPECT_EQ(edit_distance("phing", "phong"), 1u);     // substitution
    EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
    EXPECT_EQ(edit_distance("PHONG", "phong"), 0u);  // case is ignored
    EXPECT_EQ(edit_distance("ca", "abc"), 3u);       // optimal string alignment, not full Damerau
}

TEST(ClosestName, SuggestsTheNearestCloseName) {
    const std::vector<std::string> styles = {"anime", "cel", "gooch", "ink", "phong", "toon"};
    EXPECT_EQ(closest_name("anmie", styles), "anime");
    EXPECT_EQ(closest_name("phnog", styles), "phong");
    EXPECT_EQ(closest_name("Anime", styles), "anime");  // a case slip is a slip too
    EXPECT_EQ(closest_name("contuor", {"border", "contour", "crease", "suggestive"}), "contour");
    EXPECT_EQ(closest_name("--szie", {"--samples", "--set", "--size", "--style"}), "--size");
    EXPECT_EQ(closest_name("rendr", {"batch", "demo", "info", "lines", "render", "styles", "view"}), "render");
}

TEST(ClosestName, SuggestsNothingWhenNoNameIsClose) {
    const std::vector<std::string> styles = {"anime", "cel", "gooch", "ink", "phong", "toon"};
    EXPECT_EQ(closest_name("glossy", styles), "");
    EXPECT_EQ(closest_name("watercolour", styles), "");
    EXPECT_EQ(closest_name("x", {"ab", "cd"}), "");
    EXPECT_EQ(closest_name("x", {"w"}), "");  // one edit, but nothing of the name is left
    EXPECT_EQ(closest_name("k", {"kr"}), "kr");
    EXPECT_EQ(closest_name("anything", {}), "");
    EXPECT_EQ(closest_name("anime", styles), "");  // an exact match needs no suggestion
    // Short names allow one edit, longer ones a third of their length.
    EXPECT_EQ(closest_name("tn", {"toon"}), "");
    EXPECT_EQ(closest_name("suggestve", {"suggestive"}), "suggestive");
    EXPECT_EQ(closest_name("sgestve", {"suggestive"}), "");
}

TEST(ClosestName, TiesGoToTheEarlierCandidate) {
    EXPECT_EQ(closest_name("cel-001", {"cel-000", "cel-002"}), "cel-000");
}

TEST(DidYouMean, FormatsTheSuggestionOrNothing) {
    EXPECT_EQ(did_you_mean("anmie", {"anime", "toon"}), " (did you mean 'anime'?)");
    EXPECT_EQ(did_you_mean("glossy", {"anime", "toon"}), "");
}

TEST(NameCase, LowersAndComparesAsciiLetters) {
    EXPECT_EQ(lower_ascii("Threejs-Toon-OUTLINE_2"), "threejs-toon-outline_2");
    EXPECT_TRUE(equal_ignoring_case("Contour", "contour"));
    EXPECT_FALSE(equal_ignoring_case("contours", "contour"));
    EXPECT_FALSE(equal_ignoring_case("contuor", "contour"));
}

}  // namespace
}  // namespace inkshade
