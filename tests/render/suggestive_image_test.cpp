// suggestive-image (image-space suggestive contours on the GPU; DeCarlo et al. 2003): on the height
// field z = A sin(kx) (extruded along y) the radial curvature vanishes on the inflection
// lines x = n pi / k, so D_w(n.v) = 0 there; seen from direction (sin t, 0, cos t) with
// tan t > A k, w points along +x everywhere, D_w D_w(n.v) has the sign of cos(k x_n), and
// suggestive contours lie only on the inflections with cos(k x_n) > 0 (x = 2 m pi / k, slopes
// facing away). Lines appear there (within 2 px) and nowhere else; none on a sphere or a plane.
// Convex shapes have no suggestive contours (radial curvature > 0): none on a subdivided cube
// whose normals bend smoothly over its edges (a CAD part without split normals) nor on coarse
// spheres, where differences finer than a triangle used to draw a dash at every edge; on a
// torus, fine or coarse, every line pixel lies on the analytic suggestive contour.
#include <cmath>
#include <map>
#include <optional>

#include "geometry/builtin_models.hpp"
#include "geometry/normals.hpp"
#include "render/render_fixture.hpp"

namespace inkshade::test {
namespace {

constexpr float kK = 7.5f;          // wave number: about 60 px per period in the image
constexpr float kA = 0.5f / kK;     // A k = 0.5 (slopes of 27 degrees)
constexpr float kTilt = 0.610865f;  // 35 degrees: tan = 0.7 > A k; n.v >= 0.47 on every slope

Mesh height_field() {
    Mesh m;
    const int nx = 1200, ny = 8;
    const float x0 = -3.0f, x1 = 3.0f, y0 = -1.6f, y1 = 1.6f;
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) {
            const float x = x0 + (x1 - x0) * float(i) / nx, y = y0 + (y1 - y0) * float(j) / ny;
            m.positions.push_back({x, y, kA * std::sin(kK * x)});
            m.normals.push_back(glm::normalize(glm::vec3(-kA * kK * std::cos(kK * x), 0.0f, 1.0f)));
        }
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const uint32_t a = uint32_t(j * (nx + 1) + i), b = a + 1, c = a + uint32_t(nx + 1), d = c + 1;
            m.triangles.push_back({a, b, d});
            m.triangles.push_back({a, d, c});
        }
    return m;
}

Camera tilted_camera() {
    Camera c = ortho_camera();
    c.eye = 5.0f * glm::vec3(std::sin(kTilt), 0.0f, std::cos(kTilt));
    return c;
}

LineSettings suggestive() {
    LineSettings l{"suggestive-image", {}};
    l.params["color"] = {0, 0, 0};
    l.params["width"] = {2.0f};
    return l;
}

Image render_with_lines(const Mesh& mesh, const Camera& camera, int size = kSize) {
    Renderer& r = shared_renderer();
    r.set_mesh(mesh);
    RenderOptions o;
    o.width = o.height = size;
    ShadingSelection s;
    s.model = "lambert";
    s.base_color = glm::vec3(1.0f);
    Light light = directional_light(glm::vec3(0, 0, 1), glm::vec3(0), glm::vec3(1));  // white, unlit
    return r.render(camera, light, s, {suggestive()}, o);
}

bool dark(const Image& img, int x, int y) { return img.pixel(x, y)[0] < 128; }

TEST(SuggestiveImage, HeightFieldLinesOnlyOnInflectionsFacingAway) {
    Image img = render_with_lines(height_field(), tilted_camera());
    // Image x of the inflection line x_n (z = 0): its coordinate along the camera's right
    // axis (cos t, 0, -sin t).
    const float half = 0.5f * ortho_camera().ortho_height;
    auto image_x = [&](float x) { return (x * std::cos(kTilt) / half + 1.0f) * 0.5f * float(kSize); };
    std::vector<float> expected, rejected;
    for (int n = -20; n <= 20; ++n) {
        const float px = image_x(float(n) * float(M_PI) / kK);
        if (px < 8.0f || px > float(kSize) - 8.0f) continue;
        (n % 2 == 0 ? expected : rejected).push_back(px);
    }
    ASSERT_GE(expected.size(), 3u);
    ASSERT_GE(rejected.size(), 3u);
    // Each expected line: a dark pixel within 2 px on (almost) every row away from the border.
    for (float px : expected) {
        int rows = 0, found = 0;
        for (int y = 16; y < kSize - 16; ++y, ++rows) {
            bool hit = false;
            for (int x = int(std::floor(px - 2.0f)); x <= int(std::floor(px + 2.0f)); ++x) hit = hit || dark(img, x, y);
            found += hit;
        }
        EXPECT_GE(found, rows * 95 / 100) << "line at x = " << px;
    }
    // Every dark pixel is within 2 px of an expected line (none at the other inflections).
    int dark_pixels = 0;
    for (int y = 16; y < kSize - 16; ++y)
        for (int x = 8; x < kSize - 8; ++x) {
            if (!dark(img, x, y)) continue;
            ++dark_pixels;
            float d = INFINITY;
            for (float px : expected) d = std::min(d, std::abs(float(x) + 0.5f - px));
            EXPECT_LE(d, 2.5f) << "stray suggestive pixel " << x << "," << y;
            if (d > 2.5f) return;
        }
    EXPECT_GT(dark_pixels, 200);
}

