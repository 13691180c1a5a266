// silhouette and external-contour (docs/lines.md): a sphere in front of a larger one is all
// silhouette (the background or the other sphere behind it) but none of it external contour
// (the other sphere is behind all of it); the back sphere's outline is both. A torus seen from
// above at a slant: its inner rim lies over its own far side, contour but neither.
#include "geometry/contour_backgrounds.hpp"

#include <gtest/gtest.h>

#include "geometry/builtin_models.hpp"
#include "geometry/connected_objects.hpp"
#include "inkshade/line_drawing.hpp"

namespace inkshade::geometry {
namespace {

Mesh append(Mesh a, const Mesh& b, const glm::vec3& offset) {
    const uint32_t base = uint32_t(a.positions.size());
    for (const glm::vec3& p : b.positions) a.positions.push_back(p + offset);
    a.normals.insert(a.normals.end(), b.normals.begin(), b.normals.end());
    for (const glm::uvec3& t : b.triangles) a.triangles.push_back(t + glm::uvec3(base));
    return a;
}

Camera camera_at(const glm::vec3& eye, const glm::vec3& up = {0, 1, 0}) {
    Camera c;
    c.eye = eye;
    c.target = glm::vec3(0.0f);
    c.up = up;
    c.fov_degrees = 35.0f;
    c.near_plane = 0.5f;
    c.far_plane = 30.0f;
    return c;
}

struct Classified {
    std::vector<LineSegment> contours;
    std::vector<Behind> behind;
};

Classified classify(const Mesh& mesh, const Camera& camera) {
    RayScene scene(mesh);
    Classified c;
    c.contours = extract_contours(mesh, mesh.normals, camera);
    c.behind = behind_contours(mesh, mesh.normals, camera, scene, c.contours, face_objects(mesh));
    return c;
}

// Sphere A (r = 1) at the origin in front of sphere B (r = 1.5) at z = −3, seen from z = 8: A's
// outline (angular radius 1/8) lies inside B's (1.5/11).
TEST(ContourBackgrounds, SphereInFrontOfSphere) {
    const Mesh a = builtin::sphere(48, 96, 1.0f);
    const Mesh both = append(a, builtin::sphere(48, 96, 1.5f), {0.0f, 0.0f, -3.0f});
    const size_t a_faces = a.triangles.size();
    const Classified c = classify(both, camera_at({0.0f, 0.0f, 8.0f}));
    size_t a_count = 0, b_count = 0;
    for (size_t i = 0; i < c.contours.size(); ++i) {
        if (c.contours[i].face < a_faces) {
            ++a_count;
            EXPECT_EQ(c.behind[i], Behind::OtherObject) << "front sphere's contour: the back sphere is behind";
        } else {
            ++b_count;
            EXPECT_EQ(c.behind[i], Behind::Nothing) << "back sphere's contour: the background is behind";
        }
    }
    EXPECT_GT(a_count, 50u);
    EXPECT_GT(b_count, 50u);
    // Drawn: silhouette = both outlines, external-contour = the back sphere's only.
    LineExtractor extractor(both);
    const LineDrawing d = extractor.draw(camera_at({0.0f, 0.0f, 8.0f}), 400, 400,
                                         {{"contour", {}}, {"silhouette", {}}, {"external-contour", {}}});
    ASSERT_EQ(d.layers.size(), 3u);
    EXPECT_EQ(d.layers[0].visible.size(), 2u);
    EXPECT_EQ(d.layers[1].visible.size(), 2u);
    ASSERT_EQ(d.layers[2].visible.size(), 1u);
    for (const glm::vec2& p : d.layers[2].visible[0].points)  // on B's outline, outside A's
        EXPECT_GT(glm::length(p - glm::vec2(200.0f)),
                  0.5f * 400 * std::tan(std::asin(1.0 / 8.0)) / std::tan(glm::radians(17.5)) + 5.0f);
}

// The torus (axis z) from 15° above its plane: the ray past its near inner rim meets the far side
// of the tube, so that rim is contour but not silhouette nor external contour; its outer
// outline has the background behind it.
TEST(ContourBackgrounds, TorusInnerRimIsNotExternal) {
    const Mesh torus = builtin::torus(1.0f, 0.4f, 128, 64);
    const Camera camera = camera_at({0.0f, -6.0f * std::cos(glm::radians(15.0f)), 6.0f * std::sin(glm::radians(15.0f))},
                                    {0.0f, 0.0f, 1.0f});
    const Classified c = classify(torus, camera);
    size_t inner = 0, outer = 0;
    for (size_t i = 0; i < c.contours.size(); ++i) {
        const glm::vec3 m = 0.5f * (c.contours[i].a + c.contours[i].b);
        const float from_axis = glm::length(glm::vec2(m));
        // The near inner rim: inside the tube's centre circle, on the camera's side (y < 0).
        if (from_axis < 1.0f && m.y < -0.3f) {
            ++inner;
            EXPECT_EQ(c.behind[i], Behind::SameObject) << m.x << "," << m.y << "," << m.z;
        } else if (from_axis > 1.2f) {
            ++outer;
            EXPECT_EQ(c.behind[i], Behind::Nothing) << m.x << "," << m.y << "," << m.z;
        }
    }
    EXPECT_GT(inner, 20u);
    EXPECT_GT(outer, 50u);
}

}  // namespace
}  // namespace inkshade::geometry
