// Component-wise comparison of vectors, naming the component that differs.
#pragma once
#include <gtest/gtest.h>

#include <glm/glm.hpp>

namespace inkshade::test {

inline void expect_near(glm::vec3 a, glm::vec3 b, float eps = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, eps) << "x";
    EXPECT_NEAR(a.y, b.y, eps) << "y";
    EXPECT_NEAR(a.z, b.z, eps) << "z";
}

}  // namespace inkshade::test