TEST(SuggestiveImage, NoneOnSphereOrPlane) {
    Mesh plane;
    plane.positions = {{-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0}};
    plane.normals.assign(4, glm::vec3(0, 0, 1));
    plane.triangles = {{0, 1, 2}, {0, 2, 3}};
    for (const Mesh* m : std::vector<const Mesh*>{&fine_sphere(), &plane})
        for (const Camera& c : {ortho_camera(), tilted_camera()}) {
            Image img = render_with_lines(*m, c);
            int count = 0;
            for (int y = 0; y < kSize; ++y)
                for (int x = 0; x < kSize; ++x) count += dark(img, x, y);
            EXPECT_EQ(count, 0) << (m == &plane ? "plane" : "sphere");
        }
}

// Pixels a line darkened by more than 1/8 (the surface is exactly white): a faint pixel where
// the fade barely lets a weak valley through is no mark.
int line_pixels(const Image& img) {
    int n = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) n += img.pixel(x, y)[0] < 224;
    return n;
}

// Orthographic camera looking at the origin from direction `from`, `height` units high.
Camera ortho_from(const glm::vec3& from, float height, const glm::vec3& up = {0, 0, 1}) {
    Camera c = ortho_camera();
    c.eye = 5.0f * glm::normalize(from);
    c.up = up;
    c.ortho_height = height;
    return c;
}

Camera perspective_from(const glm::vec3& from) {
    Camera c;
    c.eye = 4.5f * glm::normalize(from);
    c.up = {0, 0, 1};
    c.fov_degrees = 30.0f;
    c.near_plane = 1.0f;
    c.far_plane = 10.0f;
    return c;
}

// The cube [-1, 1]^3 with an n x n grid on each face, welded along its edges, with
// angle-weighted vertex normals: flat faces whose normals bend over the edges' triangles.
Mesh subdivided_cube(int n) {
    Mesh m;
    std::map<std::tuple<int, int, int>, uint32_t> index;
    const auto vertex = [&](glm::ivec3 g) {
        auto [it, added] = index.try_emplace({g.x, g.y, g.z}, uint32_t(m.positions.size()));
        if (added) m.positions.push_back(glm::vec3(g) * (2.0f / float(n)) - 1.0f);
        return it->second;
    };
    for (int axis = 0; axis < 3; ++axis)
        for (int side : {0, n}) {
            const int u_axis = (axis + 1) % 3, v_axis = (axis + 2) % 3;
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    const auto at = [&](int a, int b) {
                        glm::ivec3 g(0);
                        g[axis] = side, g[u_axis] = a, g[v_axis] = b;
                        return vertex(g);
                    };
                    const uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
                    // u x v is +axis: counter-clockwise seen from outside on the far side.
                    if (side == n) {
                        m.triangles.push_back({a, b, c});
                        m.triangles.push_back({a, c, d});
                    } else {
                        m.triangles.push_back({a, c, b});
                        m.triangles.push_back({a, d, c});
                    }
                }
        }
    m.normals = geometry::angle_weighted_vertex_normals(m);
    return m;
}

TEST(SuggestiveImage, NoneOnASubdividedCube) {
    const Mesh cube = subdivided_cube(8);
    for (const glm::vec3& from :
         {glm::vec3(1.0f, 0.7f, 0.5f), glm::vec3(-0.4f, 1.0f, 0.8f), glm::vec3(0.3f, 0.2f, 1.0f)}) {
        EXPECT_EQ(line_pixels(render_with_lines(cube, ortho_from(from, 4.0f), 512)), 0) << "ortho " << from.x;
        EXPECT_EQ(line_pixels(render_with_lines(cube, perspective_from(from), 512)), 0) << "perspective " << from.x;
    }
}

TEST(SuggestiveImage, NoneOnCoarseSpheres) {
    for (const Mesh& sphere : {builtin::sphere(6, 12), builtin::sphere(12, 24), builtin::sphere(24, 48)})
        for (const glm::vec3& from : {glm::vec3(0.2f, 1.0f, 0.4f), glm::vec3(1.0f, -0.3f, 0.1f)})
            EXPECT_EQ(line_pixels(render_with_lines(sphere, ortho_from(from, 2.5f), 512)), 0)
                << sphere.triangles.size() << " triangles";
}

// The torus of builtin::torus (axis z, radii kMajor and kMinor) as a surface: its nearest point
// to p, and there the radial curvature for the view direction v (towards the viewer),
// k_r = (k_u (w.e_u)^2 + k_phi (w.e_phi)^2) / |w|^2 with w = v - (n.v) n and principal
// curvatures k_u = cos(phi) / (distance to the axis) around the axis, k_phi = 1 / r around the
// tube.
constexpr float kMajor = 1.0f, kMinor = 0.4f;

