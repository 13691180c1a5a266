// Orbit, pan and zoom (the viewer's mouse controls) as camera math.
#include <gtest/gtest.h>

#include <cmath>

#include "inkshade/orbit_controls.hpp"

namespace inkshade {
namespace {

BoundingBox unit_box() { return {glm::vec3(-1.0f), glm::vec3(1.0f)}; }

Camera front_camera() {
    Camera c;
    c.eye = {0.0f, 0.0f, 5.0f};
    c.target = {0.0f, 0.0f, 0.0f};
    return c;
}

// Pixel position of world point p in a viewport of width x height (y down).
glm::vec2 project(const Camera& c, glm::vec3 p, int width, int height) {
    glm::vec4 clip = c.projection(float(width) / float(height)) * c.view() * glm::vec4(p, 1.0f);
    glm::vec3 ndc = glm::vec3(clip) / clip.w;
    return {(ndc.x * 0.5f + 0.5f) * float(width), (0.5f - ndc.y * 0.5f) * float(height)};
}

TEST(OrbitControls, YawRotatesAboutUpAndKeepsDistance) {
    Camera c = front_camera();
    orbit(c, 90.0f, 0.0f);
    EXPECT_NEAR(c.eye.x, 5.0f, 1e-4f);
    EXPECT_NEAR(c.eye.y, 0.0f, 1e-4f);
    EXPECT_NEAR(c.eye.z, 0.0f, 1e-4f);
    orbit(c, 0.0f, 30.0f);
    EXPECT_NEAR(glm::length(c.eye - c.target), 5.0f, 1e-4f);
    EXPECT_NEAR(c.eye.y, 5.0f * std::sin(glm::radians(30.0f)), 1e-4f);
}

TEST(OrbitControls, PitchStopsShortOfThePole) {
    Camera c = front_camera();
    orbit(c, 0.0f, 200.0f);
    const float elevation = glm::degrees(std::asin(c.eye.y / glm::length(c.eye)));
    EXPECT_NEAR(elevation, 89.0f, 1e-3f);
    EXPECT_GT(glm::length(glm::cross(glm::normalize(c.target - c.eye), c.up)), 0.01f);
}

TEST(OrbitControls, PanMovesTheTargetUnderTheCursor) {
    for (bool ortho : {false, true}) {
        Camera c = front_camera();
        c.orthographic = ortho;
        const glm::vec3 point(0.0f);  // at the target's depth
        const glm::vec2 before = project(c, point, 400, 300);
        pan(c, 25.0f, -10.0f, 300);
        const glm::vec2 after = project(c, point, 400, 300);
        // Dragging right by 25 px and up by 10 px moves the scene with the cursor.
        EXPECT_NEAR(after.x - before.x, 25.0f, 1e-2f) << ortho;
        EXPECT_NEAR(after.y - before.y, -10.0f, 1e-2f) << ortho;
        EXPECT_NEAR(glm::length(c.eye - c.target), 5.0f, 1e-4f);
    }
}

TEST(OrbitControls, ZoomScalesDistanceAndOrthoHeightAndRefitsClipPlanes) {
    Camera c = front_camera();
    c.ortho_height = 4.0f;
    zoom(c, 0.5f, unit_box());
    EXPECT_NEAR(glm::length(c.eye - c.target), 2.5f, 1e-5f);
    EXPECT_NEAR(c.ortho_height, 2.0f, 1e-5f);
    // The bounding sphere (radius sqrt 3) lies between the planes.
    EXPECT_LE(c.near_plane, 2.5f - std::sqrt(3.0f));
    EXPECT_GE(c.far_plane, 2.5f + std::sqrt(3.0f));
    EXPECT_GT(c.near_plane, 0.0f);
    // Zooming in forever stops at a small positive distance; bad factors are ignored.
    for (int i = 0; i < 200; ++i) zoom(c, 0.1f, unit_box());
    EXPECT_GT(glm::length(c.eye - c.target), 0.0f);
    const glm::vec3 eye = c.eye;
    zoom(c, std::nanf(""), unit_box());
    zoom(c, -1.0f, unit_box());
    EXPECT_EQ(c.eye, eye);
}

TEST(OrbitControls, YawTurnsAboutTheModelsUpAxis) {
    Camera c;
    c.target = glm::vec3(0.0f);
    c.eye = glm::vec3(0.0f, -5.0f, 1.0f);  // in front of a z-up model, a little above
    c.up = glm::vec3(0.0f, 0.0f, 1.0f);
    orbit(c, 90.0f, 0.0f, UpAxis::PosZ);
    EXPECT_NEAR(c.eye.z, 1.0f, 1e-4f);  // the height above the ground plane is kept
    EXPECT_NEAR(glm::length(c.eye), std::sqrt(26.0f), 1e-4f);
    EXPECT_NEAR(c.eye.y, 0.0f, 1e-4f);  // a quarter turn about +z
    EXPECT_EQ(c.up, glm::vec3(0.0f, 0.0f, 1.0f));
}

}  // namespace
}  // namespace inkshade
