// glTF animations: keyframe sampling against the formulas of glTF 2.0 Appendix C (linear,
// step, cubic Hermite, spherical rotation), and the avatar's animations moving its vertices
// where the analytic joints and weights put them at two times, with clamping, names, indices
// and one-line errors for damaged animations.
#include <gtest/gtest.h>

#include <functional>

#include "inkshade/error.hpp"
#include "inkshade/io.hpp"
#include "io/avatar_files.hpp"
#include "io/gltf_animation.hpp"
#include "support/expect_near.hpp"
#include "support/temp_dir.hpp"

namespace inkshade::test {
namespace {

using io::Interpolation;
using io::sample_keyframes;

glm::vec3 at(const std::vector<float>& xyz, size_t i) { return {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]}; }

LoadOptions playing(const std::string& animation, float time) {
    LoadOptions o;
    o.pose.animation = animation;
    o.pose.time = time;
    return o;
}

std::string load_error(const std::string& path, const LoadOptions& options) {
    try {
        load_mesh(path, options);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(GltfAnimation, LinearAndStepKeyframes) {
    const std::vector<float> times = {1, 2, 4}, values = {0, 10, 20, 30, 40, 50};  // VEC2
    EXPECT_EQ(sample_keyframes(times, values, 2, Interpolation::Linear, 1.5, false), (std::vector<double>{10, 20}));
    EXPECT_EQ(sample_keyframes(times, values, 2, Interpolation::Linear, 3.0, false), (std::vector<double>{30, 40}));
    EXPECT_EQ(sample_keyframes(times, values, 2, Interpolation::Linear, 0.0, false), (std::vector<double>{0, 10}));
    EXPECT_EQ(sample_keyframes(times, values, 2, Interpolation::Linear, 9.0, false), (std::vector<double>{40, 50}));
    EXPECT_EQ(sample_keyframes(times, values, 2, Interpolation::Step, 1.99, false), (std::vector<double>{0, 10}));
    EXPECT_EQ(sample_keyframes(times, values, 2, Interpolation::Step, 2.0, false), (std::vector<double>{20, 30}));
    EXPECT_EQ(sample_keyframes(times, values, 2, Interpolation::Step, 3.9, false), (std::vector<double>{20, 30}));
}

TEST(GltfAnimation, CubicSplineIsTheHermiteCurveOfAppendixC) {
    // Keys at 0 and 2 with values 0 and 1, out-tangent 2 at the first key and in-tangent -1 at
    // the second: p(s) = (2s^3 - 3s^2 + 1) 0 + (s^3 - 2s^2 + s) 2 * 2 + (-2s^3 + 3s^2) 1 + (s^3 - s^2) 2 * (-1).
    const std::vector<float> times = {0, 2}, values = {9, 0, 2, -1, 1, 9};  // in, value, out per key
    for (double t : {0.0, 0.5, 1.0, 1.7, 2.0}) {
        const double s = t / 2, s2 = s * s, s3 = s2 * s;
        const double expected = (s3 - 2 * s2 + s) * 4 + (-2 * s3 + 3 * s2) + (s3 - s2) * -2;
        EXPECT_NEAR(sample_keyframes(times, values, 1, Interpolation::CubicSpline, t, false)[0], expected, 1e-12) << t;
    }
}

TEST(GltfAnimation, RotationsTurnAlongTheShorterArc) {
    auto about_z = [](double degrees, double sign = 1) {
        const double h = glm::radians(degrees) / 2;
        return std::vector<float>{0, 0, float(sign * std::sin(h)), float(sign * std::cos(h))};
    };
    std::vector<float> values = about_z(0);
    for (float v : about_z(90, -1)) values.push_back(v);  // the same rotation as +90, negated
    const std::vector<double> q = sample_keyframes({0, 1}, values, 4, Interpolation::Linear, 0.5, true);
    const double angle = 2 * std::atan2(q[2], q[3]);
    EXPECT_NEAR(std::abs(angle), glm::radians(45.0), 1e-6);  // float keys  // not 135: the shorter way
    EXPECT_NEAR(glm::length(glm::dvec4(q[0], q[1], q[2], q[3])), 1.0, 1e-12);
    // A quarter of the way from 0 to 180 degrees is 45 degrees (interpolating the components
    // linearly would give 2 atan(1/3) = 36.9 degrees).
    const std::vector<float> wide = {0, 0, 0, 1, 0, 0, 1, 0};  // 0 to 180 degrees
    const std::vector<double> r = sample_keyframes({0, 1}, wide, 4, Interpolation::Linear, 0.25, true);
    EXPECT_NEAR(2 * std::atan2(r[2], r[3]), glm::radians(45.0), 1e-6);
}

// The avatar's vertices at a shoulder angle and a "happy" weight, in the load order.
void expect_avatar_pose(const Mesh& m, float shoulder_degrees, float happy, glm::vec3 lift = glm::vec3(0)) {
    const AvatarLayout l = avatar_layout();
    ASSERT_EQ(m.positions.size(), l.end);
    const AvatarPart arm = avatar_arm(), ball = avatar_sphere(kHandBall, kHandBallRadius, 8, 12),
                     head = avatar_sphere(glm::vec3(0), kHeadRadius, 12, 16);
    for (size_t i = 0; i < arm.positions.size() / 3; ++i) {
        const glm::vec3 p = at(arm.positions, i);
        expect_near(m.positions[l.arm + i], lift + avatar_skinned(p, avatar_arm_weights(p.x), shoulder_degrees));
    }
    for (size_t i = 0; i < ball.positions.size() / 3; ++i)
        expect_near(m.positions[l.ball + i], lift + avatar_skinned(at(ball.positions, i), {0, 1}, shoulder_degrees));
    for (size_t i = 0; i < head.positions.size() / 3; ++i) {
        const glm::vec3 p = at(head.positions, i);
        expect_near(m.positions[l.head + i], lift + kHeadCentre + p + happy * avatar_happy(p));
    }
}

TEST(GltfAnimation, WaveMovesTheArmAndTheFaceAsItsKeysSay) {
    TempDir dir;
    const std::string path = dir.write("avatar.glb", avatar(AvatarFormat::Gltf).glb());
    {
        SCOPED_TRACE("rest");
        expect_avatar_pose(load_mesh(path), 0.0f, 0.0f);
    }
    {
        SCOPED_TRACE("t = 1: half way");
        expect_avatar_pose(load_mesh(path, playing("wave", 1.0f)), 45.0f, 0.5f);
    }
    {
        SCOPED_TRACE("t = 0.5");
        expect_avatar_pose(load_mesh(path, playing("wave", 0.5f)), 22.5f, 0.25f);
    }
    {
        SCOPED_TRACE("t = 2: the last key");
        expect_avatar_pose(load_mesh(path, playing("wave", 2.0f)), 90.0f, 1.0f);
    }
    {
        SCOPED_TRACE("clamped after the end");
        expect_avatar_pose(load_mesh(path, playing("wave", 7.5f)), 90.0f, 1.0f);
    }
    {
        SCOPED_TRACE("clamped before the start");
        expect_avatar_pose(load_mesh(path, playing("wave", -3.0f)), 0.0f, 0.0f);
    }
    // The hand ball's centre turns about the shoulder: at 90 degrees the arm points up.
    const Mesh up = load_mesh(path, playing("WAVE", 2.0f));  // names ignore case when nothing matches exactly
    const AvatarLayout l = avatar_layout();
    const AvatarPart ball = avatar_sphere(kHandBall, kHandBallRadius, 8, 12);
    glm::vec3 centre(0), rest(0);
    for (size_t i = l.ball; i < l.end; ++i) {
        centre += up.positions[i] / float(l.end - l.ball);
        rest += at(ball.positions, i - l.ball) / float(l.end - l.ball);
    }
    expect_near(centre, glm::vec3(avatar_lower_arm(90.0f) * glm::vec4(rest - kElbow, 1.0f)), 1e-5f);
    EXPECT_GT(centre.y, kElbow.y + 0.3f);
}

TEST(GltfAnimation, StepTranslationByIndex) {
    TempDir dir;
    const std::string path = dir.write("avatar.glb", avatar(AvatarFormat::Gltf).glb());
    expect_avatar_pose(load_mesh(path, playing("1", 0.99f)), 0.0f, 0.0f);
    expect_avatar_pose(load_mesh(path, playing("1", 1.0f)), 0.0f, 0.0f, {0, 0.5f, 0});
    expect_avatar_pose(load_mesh(path, playing("hop", 1.7f)), 0.0f, 0.0f, {0, 0.5f, 0});
    expect_avatar_pose(load_mesh(path, playing("hop", 2.0f)), 0.0f, 0.0f);
}

TEST(GltfAnimation, UnknownAnimationsAndDamagedOnesAreOneLineErrors) {
    TempDir dir;
    const std::string path = dir.write("avatar.glb", avatar(AvatarFormat::Gltf).glb());
    EXPECT_EQ(load_error(path, playing("wav", 1)),
              path + ": no animation 'wav' (did you mean 'wave'?); its animations: 0 'wave', 1 'hop'");
    EXPECT_EQ(load_error(path, playing("2", 1)), path + ": no animation '2'; its animations: 0 'wave', 1 'hop'");
    GltfBuilder plain = textured_quad();
    const std::string quad = dir.write("quad.glb", plain.glb());
    EXPECT_EQ(load_error(quad, playing("wave", 1)), quad + ": no animation 'wave': the file has none");
    const std::string obj = dir.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    EXPECT_EQ(load_error(obj, playing("wave", 1)),
              obj + ": only glTF, GLB and VRM files have animations, morph targets and expressions");

    struct Case {
        const char* name;
        std::function<void(nlohmann::json&)> edit;
        std::string message;
    };
    const std::vector<Case> cases = {
        {"target node", [](nlohmann::json& a) { a["channels"][0]["target"]["node"] = 70; },
         "animation 0 channel 0 targets node 70 but the file has 7"},
        {"sampler", [](nlohmann::json& a) { a["channels"][1]["sampler"] = 5; },
         "animation 0 channel 1 refers to sampler 5 but the animation has 2"},
        {"interpolation", [](nlohmann::json& a) { a["samplers"][0]["interpolation"] = "BEZIER"; },
         "animation 0 sampler 0 has unknown interpolation 'BEZIER'"},
        {"cubic without tangents", [](nlohmann::json& a) { a["samplers"][0]["interpolation"] = "CUBICSPLINE"; },
         "output of animation 0 sampler 0 has 2 elements but 2 keyframes need 6"},
        {"output accessor", [](nlohmann::json& a) { a["samplers"][1]["output"] = 500; }, "refers to accessor 500"},
        {"input accessor type", [](nlohmann::json& a) { a["samplers"][1]["input"] = a["samplers"][0]["output"]; },
         "(input of animation 0 sampler 1) has an unsupported element type"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        GltfBuilder g = avatar(AvatarFormat::Gltf);
        c.edit(g.doc["animations"][0]);
        const std::string bad = dir.write("bad.glb", g.glb());
        const std::string error = load_error(bad, playing("wave", 1));
        EXPECT_EQ(error.rfind(bad + ": ", 0), 0u) << error;
        EXPECT_NE(error.find(c.message), std::string::npos) << error;
        EXPECT_EQ(error.find('\n'), std::string::npos);
        EXPECT_NO_THROW(load_mesh(bad));  // without the animation the file loads
    }
}

}  // namespace
}  // namespace inkshade::test