glm::dvec3 onto_torus(const glm::dvec3& p) {
    const glm::dvec3 axis_point = double(kMajor) * glm::normalize(glm::dvec3(p.x, p.y, 0.0));
    return axis_point + double(kMinor) * glm::normalize(p - axis_point);
}

double radial_curvature(const glm::dvec3& p, const glm::dvec3& v) {
    const glm::dvec3 c = double(kMajor) * glm::normalize(glm::dvec3(p.x, p.y, 0.0));
    const glm::dvec3 n = glm::normalize(p - c);
    const double rho = std::hypot(p.x, p.y), cos_phi = glm::dot(n, glm::normalize(c));
    const glm::dvec3 e_u = glm::normalize(glm::dvec3(-p.y, p.x, 0.0)), e_phi = glm::cross(n, e_u);
    const glm::dvec3 w = v - glm::dot(n, v) * n;
    const double wu = glm::dot(w, e_u), wp = glm::dot(w, e_phi);
    return (cos_phi / rho * wu * wu + wp * wp / double(kMinor)) / glm::dot(w, w);
}

// First hit of the ray o - t v (t > 0) on the torus, marching its implicit function.
std::optional<glm::dvec3> hit_torus(const glm::dvec3& o, const glm::dvec3& v) {
    const double R2 = double(kMajor) * kMajor, r2 = double(kMinor) * kMinor;
    const auto F = [&](const glm::dvec3& p) {
        const double s = glm::dot(p, p) + R2 - r2;
        return s * s - 4.0 * R2 * (p.x * p.x + p.y * p.y);
    };
    double t0 = 0.0, f0 = F(o);
    for (double t = 1e-3; t < 10.0; t += 1e-3) {
        const double f = F(o - t * v);
        if ((f < 0.0) != (f0 < 0.0)) {
            double a = t0, b = t;
            for (int i = 0; i < 50; ++i) {
                const double m = 0.5 * (a + b);
                ((F(o - m * v) < 0.0) == (f0 < 0.0) ? a : b) = m;
            }
            return o - 0.5 * (a + b) * v;
        }
        t0 = t, f0 = f;
    }
    return std::nullopt;
}

// Each line pixel of a torus seen from above its equatorial plane lies within `tolerance_px`
// of the analytic suggestive contour: where k_r changes sign (the distance is |k_r| over its
// rate of change along w, in pixels), with k_r growing along w (D_w k_r > 0), on the inner
// half (distance to the axis < R, where k_u < 0 makes k_r = 0 possible).
void expect_on_analytic_contours(const Mesh& torus, float tolerance_px, const std::string& what) {
    constexpr int size = 512;
    const Camera camera = ortho_from(glm::vec3(0.3f, 0.5f, 0.3f), 3.2f);
    const Image img = render_with_lines(torus, camera, size);
    const glm::dvec3 v = glm::normalize(glm::dvec3(camera.eye - camera.target));
    const glm::dvec3 right = glm::normalize(glm::cross(glm::dvec3(camera.up), v)), up = glm::cross(v, right);
    const double px_per_unit = double(size) / camera.ortho_height;
    int lines = 0, checked = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            if (img.pixel(x, y)[0] >= 128) continue;  // darker than half: the line's core
            ++lines;
            const glm::dvec3 o = glm::dvec3(camera.eye) + (x + 0.5 - 0.5 * size) / px_per_unit * right +
                                 (0.5 * size - y - 0.5) / px_per_unit * up;
            const std::optional<glm::dvec3> p = hit_torus(o, v);
            if (!p) continue;  // the mesh's silhouette differs from the torus's by a pixel
            ++checked;
            EXPECT_LT(std::hypot(p->x, p->y), kMajor) << what << " pixel " << x << "," << y;
            const glm::dvec3 c = double(kMajor) * glm::normalize(glm::dvec3(p->x, p->y, 0.0));
            const glm::dvec3 n = glm::normalize(*p - c), w = glm::normalize(v - glm::dot(n, v) * n);
            const double step = 1e-4, k = radial_curvature(*p, v);
            const double dk =
                (radial_curvature(onto_torus(*p + step * w), v) - radial_curvature(onto_torus(*p - step * w), v)) /
                (2.0 * step);
            EXPECT_GT(dk, 0.0) << what << " pixel " << x << "," << y;
            // Moving along w by s moves the image by s |w - (w.v) v|.
            const double distance_px = std::abs(k) / std::abs(dk) * glm::length(w - glm::dot(w, v) * v) * px_per_unit;
            EXPECT_LE(distance_px, tolerance_px) << what << " pixel " << x << "," << y << " k_r " << k;
        }
    EXPECT_GT(lines, 40) << what;
    EXPECT_GT(checked, lines * 9 / 10) << what;
}

TEST(SuggestiveImage, TorusLinesLieOnTheAnalyticContours) {
    expect_on_analytic_contours(builtin::torus(kMajor, kMinor, 128, 64), 2.0f, "128 x 64 torus");
    expect_on_analytic_contours(builtin::torus(kMajor, kMinor, 48, 24), 3.0f, "48 x 24 torus");
}

}  // namespace
}  // namespace inkshade::test
