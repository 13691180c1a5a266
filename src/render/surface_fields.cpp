// Surface fields per pixel (render/surface_fields.hpp): the pixel centre's ray (through the
// inverse view-projection, so perspective and orthographic alike) meets the plane of the face
// drawn there at barycentric coordinates b (Möller & Trumbore 1997, "Fast, Minimum Storage
// Ray/Triangle Intersection"); each field is Σ b_i f_i of its vertex values, the value a
// rasteriser's perspective-correct interpolation gives at the pixel centre.
#include "render/surface_fields.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "geometry/contours.hpp"

namespace inkshade::render {

namespace {

// A face as the pixels over it read it: corners in double, their edges from the first.
struct FaceCorners {
    uint32_t face = 0;  // the face buffer's value (face + 1; 0: none yet)
    glm::uvec3 v{0};
    glm::dvec3 a{0.0}, b{0.0}, c{0.0}, e1{0.0}, e2{0.0};
    void set(uint32_t f, const Mesh& mesh) {
        face = f;
        v = mesh.triangles[f - 1];
        a = glm::dvec3(mesh.positions[v.x]);
        b = glm::dvec3(mesh.positions[v.y]);
        c = glm::dvec3(mesh.positions[v.z]);
        e1 = b - a;
        e2 = c - a;
    }
};

// Barycentric coordinates of where the ray (o, d) meets the plane of the face, clamped into
// the triangle (a pixel centre on an edge may fall a rounding error outside). Möller and
// Trumbore's u and v share the denominator det, so the weights are taken unscaled
// (det − U − V, U, V), clamped, and divided once by their sum. d need not be unit: the weights
// do not change with its length.
glm::dvec3 ray_barycentrics(const glm::dvec3& o, const glm::dvec3& d, const FaceCorners& t) {
    const glm::dvec3 p = glm::cross(d, t.e2);
    const double det = glm::dot(t.e1, p);
    if (std::abs(det) < 1e-300 || !std::isfinite(det)) return glm::dvec3(1.0 / 3.0);  // seen edge-on
    const glm::dvec3 s = o - t.a, q = glm::cross(s, t.e1);
    const double u = glm::dot(s, p), v = glm::dot(d, q);
    const glm::dvec3 w = glm::max(glm::dvec3(det - u - v, u, v) * (det < 0.0 ? -1.0 : 1.0), glm::dvec3(0.0));
    const double sum = w.x + w.y + w.z;
    return sum > 0.0 ? w * (1.0 / sum) : glm::dvec3(1.0 / 3.0);
}

// Every field of one vertex side by side: a pixel reads three vertices, so it touches a few
// cache lines instead of one per field and vertex (a quarter less time per view on a 75 k-face
// scan).
struct PackedVertex {
    glm::vec3 normal{0.0f};
    float kr = 0.0f, dwkr = 0.0f, k1 = 0.0f, k2 = 0.0f;
    glm::vec3 pdir1{0.0f}, pdir2{0.0f};  // in camera space: the view's rotation applied once a vertex
    // The smoothed normals' x, y and z, a lane a scale (the last lanes zero): a pixel's five
    // scales vectorise.
    static constexpr size_t kLanes = 8;
    static_assert(kShadingScales <= int(kLanes));
    std::array<float, kLanes> sx{}, sy{}, sz{};
};

std::vector<PackedVertex> pack(const FieldVertices& f, size_t n, const glm::dmat3& view_rotation) {
    std::vector<PackedVertex> out(n);
    auto copy = [&](const auto& values, auto member) {
        if (values.size() == n)
            for (size_t i = 0; i < n; ++i) out[i].*member = values[i];
    };
    copy(f.normals, &PackedVertex::normal);
    copy(f.kr, &PackedVertex::kr);
    copy(f.dwkr, &PackedVertex::dwkr);
    copy(f.k1, &PackedVertex::k1);
    copy(f.k2, &PackedVertex::k2);
    for (auto [values, member] : {std::pair{&f.pdir1, &PackedVertex::pdir1}, std::pair{&f.pdir2, &PackedVertex::pdir2}})
        if (values->size() == n)
            for (size_t i = 0; i < n; ++i) out[i].*member = glm::vec3(view_rotation * glm::dvec3((*values)[i]));
    for (size_t k = 0; k < f.smoothed.size() && k < size_t(kShadingScales); ++k)
        if (f.smoothed[k].size() == n)
            for (size_t i = 0; i < n; ++i) {
                out[i].sx[k] = f.smoothed[k][i].x;
                out[i].sy[k] = f.smoothed[k][i].y;
                out[i].sz[k] = f.smoothed[k][i].z;
            }
    return out;
}

// One pixel's surface point: the face's vertices and their weights.
struct Sample {
    std::array<const PackedVertex*, 3> v;
    glm::dvec3 b;
    glm::dvec3 p;  // world
    double at(float PackedVertex::*f) const { return b.x * v[0]->*f + b.y * v[1]->*f + b.z * v[2]->*f; }
    glm::dvec3 at(glm::vec3 PackedVertex::*f) const {
        return b.x * glm::dvec3(v[0]->*f) + b.y * glm::dvec3(v[1]->*f) + b.z * glm::dvec3(v[2]->*f);
    }
    // A line field (principal directions): each vertex's turned to agree with the first's.
    glm::dvec3 axis_at(glm::vec3 PackedVertex::*f) const {
        const glm::dvec3 d0(v[0]->*f), d1(v[1]->*f), d2(v[2]->*f);
        return b.x * d0 + b.y * (glm::dot(d1, d0) < 0.0 ? -d1 : d1) + b.z * (glm::dot(d2, d0) < 0.0 ? -d2 : d2);
    }
};

glm::dvec3 unit(const glm::dvec3& v) {
    const double len = glm::length(v);
    return len > 0.0 && std::isfinite(len) ? v * (1.0 / len) : glm::dvec3(0.0);
}

// The cosine of the angle between a and b; 0 when either vanishes.
double cosine(const glm::dvec3& a, const glm::dvec3& b) {
    const double len2 = glm::dot(a, a) * glm::dot(b, b);
    return len2 > 0.0 && std::isfinite(len2) ? glm::dot(a, b) / std::sqrt(len2) : 0.0;
}

// The unit image-space direction (pixels: x right, y down) of camera-space direction `e` at
// the point whose camera-space position is `q`: the derivative of the projection, without its
// positive factor 1/q.z² (the normalisation drops it); the sign with x > 0 (or x = 0, y > 0): a
// principal direction is an axis, so this fixes one of its two ends. (0, 0) when it projects
// to a point.
glm::dvec2 image_direction(bool orthographic, const glm::dvec3& q, const glm::dvec3& e) {
    glm::dvec2 s = orthographic ? glm::dvec2(e.x, -e.y) : glm::dvec2(-e.x * q.z + q.x * e.z, e.y * q.z - q.y * e.z);
    const double len = glm::length(s);
    if (!(len > 1e-12 * (std::abs(s.x) + std::abs(s.y) + 1e-300)) || !std::isfinite(len)) return glm::dvec2(0.0);
    s *= 1.0 / len;
    return s.x < 0.0 || (s.x == 0.0 && s.y < 0.0) ? -s : s;
}

// What every pixel reads: the camera's rays and the light.
struct PixelContext {
    explicit PixelContext(const Frame& frame)
        : view(frame.camera.view()),
          inverse_view_proj(glm::inverse(glm::dmat4(frame.camera.projection(frame.aspect())) * view)),
          eye(frame.camera.eye),
          view_direction(unit(glm::dvec3(frame.camera.eye) - glm::dvec3(frame.camera.target))),
          light(frame.light),
          orthographic(frame.camera.orthographic),
          width(frame.options.width),
          height(frame.options.height) {}
    glm::dmat4 view, inverse_view_proj;
    glm::dvec3 eye, view_direction;
    const Light& light;
    bool orthographic;
    int width, height;

