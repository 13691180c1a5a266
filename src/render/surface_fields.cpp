// Surface fields per pixel (render/surface_fields.hpp): the pixel centre's ray (through the
// inverse view-projection, so perspective and orthographic alike) meets the plane of the face
// drawn there at barycentric coordinates b (Möller & Trumbore 1997, "Fast, Minimum Storage
// Ray/Triangle Intersection"); each field is Σ b_i f_i of its vertex values, the value a
// rasteriser's perspective-correct interpolation gives at the pixel centre.
#include "render/surface_fields.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "geometry/contours.hpp"

namespace inkshade::render {

namespace {

// Barycentric coordinates of where the ray (o, d) meets the plane of triangle (a, b, c),
// clamped into the triangle (a pixel centre on an edge may fall a rounding error outside).
glm::dvec3 ray_barycentrics(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& a, const glm::dvec3& b,
                            const glm::dvec3& c) {
    const glm::dvec3 e1 = b - a, e2 = c - a, p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    if (std::abs(det) < 1e-300 || !std::isfinite(det)) return glm::dvec3(1.0 / 3.0);  // seen edge-on
    const glm::dvec3 s = o - a, q = glm::cross(s, e1);
    const double u = glm::dot(s, p) / det, v = glm::dot(d, q) / det;
    glm::dvec3 w = glm::max(glm::dvec3(1.0 - u - v, u, v), glm::dvec3(0.0));
    const double sum = w.x + w.y + w.z;
    return sum > 0.0 ? w / sum : glm::dvec3(1.0 / 3.0);
}

// One pixel's surface point: the face's vertex indices and their weights.
struct Sample {
    glm::uvec3 v;
    glm::dvec3 b;
    glm::dvec3 p;  // world
    double at(const std::vector<float>& f) const { return b.x * f[v.x] + b.y * f[v.y] + b.z * f[v.z]; }
    glm::dvec3 at(const std::vector<glm::vec3>& f) const {
        return b.x * glm::dvec3(f[v.x]) + b.y * glm::dvec3(f[v.y]) + b.z * glm::dvec3(f[v.z]);
    }
    // A line field (principal directions): each vertex's turned to agree with the first's.
    glm::dvec3 axis_at(const std::vector<glm::vec3>& f) const {
        const glm::dvec3 d0(f[v.x]), d1(f[v.y]), d2(f[v.z]);
        return b.x * d0 + b.y * (glm::dot(d1, d0) < 0.0 ? -d1 : d1) + b.z * (glm::dot(d2, d0) < 0.0 ? -d2 : d2);
    }
};

glm::dvec3 unit(const glm::dvec3& v) {
    const double len = glm::length(v);
    return len > 0.0 && std::isfinite(len) ? v / len : glm::dvec3(0.0);
}

// The unit image-space direction (pixels: x right, y down) of world direction `d` at `p`, the
// derivative of the projection; the sign with x > 0 (or x = 0, y > 0): a principal direction
// is an axis, so this fixes one of its two ends. (0, 0) when it projects to a point.
glm::dvec2 image_direction(const glm::dmat4& view, bool orthographic, const glm::dvec3& p, const glm::dvec3& d) {
    const glm::dvec3 q(view * glm::dvec4(p, 1.0)), e = glm::dmat3(view) * d;
    glm::dvec2 s =
        orthographic ? glm::dvec2(e.x, -e.y) : glm::dvec2(-e.x * q.z + q.x * e.z, e.y * q.z - q.y * e.z) / (q.z * q.z);
    const double len = glm::length(s);
    if (!(len > 1e-12 * (std::abs(s.x) + std::abs(s.y) + 1e-300)) || !std::isfinite(len)) return glm::dvec2(0.0);
    s /= len;
    return s.x < 0.0 || (s.x == 0.0 && s.y < 0.0) ? -s : s;
}

// What every pixel reads: the camera's rays and the light.
struct PixelContext {
    explicit PixelContext(const Frame& frame)
        : view(frame.camera.view()),
          inverse_view_proj(glm::inverse(glm::dmat4(frame.camera.projection(frame.aspect())) * view)),
          view_vector(frame.camera),
          light(frame.light),
          orthographic(frame.camera.orthographic),
          width(frame.options.width),
          height(frame.options.height) {}
    glm::dmat4 view, inverse_view_proj;
    geometry::ViewVector view_vector;
    const Light& light;
    bool orthographic;
    int width, height;

