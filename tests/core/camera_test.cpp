// Auto-framing and camera placement (no GL).
#include <gtest/gtest.h>

#include <algorithm>
#include <utility>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "inkshade/camera.hpp"

namespace inkshade {
namespace {

BoundingBox unit_box() { return {glm::vec3(-1), glm::vec3(1)}; }

// Every corner of the box projects inside the image (|ndc| < 1) for any aspect.
void expect_box_in_view(const Camera& cam, const BoundingBox& b, float aspect) {
    glm::mat4 vp = cam.projection(aspect) * cam.view();
    for (int i = 0; i < 8; ++i) {
        glm::vec3 p((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z);
        glm::vec4 c = vp * glm::vec4(p, 1);
        ASSERT_GT(c.w, 0.0f);
        EXPECT_LT(std::abs(c.x / c.w), 1.0f);
        EXPECT_LT(std::abs(c.y / c.w), 1.0f);
        EXPECT_GT(c.z / c.w, -1.0f);
        EXPECT_LT(c.z / c.w, 1.0f);
    }
}

TEST(FrameCamera, WholeModelInViewForAnyAspect) {
    for (float aspect : {0.25f, 1.0f, 3.0f})
        for (bool ortho : {false, true}) {
            CameraOptions o;
            o.orthographic = ortho;
            expect_box_in_view(frame_camera(unit_box(), o, aspect), unit_box(), aspect);
        }
}

TEST(FrameCamera, ModelFillsMostOfTheView) {
    Camera cam = frame_camera(unit_box(), {}, 1.0f);
    glm::vec4 c = cam.projection(1.0f) * cam.view() * glm::vec4(0, 1.7320508f, 0, 1);  // top of bounding sphere
    // The bounding sphere touches ~95% of the half height (5% margin).
    EXPECT_GT(std::abs(c.y / c.w), 0.6f);
}

TEST(FrameCamera, AzimuthAndElevationPlaceEye) {
    CameraOptions o;
    o.azimuth_degrees = 90.0f;
    o.elevation_degrees = 0.0f;
    o.distance = 10.0f;
    Camera cam = frame_camera(unit_box(), o, 1.0f);
    EXPECT_NEAR(cam.eye.x, 10.0f, 1e-4f);
    EXPECT_NEAR(cam.eye.y, 0.0f, 1e-4f);
    EXPECT_NEAR(cam.eye.z, 0.0f, 1e-4f);
    o.azimuth_degrees = 0.0f;
    o.elevation_degrees = 90.0f;
    cam = frame_camera(unit_box(), o, 1.0f);
    EXPECT_NEAR(cam.eye.y, 10.0f, 1e-4f);
    // Looking straight down: up must not be parallel to the view direction.
    EXPECT_GT(glm::length(glm::cross(cam.target - cam.eye, cam.up)), 1e-3f);
}

TEST(FrameCamera, ExplicitEyeAndTargetAreKept) {
    CameraOptions o;
    o.eye = glm::vec3(3, 4, 5);
    o.target = glm::vec3(0.5f, 0, 0);
    Camera cam = frame_camera(unit_box(), o, 1.0f);
    EXPECT_EQ(cam.eye, glm::vec3(3, 4, 5));
    EXPECT_EQ(cam.target, glm::vec3(0.5f, 0, 0));
    EXPECT_LT(cam.near_plane, cam.far_plane);
}

std::vector<glm::vec3> corners(const BoundingBox& b) {
    std::vector<glm::vec3> out;
    for (int i = 0; i < 8; ++i)
        out.emplace_back((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z);
    return out;
}

// The points' projection in normalised device coordinates: lo and hi per image axis.
std::pair<glm::vec2, glm::vec2> projected_extent(const Camera& cam, const std::vector<glm::vec3>& points,
                                                 float aspect) {
    const glm::mat4 vp = cam.projection(aspect) * cam.view();
    glm::vec2 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec3& p : points) {
        const glm::vec4 c = vp * glm::vec4(p, 1);
        EXPECT_GT(c.w, 0.0f);
        lo = glm::min(lo, glm::vec2(c) / c.w);
        hi = glm::max(hi, glm::vec2(c) / c.w);
    }
    return {lo, hi};
}

// Tight framing: the corners reach 1 - 2 margin (NDC spans 2) on both sides of the limiting
// axis and are centred on the other, for wide and tall images, both projections, any view.
TEST(FrameCamera, BoxCornersTouchTheMarginOnTheLimitingAxisCentred) {
    const std::vector<BoundingBox> boxes = {unit_box(),
                                            {{2.0f, -1.5f, 0.5f}, {6.0f, -0.5f, 1.1f}},   // wide, off the origin
                                            {{-0.2f, 0.0f, -0.3f}, {0.2f, 3.0f, 0.3f}}};  // tall
    for (const BoundingBox& box : boxes)
        for (float aspect : {1920.0f / 1080.0f, 1080.0f / 1920.0f, 1.0f})
            for (bool ortho : {false, true})
                for (float margin : {0.05f, 0.0f, 0.2f})
                    for (auto [az, el] : {std::pair{35.0f, 20.0f}, std::pair{-120.0f, 65.0f}, std::pair{0.0f, 0.0f}}) {
                        CameraOptions o;
                        o.orthographic = ortho;
                        o.margin = margin;
                        o.azimuth_degrees = az;
                        o.elevation_degrees = el;
                        o.fov_degrees = 40.0f;
                        const Camera cam = frame_camera(box, o, aspect);
                        const auto [lo, hi] = projected_extent(cam, corners(box), aspect);
                        SCOPED_TRACE(::testing::Message()
                                     << "aspect " << aspect << " ortho " << ortho << " margin " << margin << " view "
                                     << az << ":" << el << " box " << box.max.x);
                        const float reach = 1.0f - 2.0f * margin;
                        const int limiting = hi.x - lo.x >= hi.y - lo.y ? 0 : 1;  // NDC: both axes span 2
                        EXPECT_NEAR(hi[limiting], reach, 1e-4f);
                        EXPECT_NEAR(lo[limiting], -reach, 1e-4f);
                        EXPECT_NEAR(hi[1 - limiting], -lo[1 - limiting], 1e-4f) << "centred";
                        EXPECT_LE(hi[1 - limiting], reach + 1e-4f);
                        // The orbit pivot stays on the view axis, level with the box centre.
                        const glm::vec3 f = glm::normalize(cam.target - cam.eye);
                        EXPECT_NEAR(glm::dot(box.center() - cam.target, f), 0.0f, 1e-4f * glm::length(box.max));
                    }
}

// Given the model's points, they (not the box corners) touch the margin: a cloud on a tilted
// ellipse, in the model's coordinates whatever its up axis.
TEST(FrameCamera, PointsTouchTheMarginOnTheLimitingAxisCentred) {
    std::vector<glm::vec3> points;
    for (int i = 0; i < 200; ++i) {
        const float a = 0.1f * float(i), b = 0.37f * float(i);
        points.emplace_back(3.0f + 2.0f * std::cos(a), 1.0f + std::sin(a) * std::cos(b), 0.5f * std::sin(b));
    }
    BoundingBox box{points[0], points[0]};
    for (const glm::vec3& p : points) box.min = glm::min(box.min, p), box.max = glm::max(box.max, p);
    for (UpAxis axis : {UpAxis::PosY, UpAxis::PosZ, UpAxis::NegX})
        for (float aspect : {16.0f / 9.0f, 9.0f / 16.0f})
            for (bool ortho : {false, true}) {
                CameraOptions o;
                o.up_axis = axis;
                o.orthographic = ortho;
                o.margin = 0.1f;
                const Camera cam = frame_camera(box, o, aspect, points);
                const auto [lo, hi] = projected_extent(cam, points, aspect);
                SCOPED_TRACE(::testing::Message()
                             << "axis " << int(axis) << " aspect " << aspect << " ortho " << ortho);
                const int limiting = hi.x - lo.x >= hi.y - lo.y ? 0 : 1;
                EXPECT_NEAR(hi[limiting], 0.8f, 1e-4f);
                EXPECT_NEAR(lo[limiting], -0.8f, 1e-4f);
                EXPECT_NEAR(hi[1 - limiting], -lo[1 - limiting], 1e-4f) << "centred";
                // Tighter than the box: its corners reach beyond the points' extent.
                const auto [box_lo, box_hi] = projected_extent(cam, corners(box), aspect);
                EXPECT_GT(std::max(box_hi[limiting], -box_lo[limiting]), 0.8f + 1e-3f);
            }
}

// A given target keeps the view axis through it: the distance (or the orthographic height)
// fits, so the farthest corner meets the margin on its side.
TEST(FrameCamera, GivenTargetFitsTheDistanceToTheFarthestCorner) {
    for (bool ortho : {false, true}) {
        CameraOptions o;
        o.orthographic = ortho;
        o.target = glm::vec3(0.5f, 0.25f, 0.0f);
        o.margin = 0.1f;
        const Camera cam = frame_camera(unit_box(), o, 1.5f);
        EXPECT_EQ(cam.target, *o.target);
        const auto [lo, hi] = projected_extent(cam, corners(unit_box()), 1.5f);
        const float widest = std::max({hi.x, hi.y, -lo.x, -lo.y});
        EXPECT_NEAR(widest, 0.8f, 1e-4f) << "ortho " << ortho;
    }
}

// The margin and projection change the framing, not the view direction; a given distance or
// orthographic height wins over it.
TEST(FrameCamera, GivenDistanceAndOrthoHeightAreKept) {
    CameraOptions o;
    o.distance = 9.0f;
    o.margin = 0.3f;
    Camera cam = frame_camera(unit_box(), o, 1.0f);
    EXPECT_NEAR(glm::length(cam.eye - cam.target), 9.0f, 1e-4f);
    EXPECT_EQ(cam.target, glm::vec3(0.0f));
    o = {};
    o.orthographic = true;
    o.ortho_height = 7.0f;
    EXPECT_EQ(frame_camera(unit_box(), o, 1.0f).ortho_height, 7.0f);
}

TEST(Light, DirectionalLightDirectionIsIndependentOfPoint) {
    Light l;
    l.position = glm::vec3(0, 10, 0);
    l.target = glm::vec3(0);
    EXPECT_EQ(l.direction_to_light(glm::vec3(5, 0, 0)), glm::vec3(0, 1, 0));
    l.type = LightType::Point;
    glm::vec3 d = l.direction_to_light(glm::vec3(10, 10, 0));
    EXPECT_NEAR(d.x, -1.0f, 1e-6f);
}

TEST(Light, DefaultLightIsAboveAndInFrontOfModel) {
    Camera cam = frame_camera(unit_box(), {}, 1.0f);
    Light l = default_light(unit_box(), cam);
    glm::vec3 to_light = l.direction_to_light(glm::vec3(0));
    EXPECT_GT(glm::dot(to_light, glm::normalize(cam.eye - cam.target)), 0.3f);  // lights the visible side
    EXPECT_GT(to_light.y, 0.3f);
}

// A model whose up is another axis is framed as the y-up model it is a rotation of: the camera
// is that model's camera turned by the same rotation, for every axis.
TEST(FrameCamera, UpAxisFramesTheModelAsItsYUpTwin) {
    const BoundingBox y_up{{-1.0f, 0.0f, -0.5f}, {1.0f, 4.0f, 0.5f}};  // tall along +y
    CameraOptions o;
    o.azimuth_degrees = 30.0f;
    o.elevation_degrees = 15.0f;
    const Camera reference = frame_camera(y_up, o, 1.5f);
    for (UpAxis axis : {UpAxis::PosX, UpAxis::NegX, UpAxis::NegY, UpAxis::PosZ, UpAxis::NegZ}) {
        SCOPED_TRACE(int(axis));
        const glm::mat3 r = up_axis_rotation(axis);
        EXPECT_NEAR(glm::determinant(r), 1.0f, 1e-6f);  // a rotation, not a mirror
        const glm::vec3 a = r * y_up.min, b = r * y_up.max;
        CameraOptions turned = o;
        turned.up_axis = axis;
        const Camera c = frame_camera({glm::min(a, b), glm::max(a, b)}, turned, 1.5f);
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(c.eye[k], (r * reference.eye)[k], 1e-4f);
            EXPECT_NEAR(c.target[k], (r * reference.target)[k], 1e-4f);
            EXPECT_NEAR(c.up[k], (r * reference.up)[k], 1e-5f);
        }
        EXPECT_NEAR(c.near_plane, reference.near_plane, 1e-4f);
        EXPECT_NEAR(c.far_plane, reference.far_plane, 1e-4f);
    }
    // +z up: the camera's up is +z, and azimuth 0 at elevation 0 looks from -y.
    CameraOptions front;
    front.azimuth_degrees = 0.0f;
    front.elevation_degrees = 0.0f;
    front.up_axis = UpAxis::PosZ;
    const Camera c = frame_camera({glm::vec3(-1.0f), glm::vec3(1.0f)}, front, 1.0f);
    EXPECT_NEAR(c.up.z, 1.0f, 1e-6f);
    EXPECT_LT(c.eye.y, -1.0f);
    EXPECT_NEAR(c.eye.x, 0.0f, 1e-5f);
    EXPECT_NEAR(c.eye.z, 0.0f, 1e-5f);
}

}  // namespace
}  // namespace inkshade