    // The rays through the pixel centres of row y (row 0 at the top): the homogeneous near and
    // far points are linear in x, so a row needs two matrix products and a step.
    struct RowRays {
        glm::dvec4 near0, far0, step;  // pixel 0's near and far points; one pixel along x
        // Origin and direction (not unit) of the ray through the centre of pixel x: from the
        // near point a/a.w towards the far point b/b.w, the direction scaled by a.w·b.w to
        // save a division.
        std::pair<glm::dvec3, glm::dvec3> at(int x) const {
            const glm::dvec4 a = near0 + double(x) * step, b = far0 + double(x) * step;
            return {glm::dvec3(a) * (1.0 / a.w), glm::dvec3(b) * a.w - glm::dvec3(a) * b.w};
        }
    };
    RowRays row(int y) const {
        const double nx = 0.5 / width * 2.0 - 1.0, ny = 1.0 - (y + 0.5) / height * 2.0, step = 2.0 / width;
        return {inverse_view_proj * glm::dvec4(nx, ny, -1.0, 1.0), inverse_view_proj * glm::dvec4(nx, ny, 1.0, 1.0),
                inverse_view_proj * glm::dvec4(step, 0.0, 0.0, 0.0)};
    }
    // The view vector at p (geometry::ViewVector) times a positive factor (cosine() normalises):
    // towards the eye, or the orthographic camera's direction.
    glm::dvec3 to_eye_unscaled(const glm::dvec3& p) const { return orthographic ? view_direction : eye - p; }
    // Towards the light from p (Light::type: a directional light shines from position to target).
    glm::dvec3 to_light(const glm::dvec3& p) const {
        return light.type == LightType::Directional ? light_direction : unit(glm::dvec3(light.position) - p);
    }
    glm::dvec3 light_direction = unit(glm::dvec3(light.position - light.target));  // a directional light's
};

// The fields asked for at one pixel.
void write_pixel(const PixelContext& ctx, AovSet want, size_t scales, const Sample& s, size_t i, AovImages& out) {
    if (want.contains(Aov::Ndotv)) out.ndotv[i] = float(cosine(s.at(&PackedVertex::normal), ctx.to_eye_unscaled(s.p)));
    if (want.contains(Aov::Kr)) out.kr[i] = float(s.at(&PackedVertex::kr));
    if (want.contains(Aov::Dwkr)) out.dwkr[i] = float(s.at(&PackedVertex::dwkr));
    if (want.contains(Aov::K1)) out.k1[i] = float(s.at(&PackedVertex::k1));
    if (want.contains(Aov::K2)) out.k2[i] = float(s.at(&PackedVertex::k2));
    const bool pdirs = want.contains(Aov::Pdir1) || want.contains(Aov::Pdir2);
    const glm::dvec3 q = pdirs ? glm::dvec3(ctx.view * glm::dvec4(s.p, 1.0)) : glm::dvec3(0.0);
    for (auto [aov, dirs] : {std::pair{Aov::Pdir1, &PackedVertex::pdir1}, std::pair{Aov::Pdir2, &PackedVertex::pdir2}})
        if (want.contains(aov)) {
            const glm::dvec2 d = image_direction(ctx.orthographic, q, s.axis_at(dirs));
            std::vector<float>& buffer = field_buffer(out, aov);
            buffer[2 * i] = float(d.x);
            buffer[2 * i + 1] = float(d.y);
        }
    if (want.contains(Aov::ShadingScales)) {
        // In float: n·l lands in a 16-bit PNG, whose step is 500 times float's rounding here.
        const glm::vec3 l(ctx.to_light(s.p)), b(s.b);
        constexpr size_t lanes = PackedVertex::kLanes;
        std::array<float, lanes> shade;
        const PackedVertex &v0 = *s.v[0], &v1 = *s.v[1], &v2 = *s.v[2];
        for (size_t k = 0; k < lanes; ++k) {
            const float x = b.x * v0.sx[k] + b.y * v1.sx[k] + b.z * v2.sx[k];
            const float y = b.x * v0.sy[k] + b.y * v1.sy[k] + b.z * v2.sy[k];
            const float z = b.x * v0.sz[k] + b.y * v1.sz[k] + b.z * v2.sz[k];
            const float len = std::sqrt(x * x + y * y + z * z);
            const float cosine = (x * l.x + y * l.y + z * l.z) / len;  // NaN where len is 0 or not finite
            shade[k] = cosine > 0.0f ? cosine : 0.0f;
        }
        for (size_t k = 0; k < scales; ++k) out.shading[k][i] = shade[k];
    }
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
    const std::vector<PackedVertex> packed = pack(f, mesh.positions.size(), glm::dmat3(ctx.view));
    const size_t scales = std::min(f.smoothed.size(), size_t(kShadingScales));
    tbb::parallel_for(tbb::blocked_range<int>(0, ctx.height, 8), [&](const auto& rows) {
        for (int y = rows.begin(); y != rows.end(); ++y) {
            const PixelContext::RowRays rays = ctx.row(y);
            FaceCorners t;  // neighbouring pixels mostly show the same face
            for (int x = 0; x < ctx.width; ++x) {
                const size_t i = size_t(y) * width + size_t(x);
                if (faces[i] == 0 || faces[i] > mesh.triangles.size()) continue;
                if (faces[i] != t.face) t.set(faces[i], mesh);
                const auto [o, d] = rays.at(x);
                Sample s{{&packed[t.v.x], &packed[t.v.y], &packed[t.v.z]}, ray_barycentrics(o, d, t), {}};
                s.p = s.b.x * t.a + s.b.y * t.b + s.b.z * t.c;
                write_pixel(ctx, want, scales, s, i, out);
            }
        }
    });
    out.field_scales = f.scales;
    std::vector<Aov> scaled;
    for (Aov a : {Aov::Kr, Aov::Dwkr, Aov::K1, Aov::K2})
        if (want.contains(a)) scaled.push_back(a);
    std::vector<float> p90(scaled.size());  // each a selection over the visible pixels: in parallel
    tbb::parallel_for(size_t(0), scaled.size(),
                      [&](size_t k) { p90[k] = visible_p90(field_buffer(out, scaled[k]), faces); });
    for (size_t k = 0; k < scaled.size(); ++k) out.field_scales.p90.emplace_back(aov_name(scaled[k]), p90[k]);
}

float visible_p90(const std::vector<float>& values, const std::vector<uint32_t>& faces, int channels) {
    std::vector<float> a;  // |v| is exact in float; the interpolation below is in double
    a.reserve(faces.size());
    for (size_t i = 0; i < faces.size(); ++i)
        if (faces[i] != 0) a.push_back(std::abs(values[i * size_t(channels)]));
    if (a.empty()) return 0.0f;
    const double rank = 0.9 * double(a.size() - 1);
    const size_t lo = size_t(rank);
    std::nth_element(a.begin(), a.begin() + std::ptrdiff_t(lo), a.end());
    const double low = a[lo];
    const double high =
        lo + 1 < a.size() ? double(*std::min_element(a.begin() + std::ptrdiff_t(lo) + 1, a.end())) : low;
    return float(low + (rank - double(lo)) * (high - low));
}

}  // namespace inkshade::render
