// Back faces are shaded only where the mesh is really seen from behind (render/back_faces.hpp):
// tiny reversed triangles lying on (or just in front of) a front-facing plane, as the folds of
// a scan, leave the picture, its G-buffer lines and its hull exactly as the plain plane's,
// from the front and at a grazing 60 degrees, and so do triangles wound against their
// neighbours (their normals turn to the viewer only when they face away); the inside of an open cup and a single-sided
// plane seen from below are still shaded with the normal turned towards the viewer, and a
// reversed patch well in front of the plane still shows.
#include <cmath>

#include "render/back_faces.hpp"
#include "render/render_fixture.hpp"

namespace inkshade::test {
namespace {

// World size of one pixel at the plane under the orthographic test camera.
const float kFootprint = ortho_camera().ortho_height / float(kSize);

// The square [-1, 1]^2 at z = 0 as a grid of quads, facing +z.
Mesh plane(int n = 8) {
    Mesh m;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            m.positions.push_back({-1.0f + 2.0f * float(i) / float(n), -1.0f + 2.0f * float(j) / float(n), 0.0f});
            m.normals.push_back({0, 0, 1});
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const uint32_t a = uint32_t(j * (n + 1) + i), b = a + 1, c = a + uint32_t(n + 1), d = c + 1;
            m.triangles.push_back({a, b, d});
            m.triangles.push_back({a, d, c});
        }
    return m;
}

// Adds a triangle wound clockwise seen from +z (a back face from the front) of `size` world
// units at (x, y), `lift` above the plane: a fold of a scan, whose vertex normals follow the
// (here bumpier) surface around it, facing the viewer but not along the plane's normal, so the
// fold would shade differently from the plane if it were seen.
void add_fold(Mesh& m, float x, float y, float size, float lift) {
    const uint32_t base = uint32_t(m.positions.size());
    m.positions.push_back({x, y, lift});
    m.positions.push_back({x, y + size, lift});
    m.positions.push_back({x + size, y, lift});
    for (int k = 0; k < 3; ++k) m.normals.push_back(glm::normalize(glm::vec3(0.4f, -0.3f, 1.0f)));
    m.triangles.push_back({base, base + 1, base + 2});
}

// The plane with folds of 0.5 to 3 pixels, lying on it or lifted by up to half a pixel.
Mesh folded_plane() {
    Mesh m = plane();
    int k = 0;
    for (float size : {0.5f, 1.0f, 2.0f, 3.0f})
        for (float lift : {0.0f, 0.25f, 0.5f}) {
            const float x = -0.8f + 0.13f * float(k % 12), y = -0.7f + 0.37f * float(k / 4);
            add_fold(m, x, y, size * kFootprint, lift * kFootprint);
            ++k;
        }
    return m;
}

Light side_light() { return directional_light(glm::vec3(0.3f, 0.2f, 1.0f), glm::vec3(0.9f), glm::vec3(0.1f)); }

ShadingSelection lambert() {
    ShadingSelection s;
    s.model = "lambert";
    s.base_color = glm::vec3(0.8f, 0.6f, 0.4f);
    return s;
}

RenderOptions options() {
    RenderOptions o;
    o.width = o.height = kSize;
    o.background = glm::vec4(1, 0, 0, 1);
    return o;
}

Image render(const Mesh& mesh, const Camera& camera, const std::vector<LineSettings>& lines = {}) {
    Renderer& r = shared_renderer();
    r.set_mesh(mesh);
    return r.render(camera, side_light(), lambert(), lines, options());
}

// Perspective view of the plane from 60 degrees off its normal, about as large as the
// orthographic one.
Camera grazing_camera() {
    Camera c;
    const float t = glm::radians(60.0f);
    c.eye = 4.0f * glm::vec3(0.0f, -std::sin(t), std::cos(t));
    c.target = glm::vec3(0);
    c.up = {0, 0, 1};
    c.fov_degrees = 30.0f;
    c.near_plane = 1.0f;
    c.far_plane = 10.0f;
    return c;
}

int differing_pixels(const Image& a, const Image& b) {
    int n = 0;
    for (size_t i = 0; i < a.rgba.size(); i += 4)
        n += a.rgba[i] != b.rgba[i] || a.rgba[i + 1] != b.rgba[i + 1] || a.rgba[i + 2] != b.rgba[i + 2];
    return n;
}

glm::vec3 lambert_formula(const glm::vec3& n) {
    const Light l = side_light();
    const glm::vec3 to_light = glm::normalize(l.position - l.target);
    return lambert().base_color * (l.color * std::max(glm::dot(n, to_light), 0.0f) + l.ambient);
}

void expect_colour(const Image& img, int x, int y, const glm::vec3& want, const std::string& what) {
    const uint8_t* got = img.pixel(x, y);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(int(got[c]), to_byte(want[c]), 2) << what << " channel " << c;
}

TEST(BackFaces, FoldsOnAFrontFacingPlaneLeaveNoSpecks) {
    const Mesh plain = plane(), folded = folded_plane();
    for (const Camera& camera : {ortho_camera(), grazing_camera()}) {
        const std::string view = camera.orthographic ? "front" : "grazing";
        EXPECT_EQ(differing_pixels(render(plain, camera), render(folded, camera)), 0) << view;
        // The G-buffer the image-space lines read and the hull's back-face shell see the same
        // surface as the shading pass.
        for (const char* type : {"edges", "suggestive-image", "hull"}) {
            const std::vector<LineSettings> lines{{type, {}}};
            EXPECT_EQ(differing_pixels(render(plain, camera, lines), render(folded, camera, lines)), 0)
                << view << " with " << type;
        }
    }
}

// A non-manifold scan's triangles wound against their neighbours (back faces in place, nothing
// behind them) whose vertex normals follow the surface: lit as the surface, not as dark specks.
TEST(BackFaces, TrianglesWoundAgainstTheirNeighboursLeaveNoSpecks) {
    const Mesh plain = plane();
    Mesh flipped = plain;
    for (size_t t : {5u, 40u, 77u, 100u}) std::swap(flipped.triangles[t].y, flipped.triangles[t].z);
    for (const Camera& camera : {ortho_camera(), grazing_camera()})
        for (const char* type : {"", "edges", "suggestive-image", "rim-contour"}) {
            std::vector<LineSettings> lines;
            if (*type) lines.push_back({type, {}});
            EXPECT_EQ(differing_pixels(render(plain, camera, lines), render(flipped, camera, lines)), 0)
                << (camera.orthographic ? "front" : "grazing") << " with " << type;
        }
}

// The tolerance is about a pixel: a reversed patch 20 pixels in front of the plane is seen
// from behind and lit with its normal turned towards the viewer.
TEST(BackFaces, ReversedPatchWellInFrontOfThePlaneStillShows) {
    Mesh m = plane();
    const float lift = 20.0f * kFootprint;
    const uint32_t base = uint32_t(m.positions.size());
    for (const glm::vec3& p : {glm::vec3(-0.2f, -0.2f, lift), glm::vec3(-0.2f, 0.2f, lift), glm::vec3(0.2f, 0.2f, lift),
                               glm::vec3(0.2f, -0.2f, lift)}) {
        m.positions.push_back(p);
        m.normals.push_back(glm::normalize(glm::vec3(0.5f, 0.0f, -1.0f)));  // turned: (-0.5, 0, 1)
    }
    m.triangles.push_back({base, base + 1, base + 2});  // clockwise from +z: back faces
    m.triangles.push_back({base, base + 2, base + 3});
    const Image img = render(m, ortho_camera());
    expect_colour(img, kSize / 2, kSize / 2, lambert_formula(glm::normalize(glm::vec3(-0.5f, 0.0f, 1.0f))), "patch");
    expect_colour(img, kSize / 2 + 60, kSize / 2, lambert_formula({0, 0, 1}), "plane beside it");
}

// A single-sided plane seen from below has only back faces: shaded with the normal -z.
TEST(BackFaces, SingleSidedPlaneSeenFromBelowIsShaded) {
    Camera below = ortho_camera();
    below.eye = {0, 0, -5};
    Renderer& r = shared_renderer();
    r.set_mesh(plane());
    const Light light = directional_light(glm::vec3(0.3f, 0.2f, -1.0f), glm::vec3(0.9f), glm::vec3(0.1f));
    const Image img = r.render(below, light, lambert(), options());
    const glm::vec3 to_light = glm::normalize(light.position - light.target);
    const glm::vec3 want =
        lambert().base_color * (light.color * std::max(-to_light.z, 0.0f) * 1.0f + light.ambient);  // n = -z
    for (int x : {40, 128, 200}) expect_colour(img, x, 128, want, "from below x=" + std::to_string(x));
}

// An open cup (a cylinder with a bottom, no top; normals outward) seen from straight above:
// through the opening the inside of the bottom is seen from behind and lit with +z; outside
// the cup the background.
TEST(BackFaces, InsideOfAnOpenCupIsShaded) {
    Mesh cup;
    const int n = 64;
    const float radius = 0.8f;
    for (int i = 0; i < n; ++i) {
        const float a = 2.0f * float(M_PI) * float(i) / float(n);
        const glm::vec3 d(std::cos(a), std::sin(a), 0.0f);
        cup.positions.push_back(radius * d + glm::vec3(0, 0, -0.5f));  // 2i: bottom rim
        cup.positions.push_back(radius * d + glm::vec3(0, 0, 0.5f));   // 2i + 1: top rim
        cup.normals.push_back(d);
        cup.normals.push_back(d);
    }
    for (int i = 0; i < n; ++i) {
        const uint32_t a = uint32_t(2 * i), b = uint32_t(2 * ((i + 1) % n));
        cup.triangles.push_back({a, b, b + 1});  // wall, outward
        cup.triangles.push_back({a, b + 1, a + 1});
    }
    const uint32_t centre = uint32_t(cup.positions.size());
    cup.positions.push_back({0, 0, -0.5f});
    cup.normals.push_back({0, 0, -1});
    const uint32_t bottom = uint32_t(cup.positions.size());
    for (int i = 0; i < n; ++i) {
        cup.positions.push_back(cup.positions[size_t(2 * i)]);
        cup.normals.push_back({0, 0, -1});
    }
    for (int i = 0; i < n; ++i)  // clockwise from +z: the bottom faces down, out of the cup
        cup.triangles.push_back({centre, bottom + uint32_t((i + 1) % n), bottom + uint32_t(i)});
    const Image img = render(cup, ortho_camera());
    for (int dx : {-60, 0, 40}) expect_colour(img, kSize / 2 + dx, kSize / 2, lambert_formula({0, 0, 1}), "bottom");
    const uint8_t* corner = img.pixel(4, 4);
    EXPECT_EQ(int(corner[0]), 255);  // background
    EXPECT_EQ(int(corner[1]), 0);
}

// The push moves a point one pixel footprint farther along its view ray and keeps its image.
TEST(BackFaces, PushIsOnePixelFootprintAlongTheRay) {
    for (bool orthographic : {true, false}) {
        Camera c = grazing_camera();
        c.orthographic = orthographic;
        const int height = 300;
        const float aspect = 1.5f;
        const glm::mat4 view = c.view(), proj = c.projection(aspect);
        const glm::vec3 p(0.3f, -0.2f, 0.1f);
        const glm::vec4 clip = proj * view * glm::vec4(p, 1.0f);
        glm::vec4 pushed = clip;
        pushed.z += render::back_face_depth_push(c, aspect, height);
        // Back to view space: the pushed point's distance along view z.
        const glm::vec4 v0 = glm::inverse(proj) * clip, v1 = glm::inverse(proj) * pushed;
        const float z0 = -v0.z / v0.w, z1 = -v1.z / v1.w;
        const float footprint = orthographic ? c.ortho_height / float(height)
                                             : z0 * 2.0f * std::tan(0.5f * glm::radians(c.fov_degrees)) / float(height);
        EXPECT_NEAR(z1 - z0, render::kBackFaceTolerancePx * footprint, 1e-3f * footprint) << orthographic;
        // On the same view ray: the same view-space x, y (orthographic) or x/z, y/z.
        const glm::vec3 p0 = glm::vec3(v0) / v0.w, p1 = glm::vec3(v1) / v1.w;
        const glm::vec2 ray0 = orthographic ? glm::vec2(p0) : glm::vec2(p0) / p0.z;
        const glm::vec2 ray1 = orthographic ? glm::vec2(p1) : glm::vec2(p1) / p1.z;
        EXPECT_NEAR(ray1.x, ray0.x, 1e-5f) << orthographic;
        EXPECT_NEAR(ray1.y, ray0.y, 1e-5f) << orthographic;
    }
}

}  // namespace
}  // namespace inkshade::test