    // The ray through the centre of pixel (x, y), row 0 at the top: origin and direction.
    std::pair<glm::dvec3, glm::dvec3> ray(int x, int y) const {
        const double nx = (x + 0.5) / width * 2.0 - 1.0, ny = 1.0 - (y + 0.5) / height * 2.0;
        glm::dvec4 a = inverse_view_proj * glm::dvec4(nx, ny, -1.0, 1.0),
                   b = inverse_view_proj * glm::dvec4(nx, ny, 1.0, 1.0);
        const glm::dvec3 near(a / a.w), far(b / b.w);
        return {near, far - near};
    }
    // Towards the light from p (Light::type: a directional light shines from position to target).
    glm::dvec3 to_light(const glm::dvec3& p) const {
        return light.type == LightType::Directional ? unit(glm::dvec3(light.position - light.target))
                                                    : unit(glm::dvec3(light.position) - p);
    }
};

// The fields asked for at one pixel.
void write_pixel(const PixelContext& ctx, const FieldVertices& f, AovSet want, const Sample& s, size_t i,
                 AovImages& out) {
    if (want.contains(Aov::Ndotv))
        out.ndotv[i] = float(glm::dot(unit(s.at(f.normals)), ctx.view_vector.at(glm::vec3(s.p))));
    if (want.contains(Aov::Kr)) out.kr[i] = float(s.at(f.kr));
    if (want.contains(Aov::Dwkr)) out.dwkr[i] = float(s.at(f.dwkr));
    if (want.contains(Aov::K1)) out.k1[i] = float(s.at(f.k1));
    if (want.contains(Aov::K2)) out.k2[i] = float(s.at(f.k2));
    for (auto [aov, dirs] : {std::pair{Aov::Pdir1, &f.pdir1}, std::pair{Aov::Pdir2, &f.pdir2}})
        if (want.contains(aov)) {
            const glm::dvec2 d = image_direction(ctx.view, ctx.orthographic, s.p, s.axis_at(*dirs));
            std::vector<float>& buffer = field_buffer(out, aov);
            buffer[2 * i] = float(d.x);
            buffer[2 * i + 1] = float(d.y);
        }
    if (want.contains(Aov::ShadingScales))
        for (size_t k = 0; k < f.smoothed.size(); ++k)
            out.shading[k][i] = float(std::max(0.0, glm::dot(unit(s.at(f.smoothed[k])), ctx.to_light(s.p))));
}

void allocate(AovSet want, const FieldVertices& f, size_t pixels, AovImages& out) {
    for (Aov a : {Aov::Ndotv, Aov::Kr, Aov::Dwkr, Aov::K1, Aov::K2, Aov::Pdir1, Aov::Pdir2})
        if (want.contains(a)) field_buffer(out, a).assign(pixels * size_t(field_channels(a)), 0.0f);
    if (want.contains(Aov::ShadingScales)) out.shading.assign(f.smoothed.size(), std::vector<float>(pixels, 0.0f));
}

}  // namespace

void interpolate_fields(const Frame& frame, AovSet want, const std::vector<uint32_t>& faces, AovImages& out) {
    const FieldVertices& f = *frame.field_vertices;
    const PixelContext ctx(frame);
    const Mesh& mesh = frame.cpu_mesh;
    const size_t width = size_t(ctx.width), pixels = width * size_t(ctx.height);
    allocate(want, f, pixels, out);
    tbb::parallel_for(tbb::blocked_range<int>(0, ctx.height, 8), [&](const auto& rows) {
        for (int y = rows.begin(); y != rows.end(); ++y)
            for (int x = 0; x < ctx.width; ++x) {
                const size_t i = size_t(y) * width + size_t(x);
                if (faces[i] == 0 || faces[i] > mesh.triangles.size()) continue;
                const glm::uvec3 t = mesh.triangles[faces[i] - 1];
                const glm::dvec3 a(mesh.positions[t.x]), b(mesh.positions[t.y]), c(mesh.positions[t.z]);
                const auto [o, d] = ctx.ray(x, y);
                Sample s{t, ray_barycentrics(o, d, a, b, c), {}};
                s.p = s.b.x * a + s.b.y * b + s.b.z * c;
                write_pixel(ctx, f, want, s, i, out);
            }
    });
    out.field_scales = f.scales;
    for (Aov a : {Aov::Kr, Aov::Dwkr, Aov::K1, Aov::K2})
        if (want.contains(a)) out.field_scales.p90.emplace_back(aov_name(a), visible_p90(field_buffer(out, a), faces));
}

float visible_p90(const std::vector<float>& values, const std::vector<uint32_t>& faces, int channels) {
    std::vector<double> a;
    for (size_t i = 0; i < faces.size(); ++i)
        if (faces[i] != 0) a.push_back(std::abs(double(values[i * size_t(channels)])));
    if (a.empty()) return 0.0f;
    const double rank = 0.9 * double(a.size() - 1);
    const size_t lo = size_t(rank);
    std::nth_element(a.begin(), a.begin() + std::ptrdiff_t(lo), a.end());
    const double low = a[lo];
    const double high = lo + 1 < a.size() ? *std::min_element(a.begin() + std::ptrdiff_t(lo) + 1, a.end()) : low;
    return float(low + (rank - double(lo)) * (high - low));
}

}  // namespace inkshade::render
