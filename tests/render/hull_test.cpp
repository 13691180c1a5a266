// hull (inverted hull silhouette): on the unit sphere the outline ring runs from the projected
// radius to radius + width, in world and screen modes (within 1 px); screen width does not
// change with camera distance or resolution; a cube with split normals does not crack open.
#include <cmath>

#include "geometry/builtin_models.hpp"
#include "render/render_fixture.hpp"
#include "render/sphere_ring.hpp"

namespace inkshade::test {
namespace {

// Unlit flat colours: the surface is exactly base * ambient, the hull blue, the background white.
ShadingSelection flat_green() {
    ShadingSelection s;
    s.model = "lambert";
    s.base_color = glm::vec3(0, 1, 0);
    return s;
}
Light ambient_only() { return directional_light(glm::vec3(0, 0, 1), glm::vec3(0), glm::vec3(1)); }

LineSettings hull(float width_px, const char* mode = "screen", float world_width = 0.25f) {
    LineSettings l{"hull", {}};
    l.params["color"] = {0, 0, 1};
    l.params["width"] = {width_px};
    l.params["mode"] = {std::string(mode) == "world" ? 1.0f : 0.0f};
    l.params["world-width"] = {world_width};
    return l;
}

Image render_sphere(const Camera& camera, const LineSettings& line, int size) {
    Renderer& r = shared_renderer();
    r.set_mesh(fine_sphere());
    RenderOptions o;
    o.width = o.height = size;
    return r.render(camera, ambient_only(), flat_green(), {line}, o);
}

TEST(Hull, ScreenModeRingIsRadiusToRadiusPlusWidth) {
    const float px_per_unit = float(kSize) / ortho_camera().ortho_height;
    for (float width : {2.0f, 5.0f}) {
        Image img = render_sphere(ortho_camera(), hull(width), kSize);
        expect_ring(img, px_per_unit, px_per_unit + width, "screen width " + std::to_string(width));
    }
}

TEST(Hull, WorldModeRingIsRadiusToRadiusPlusWorldWidth) {
    const float px_per_unit = float(kSize) / ortho_camera().ortho_height;
    for (float w : {0.05f, 0.1f}) {
        Image img = render_sphere(ortho_camera(), hull(1.0f, "world", w), kSize);
        expect_ring(img, px_per_unit, (1.0f + w) * px_per_unit, "world width " + std::to_string(w));
    }
}

TEST(Hull, ScreenWidthIsConstantWithDistanceAndResolution) {
    for (float distance : {4.0f, 8.0f})
        for (int size : {256, 384}) {
            Image img = render_sphere(perspective(distance), hull(4.0f), size);
            const float r = silhouette_radius(perspective(distance), size);
            expect_ring(img, r, r + 4.0f, "distance " + std::to_string(distance) + " size " + std::to_string(size));
        }
}

// A cube whose 24 vertices carry per-face normals (split at every crease), seen face-on:
// extruding along the split normals would move the faces apart and leave no outline at all
// (the side faces are edge-on); the welded normals give a closed frame of w / sqrt(3).
TEST(Hull, SplitNormalCubeDoesNotCrackOpen) {
    Mesh cube;
    const glm::vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (const glm::vec3& n : normals) {
        const glm::vec3 u = std::abs(n.x) > 0.5f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
        const glm::vec3 v = glm::cross(n, u);
        const uint32_t base = uint32_t(cube.positions.size());
        for (glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
            cube.positions.push_back(0.5f * (n + c.x * u + c.y * v));
            cube.normals.push_back(n);
        }
        cube.triangles.push_back({base, base + 1, base + 2});
        cube.triangles.push_back({base, base + 2, base + 3});
    }
    Renderer& r = shared_renderer();
    r.set_mesh(cube);
    RenderOptions o;
    o.width = o.height = kSize;
    const float w = 0.15f;
    Image img = r.render(ortho_camera(), ambient_only(), flat_green(), {hull(1, "world", w)}, o);
    const Camera cam = ortho_camera();
    const float frame = 0.5f + 0.5f * w / std::sqrt(3.0f);  // the middle of the outline
    int checked = 0;
    for (float s = -0.45f; s <= 0.45f; s += 0.05f)
        for (glm::vec3 p : {glm::vec3(s, frame, 0.5f), glm::vec3(s, -frame, 0.5f), glm::vec3(frame, s, 0.5f),
                            glm::vec3(-frame, s, 0.5f)}) {
            const glm::vec2 q = project(cam, p);
            EXPECT_EQ(kind_of(img.pixel(int(q.x), int(q.y))), Kind::Line) << "no outline at " << q.x << "," << q.y;
            ++checked;
        }
    EXPECT_GT(checked, 60);
}

}  // namespace
}  // namespace inkshade::test
