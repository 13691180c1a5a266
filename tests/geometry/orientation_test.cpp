#include <gtest/gtest.h>

#include "geometry/builtin_models.hpp"
#include "geometry/orientation.hpp"

namespace inkshade::geometry {
namespace {

TEST(IsClosedOutward, BuiltinClosedModelsAre) {
    EXPECT_TRUE(is_closed_outward(builtin::sphere(8, 16)));
    EXPECT_TRUE(is_closed_outward(builtin::torus()));
    EXPECT_TRUE(is_closed_outward(builtin::torus_knot()));
}

TEST(IsClosedOutward, OpenInvertedOrInconsistentMeshesAreNot) {
    Mesh open = builtin::sphere(8, 16);
    open.triangles.pop_back();
    EXPECT_FALSE(is_closed_outward(open));

    Mesh inverted = builtin::sphere(8, 16);
    for (auto& t : inverted.triangles) std::swap(t.y, t.z);
    EXPECT_FALSE(is_closed_outward(inverted));  // closed, but the inside faces out

    Mesh flipped_one = builtin::sphere(8, 16);
    std::swap(flipped_one.triangles[5].y, flipped_one.triangles[5].z);
    EXPECT_FALSE(is_closed_outward(flipped_one));

    EXPECT_FALSE(is_closed_outward(builtin::teapot()));  // Newell's teapot has open rims
    EXPECT_FALSE(is_closed_outward(Mesh{}));
}

}  // namespace
}  // namespace inkshade::geometry
