// A posed scene: the avatar's animation sampled at two times moves the red ball at its hand to
// where the analytic joints put it, within a pixel of the projection through the scene's own
// camera; the request's pose reaches the loader through Scene::load_options.
#include <gtest/gtest.h>

#include "cli/run_cli.hpp"
#include "inkshade/io.hpp"
#include "inkshade/renderer.hpp"
#include "inkshade/scene.hpp"
#include "io/avatar_files.hpp"
#include "support/temp_dir.hpp"

namespace inkshade::test {
namespace {

// The centre of the red pixels, each weighted by how red it is (its coverage of the unlit red
// ball over a white background or the avatar's paler colours); pixels less than a quarter red
// are left out on every side alike.
glm::vec2 red_centroid(const Image& image, int& count) {
    glm::dvec2 sum(0.0);
    double weight = 0.0;
    count = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const uint8_t* p = image.pixel(x, y);
            const double red = double(p[0]) - double(std::max(p[1], p[2]));
            if (red < 64.0) continue;
            sum += red * glm::dvec2(x + 0.5, y + 0.5);
            weight += red;
            ++count;
        }
    return weight > 0.0 ? glm::vec2(sum / weight) : glm::vec2(-1.0f);
}

// Pixel coordinates (x right, y down, pixel centres at +0.5) of a world point.
glm::vec2 project(const Camera& camera, glm::vec3 p, int width, int height) {
    const glm::vec4 clip = camera.projection(float(width) / float(height)) * camera.view() * glm::vec4(p, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {(ndc.x + 1.0f) * 0.5f * float(width), (1.0f - ndc.y) * 0.5f * float(height)};
}

TEST(PosedScene, AnimatedHandIsWithinAPixelOfTheAnalyticJoint) {
    TempDir dir;
    const std::string path = dir.write("avatar.vrm", avatar(AvatarFormat::Vrm1).glb());
    Renderer renderer;
    glm::vec2 previous(-100.0f);
    for (float t : {0.6f, 1.6f}) {
        SCOPED_TRACE(t);
        SceneRequest r;
        r.model = path;
        r.size = {320, 320};
        r.camera.azimuth_degrees = 0.0f;  // from +z: the arm moves in the image plane
        r.camera.elevation_degrees = 0.0f;
        r.camera.orthographic = true;  // a ball's image is a disc centred on its centre's image
        r.background = glm::vec4(1.0f);
        r.animation = "wave";
        r.time = t;
        const Scene scene = make_scene(r);
        EXPECT_EQ(scene.load_options().pose.time, t);
        const Mesh mesh = load_mesh(scene.model, scene.load_options());
        const Camera camera = scene.frame(mesh);
        renderer.set_mesh(mesh);
        const Image image = render_scene(renderer, scene, camera, scene.light(mesh.bounds(), camera));
        // The shoulder turns 45 degrees a second; the ball rides on the forearm.
        const float shoulder = kWaveEndDegrees * t / kWaveEndSeconds;
        const glm::vec3 ball = glm::vec3(avatar_lower_arm(shoulder) * glm::vec4(kHandBall - kElbow, 1.0f));
        const glm::vec2 expected = project(camera, ball, 320, 320);
        int count = 0;
        const glm::vec2 found = red_centroid(image, count);
        EXPECT_GT(count, 20);
        EXPECT_LT(glm::length(found - expected), 1.0f)
            << found.x << "," << found.y << " vs " << expected.x << "," << expected.y;
        EXPECT_GT(glm::length(found - previous), 20.0f);  // it moved
        previous = found;
    }
}

// `inkshade render` with --animation, --time, --expression and --morph writes the bytes the
// library renders for the same request, and not those of the file's own pose.
TEST(PosedScene, CommandLinePoseIsTheRequestsPose) {
    TempDir dir;
    const std::string path = dir.write("avatar.vrm", avatar(AvatarFormat::Vrm1).glb());
    SceneRequest r;
    r.model = path;
    r.style = "mtoon";
    r.size = {120, 96};
    r.animation = "wave";
    r.time = 1.5f;
    r.expressions = {{"happy", 1.0f}};
    r.morphs = {{"blink", 0.5f}};
    const Scene scene = make_scene(r);
    const Mesh mesh = load_mesh(scene.model, scene.load_options());
    const Camera camera = scene.frame(mesh);
    Renderer renderer;
    renderer.set_mesh(mesh);
    write_png(dir.file("lib.png"), render_scene(renderer, scene, camera, scene.light(mesh.bounds(), camera)));
    const std::string options = " --style mtoon --size 120x96 -o ";
    auto cli = run_cli("render " + path + " --animation wave --time 1.5 --expression happy=1 --morph blink=0.5" +
                       options + dir.file("cli.png"));
    ASSERT_EQ(cli.status, 0) << cli.err;
    cli = run_cli("render " + path + options + dir.file("rest.png"));
    ASSERT_EQ(cli.status, 0) << cli.err;
    EXPECT_EQ(slurp(dir.file("cli.png")), slurp(dir.file("lib.png")));
    EXPECT_NE(slurp(dir.file("rest.png")), slurp(dir.file("lib.png")));
}

}  // namespace
}  // namespace inkshade::test
