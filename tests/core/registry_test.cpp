#include "core/registry.hpp"

#include <gtest/gtest.h>

namespace inkshade {
namespace {

struct Colour {
    std::string name;
    int rank = 0;
};

Registry<Colour> primaries() {
    Registry<Colour> r("colour");
    r.add({"red", 3});
    r.add({"green", 1});
    r.add({"blue", 2});
    return r;
}

std::string unknown_message(const Registry<Colour>& r, const std::string& name) {
    try {
        r.at(name);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(Registry, FindsByNameExactlyThenIgnoringCase) {
    Registry<Colour> r = primaries();
    ASSERT_NE(r.find("green"), nullptr);
    EXPECT_EQ(r.find("green")->rank, 1);
    EXPECT_EQ(r.find("GrEeN"), r.find("green"));
    EXPECT_EQ(&r.at("Blue"), r.find("blue"));
    EXPECT_EQ(r.find("grey"), nullptr);
    EXPECT_EQ(r.find(""), nullptr);
}

TEST(Registry, AddReturnsTheStoredEntryWhichNeverMoves) {
    Registry<Colour> r("colour");
    const Colour* first = &r.add({"c0", 0});
    for (int i = 1; i < 1000; ++i) r.add({"c" + std::to_string(i), i});
    EXPECT_EQ(r.find("c0"), first);
    EXPECT_EQ(first->name, "c0");
}

TEST(Registry, RejectsANameTakenEvenInAnotherCase) {
    Registry<Colour> r = primaries();
    EXPECT_THROW(r.add({"red", 9}), std::logic_error);
    try {
        r.add({"Green", 9});
        ADD_FAILURE() << "no error";
    } catch (const std::logic_error& e) {
        EXPECT_EQ(std::string(e.what()), "colour 'Green' registered twice (as 'green')");
    }
    EXPECT_EQ(r.list().size(), 3u);
    EXPECT_EQ(r.find("red")->rank, 3);
}

TEST(Registry, UnknownNameListsTheChoicesAndSuggestsTheClosest) {
    const Registry<Colour> r = primaries();
    EXPECT_EQ(unknown_message(r, "rde"), "unknown colour 'rde' (choose blue, green, red) (did you mean 'red'?)");
    EXPECT_EQ(unknown_message(r, "purple"), "unknown colour 'purple' (choose blue, green, red)");
    EXPECT_EQ(unknown_message(Registry<Colour>("colour"), "red"), "unknown colour 'red' (choose none registered)");
}

TEST(Registry, ListsInItsOrderWhateverTheRegistrationOrder) {
    const Registry<Colour> r = primaries();
    std::vector<std::string> names;
    for (const Colour* c : r.list()) names.push_back(c->name);
    EXPECT_EQ(names, (std::vector<std::string>{"blue", "green", "red"}));  // by name by default

    Registry<Colour> ranked("colour", [](const Colour& a, const Colour& b) { return a.rank < b.rank; });
    for (const Colour* c : r.list()) ranked.add(*c);
    std::vector<int> ranks;
    for (const Colour* c : ranked.list()) ranks.push_back(c->rank);
    EXPECT_EQ(ranks, (std::vector<int>{1, 2, 3}));
    // The error lists the names in that order too.
    EXPECT_EQ(unknown_message(ranked, "x"), "unknown colour 'x' (choose green, blue, red)");
}

}  // namespace
}  // namespace inkshade
