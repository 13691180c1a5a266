#include <gtest/gtest.h>

#include "inkshade/color.hpp"
#include "inkshade/error.hpp"

namespace inkshade {
namespace {

TEST(ParseColor, AcceptsHexListsGreyAndNames) {
    EXPECT_EQ(parse_color("#ff0080"), glm::vec4(1, 0, 128 / 255.0f, 1));
    EXPECT_EQ(parse_color("#f00"), glm::vec4(1, 0, 0, 1));
    EXPECT_EQ(parse_color("#00000000"), glm::vec4(0, 0, 0, 0));
    EXPECT_EQ(parse_color("0.5,0.25,1"), glm::vec4(0.5f, 0.25f, 1, 1));
    EXPECT_EQ(parse_color("0.5"), glm::vec4(0.5f, 0.5f, 0.5f, 1));
    EXPECT_EQ(parse_color("White"), glm::vec4(1));
    EXPECT_EQ(parse_color("transparent").a, 0.0f);
}

TEST(ParseColor, RejectsMalformedAndOutOfRange) {
    for (const char* bad : {"", "#12", "#gggggg", "1,2,3", "0.5,0.5", "nan,0,0", "red!", "0.1,0.2,0.3,0.4,0.5"})
        EXPECT_THROW(parse_color(bad), InputError) << bad;
}

}  // namespace
}  // namespace inkshade
