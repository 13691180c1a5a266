// Spring bones against three-vrm 3.5.5: the sample avatar's ponytail (scripts/avatar-sample
// --spring-hair: four joints, a sphere collider on the head and a capsule on the back, gravity)
// swinging while the animation "sway" tilts the head, its nodes' world positions at 0.5 s, 1 s
// and 2 s (tilted back, the ponytail on the capsule) as tests/reference/spring_bones.mjs has
// three-vrm place them (the same 1/60 s steps), each within 1e-3 of the avatar's height.
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>

#include <nlohmann/json.hpp>

#include "inkshade/io.hpp"
#include "support/temp_dir.hpp"

namespace inkshade::test {
namespace {

std::string run(const std::string& command) {
    std::string out;
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
    if (!pipe) return out;
    char buffer[4096];
    for (size_t n; (n = fread(buffer, 1, sizeof buffer, pipe.get())) > 0;) out.append(buffer, n);
    return out;
}

TEST(SpringBonesReference, PonytailMatchesThreeVrm) {
    TempDir dir;
    const std::string avatar = dir.file("ponytail.vrm"), source = INKSHADE_SOURCE_DIR;
    ASSERT_EQ(std::system(("python3 '" + source + "/scripts/avatar-sample' --spring-hair '" + avatar + "'").c_str()),
              0);
    const std::string text =
        run("cd '" + source + "/tests/reference' && node spring_bones.mjs '" + avatar + "' sway 0.5 1 2 2>/dev/null");
    const nlohmann::json reference = nlohmann::json::parse(text, nullptr, false);
    ASSERT_TRUE(reference.is_object()) << "tests/reference/spring_bones.mjs (scripts/setup installs three-vrm): "
                                       << text;
    const BoundingBox box = load_mesh(avatar).bounds();
    const double height = box.max.y - box.min.y;
    for (const char* time : {"0.5", "1", "2"}) {
        Pose pose{.animation = "sway", .time = std::stof(time)};
        double worst = 0.0;
        size_t ponytail = 0;
        for (const PosedNode& node : posed_nodes(avatar, pose)) {
            ASSERT_TRUE(reference[time].contains(node.name)) << node.name;
            const auto& p = reference[time][node.name];
            const glm::dvec3 want(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
            worst = std::max(worst, glm::length(node.position - want) / height);
            ponytail += node.name.starts_with("Ponytail");
        }
        EXPECT_EQ(ponytail, 5u);
        EXPECT_LT(worst, 1e-3) << "at " << time << " s";
        std::printf("spring bones vs three-vrm at %s s: largest joint error %.3g of the height\n", time, worst);
    }
}

}  // namespace
}  // namespace inkshade::test
