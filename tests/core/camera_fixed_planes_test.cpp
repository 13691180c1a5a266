// CameraOptions' fixed near/far planes and orthographic height (three.js cameras carry them)
// replace the values auto-framing fits to the model; unset, framing is unchanged.
#include <gtest/gtest.h>

#include "inkshade/camera.hpp"

namespace inkshade {
namespace {

TEST(CameraFixedPlanes, NearFarAndOrthoHeightOverrideTheFit) {
    const BoundingBox box{glm::vec3(-1.0f), glm::vec3(1.0f)};
    CameraOptions o;
    o.eye = glm::vec3(0, 0, 6);
    const Camera fitted = frame_camera(box, o, 1.5f);
    o.near_plane = 0.1f;
    o.far_plane = 2000.0f;
    o.orthographic = true;
    o.ortho_height = 7.0f;
    const Camera fixed = frame_camera(box, o, 1.5f);
    EXPECT_EQ(fixed.near_plane, 0.1f);
    EXPECT_EQ(fixed.far_plane, 2000.0f);
    EXPECT_EQ(fixed.ortho_height, 7.0f);
    EXPECT_EQ(fixed.eye, fitted.eye);
    EXPECT_NE(fitted.near_plane, 0.1f);
    EXPECT_NE(fitted.far_plane, 2000.0f);
    // Orthographic projection: the view is ortho_height high whatever the model's size.
    const glm::vec4 top = fixed.projection(1.5f) * fixed.view() * glm::vec4(0.0f, 3.5f, 0.0f, 1.0f);
    EXPECT_NEAR(top.y / top.w, 1.0f, 1e-5f);
}

}  // namespace
}  // namespace inkshade
