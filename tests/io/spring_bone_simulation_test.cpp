// Spring bone physics (three-vrm 3.5.5's VRMSpringBoneJoint.update) on cases with a closed-form
// answer: a joint under gravity alone settles along the gravity direction, stiffness and gravity
// balance along their sum, a collider holds the tail where the bone's circle meets the collider
// grown by the hit radius, and with neither stiffness nor gravity and full drag the tail stays
// where it was in world space while the parent moves.
#include <gtest/gtest.h>

#include <cmath>

#include "inkshade/error.hpp"
#include "io/spring_bone_simulation.hpp"

namespace inkshade::test {
namespace {

using io::NodeTrs;
using io::SpringBones;

// Node 0 (root, at the origin, moved by `root_at`) with node 1 (the joint, at the origin) and
// node 2 (its tail, `tail` from it): one joint.
struct OneJoint {
    SpringBones bones;
    std::vector<int> parent = {-1, 0, 1};
    std::vector<NodeTrs> rest = std::vector<NodeTrs>(3);
    std::function<glm::dvec3(double)> root_at = [](double) { return glm::dvec3(0.0); };

    explicit OneJoint(glm::dvec3 tail, double stiffness, double gravity, double drag) {
        rest[2].t = tail;
        bones.joints.push_back(
            {.node = 1, .child = 2, .stiffness = stiffness, .gravity_power = gravity, .drag_force = drag});
    }
    // The tail's direction from the joint at `time`, in world space (the root does not turn).
    glm::dvec3 direction(double time) const {
        const io::NodePoseAt pose_at = [this](double t, std::vector<NodeTrs>& nodes) { nodes[0].t = root_at(t); };
        const auto r = io::simulate_spring_bones(bones, parent, rest, pose_at, time, "test");
        return glm::normalize(*r[1] * rest[2].t);
    }
};

void expect_direction(const glm::dvec3& got, const glm::dvec3& want, double tolerance) {
    EXPECT_LT(glm::length(got - glm::normalize(want)), tolerance)
        << got.x << " " << got.y << " " << got.z << " want " << want.x << " " << want.y << " " << want.z;
}

TEST(SpringBoneSimulation, StepsAreSixtiethsEndingAtTheTime) {
    EXPECT_TRUE(io::spring_step_times(0.0).empty());
    const std::vector<double> half = io::spring_step_times(0.5);
    ASSERT_EQ(half.size(), 30u);
    EXPECT_DOUBLE_EQ(half[0], 1.0 / 60.0);
    EXPECT_EQ(half.back(), 0.5);
    const std::vector<double> odd = io::spring_step_times(0.04);  // 2 steps and a shorter one
    ASSERT_EQ(odd.size(), 3u);
    EXPECT_EQ(odd.back(), 0.04);
}

TEST(SpringBoneSimulation, AtTimeZeroTheJointKeepsItsRestRotation) {
    OneJoint j({1, 0, 0}, 1.0, 1.0, 0.4);
    j.rest[1].r = glm::angleAxis(0.3, glm::dvec3(0, 0, 1));
    const auto r = io::simulate_spring_bones(
        j.bones, j.parent, j.rest, [](double, auto&) {}, 0.0, "test");
    EXPECT_NEAR(glm::length(glm::dvec4(r[1]->x, r[1]->y, r[1]->z, r[1]->w) -
                            glm::dvec4(j.rest[1].r.x, j.rest[1].r.y, j.rest[1].r.z, j.rest[1].r.w)),
                0.0, 1e-12);
}

TEST(SpringBoneSimulation, GravityAloneSettlesAlongTheGravityDirection) {
    OneJoint j({1, 0, 0}, 0.0, 1.0, 0.4);
    expect_direction(j.direction(20.0), {0, -1, 0}, 1e-6);
    j.bones.joints[0].gravity_dir = glm::normalize(glm::dvec3(1, -1, 1));
    expect_direction(j.direction(20.0), {1, -1, 1}, 1e-6);
}

TEST(SpringBoneSimulation, StiffnessAndGravityBalanceAlongTheirSum) {
    // At rest the step adds stiffness x axis + gravity x direction (times the step) and
    // renormalises: the tail stays only where that sum points along the bone.
    OneJoint j({1, 0, 0}, 1.0, 1.0, 0.4);
    expect_direction(j.direction(20.0), {1, -1, 0}, 1e-6);
    j.bones.joints[0].stiffness = 2.0;
    expect_direction(j.direction(20.0), {2, -1, 0}, 1e-6);
}

TEST(SpringBoneSimulation, ASphereHoldsTheTailAtTheRadiusSum) {
    // The bone (length 1 from the origin) falls from +x towards -y onto a sphere; it rests where
    // its circle meets the sphere grown by the hit radius, on the side it came from.
    OneJoint j({1, 0, 0}, 0.0, 0.1, 0.4);
    const glm::dvec3 centre(0.3, -1.0, 0.0);
    const double reach = 0.4 + 0.1;  // radius + hit radius
    j.bones.colliders.push_back({.node = 0, .offset = centre, .radius = 0.4});
    j.bones.joints[0].colliders = {0};
    j.bones.joints[0].hit_radius = 0.1;
    // The circle x^2 + y^2 = 1 meets |p - centre| = reach at x = (1 + |c|^2 - reach^2) / (2 c.x)
    // minus the y term: solve along the circle numerically for the intersection with x > 0.3.
    double lo = 0.0, hi = -M_PI / 2;  // angle below +x
    for (int k = 0; k < 100; ++k) {
        const double mid = 0.5 * (lo + hi);
        const glm::dvec3 p(std::cos(mid), std::sin(mid), 0.0);
        (glm::length(p - centre) > reach ? lo : hi) = mid;
    }
    const glm::dvec3 want(std::cos(lo), std::sin(lo), 0.0);
    const glm::dvec3 got = j.direction(20.0);
    EXPECT_NEAR(glm::length(got - centre), reach, 2e-3);  // pushed out, then back onto the circle
    expect_direction(got, want, 5e-3);
}

TEST(SpringBoneSimulation, ACapsuleHoldsTheTailAtTheRadiusSum) {
    // A capsule along z through (0.5, -1, .): the tail rests at distance radius + hit from its axis.
    OneJoint j({1, 0, 0}, 0.0, 0.1, 0.4);
    j.bones.colliders.push_back(
        {.node = 0, .capsule = true, .offset = {0.5, -1.0, -1.0}, .tail = {0.5, -1.0, 1.0}, .radius = 0.6});
    j.bones.joints[0].colliders = {0};
    const glm::dvec3 got = j.direction(20.0);
    EXPECT_NEAR(glm::length(glm::dvec2(got.x, got.y) - glm::dvec2(0.5, -1.0)), 0.6, 2e-3);
    EXPECT_GT(got.x, 0.5);
}

TEST(SpringBoneSimulation, WithoutStiffnessOrGravityAndFullDragTheTailStaysInPlace) {
    // The root moves 0.6 along z in the first step; the tail stays at (1, 0, 0) in world space.
    OneJoint j({1, 0, 0}, 0.0, 0.0, 1.0);
    j.root_at = [](double t) { return glm::dvec3(0.0, 0.0, 36.0 * t); };
    expect_direction(j.direction(1.0 / 60.0), {1, 0, -0.6}, 1e-9);
}

TEST(SpringBoneSimulation, TooLongATimeIsAnError) {
    OneJoint j({1, 0, 0}, 1.0, 1.0, 0.4);
    try {
        io::simulate_spring_bones(
            j.bones, j.parent, j.rest, [](double, auto&) {}, 1e9, "file.vrm");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("turn spring bones off"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace inkshade::test
