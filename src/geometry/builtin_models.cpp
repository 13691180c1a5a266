// Procedural models with analytic normals. Every parametric grid is indexed with wrap-around
// (and shared poles), so seams are shared by construction rather than welded afterwards, and
// quads are split so that the right-hand rule over (u, v) gives ∂S/∂u × ∂S/∂v, which each
// parametrisation below makes point outward.
#include "geometry/builtin_models.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <numbers>
#include <numeric>
#include <string>
#include <vector>

#include "geometry/normals.hpp"
#include "geometry/weld.hpp"
#include "inkshade/error.hpp"

namespace inkshade::builtin {

namespace teapot_data {  // src/geometry/teapot_data.cpp
extern const uint16_t kPatches[32][16];
extern const float kControlPoints[306][3];
}  // namespace teapot_data

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

void require(bool ok, const std::string& model, const std::string& problem) {
    if (!ok) throw InputError("builtin:" + model, problem);
}

// Two triangles for the parameter quad a = (i, j), b = (i+1, j), c = (i+1, j+1), d = (i, j+1),
// counter-clockwise around ∂u × ∂v.
void add_quad(Mesh& m, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    m.triangles.emplace_back(a, b, c);
    m.triangles.emplace_back(a, c, d);
}

// Tube surface of a closed curve: rows along the curve (`rows` samples, wrapping), columns
// around it (`cols`, wrapping). `ring(i)` gives the centre c and an orthonormal frame (n, b)
// of the normal plane; the vertex at angle s is c + radius·(cos s·n − sin s·b). The minus
// sign makes ∂/∂i × ∂/∂s point away from the centre line when (t, n, b) is right-handed.
template <class Ring>
Mesh tube(int rows, int cols, double radius, Ring ring) {
    Mesh m;
    m.positions.reserve(size_t(rows) * cols);
    m.normals.reserve(size_t(rows) * cols);
    for (int i = 0; i < rows; ++i) {
        const auto [c, n, b] = ring(i);
        for (int j = 0; j < cols; ++j) {
            const double s = kTwoPi * j / cols;
            const glm::dvec3 dir = std::cos(s) * n - std::sin(s) * b;
            m.positions.emplace_back(c + radius * dir);
            m.normals.emplace_back(glm::normalize(dir));
        }
    }
    const auto idx = [&](int i, int j) { return uint32_t((i % rows) * cols + (j % cols)); };
    m.triangles.reserve(size_t(2) * rows * cols);
    for (int i = 0; i < rows; ++i)
        for (int j = 0; j < cols; ++j) add_quad(m, idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1));
    return m;
}

// Cubic Bernstein polynomials and their derivatives at t.
std::array<double, 4> bernstein(double t) {
    const double s = 1.0 - t;
    return {s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t};
}
std::array<double, 4> bernstein_derivative(double t) {
    const double s = 1.0 - t;
    return {-3.0 * s * s, 3.0 * s * s - 6.0 * t * s, 6.0 * t * s - 3.0 * t * t, 3.0 * t * t};
}

}  // namespace

// Latitude θ from the north pole (+y), longitude φ: S = r(sin θ cos φ, cos θ, −sin θ sin φ), for
// which ∂S/∂θ × ∂S/∂φ = r² sin θ · S/r points outward.
Mesh sphere(int rings, int segments, float radius) {
    require(rings >= 2 && segments >= 3, "sphere", "needs rings >= 2 and segments >= 3");
    require(radius > 0.0f && std::isfinite(radius), "sphere", "radius must be positive");
    Mesh m;
    const auto add = [&](double theta, double phi) {
        const glm::dvec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi));
        m.positions.emplace_back(double(radius) * n);
        m.normals.emplace_back(n);
    };
    add(0.0, 0.0);  // north pole, index 0
    for (int k = 1; k < rings; ++k)
        for (int s = 0; s < segments; ++s) add(std::numbers::pi * k / rings, kTwoPi * s / segments);
    add(std::numbers::pi, 0.0);  // south pole, last index
    const uint32_t north = 0, south = uint32_t(m.positions.size() - 1);
    const auto idx = [&](int k, int s) { return uint32_t(1 + (k - 1) * segments + s % segments); };
    for (int s = 0; s < segments; ++s) {
        m.triangles.emplace_back(north, idx(1, s), idx(1, s + 1));  // quad with a = d = pole
        for (int k = 1; k + 1 < rings; ++k) add_quad(m, idx(k, s), idx(k + 1, s), idx(k + 1, s + 1), idx(k, s + 1));
        m.triangles.emplace_back(idx(rings - 1, s), south, idx(rings - 1, s + 1));  // b = c = pole
    }
    return m;
}

// S(u, v) = ((R + r cos v) cos u, (R + r cos v) sin u, r sin v); the tube frame at u is
// n = (cos u, sin u, 0) (away from the axis), b = (0, 0, −1), so the normal is
// (cos v cos u, cos v sin u, sin v).
Mesh torus(float major_radius, float minor_radius, int major_segments, int minor_segments) {
    require(major_segments >= 3 && minor_segments >= 3, "torus", "needs at least 3 segments each way");
    require(major_radius > 0.0f && minor_radius > 0.0f && minor_radius < major_radius, "torus",
            "needs 0 < minor radius < major radius");
    return tube(major_segments, minor_segments, minor_radius, [&](int i) {
        const double u = kTwoPi * i / major_segments;
        const glm::dvec3 n(std::cos(u), std::sin(u), 0.0);
        return std::array<glm::dvec3, 3>{double(major_radius) * n, n, glm::dvec3(0, 0, -1)};
    });
}

// Frame: tangent t = c'/|c'|; b = t × c/|t × c| uses the direction from the origin as the
// reference, which is never parallel to c' on a torus knot (c' always has the azimuthal
// component p·(R + r cos qt) and c does not), so the frame is smooth and exactly periodic —
// the last ring joins the first without twist, unlike a rotation-minimising frame. A tube
// of constant radius is a canal surface, whose normal is exactly the unit offset from the
// centre line.
Mesh torus_knot(int p, int q, float tube_radius, int segments, int tube_segments) {
    require(p >= 1 && q >= 1 && std::gcd(p, q) == 1, "torus-knot", "p and q must be coprime positive integers");
    require(segments >= 3 && tube_segments >= 3, "torus-knot", "needs at least 3 segments each way");
    require(tube_radius > 0.0f && tube_radius < 0.4f, "torus-knot", "needs 0 < tube radius < 0.4");
    constexpr double R = 1.0, r = 0.4;
    return tube(segments, tube_segments, tube_radius, [&](int i) {
        const double t = kTwoPi * i / segments;
        const double ct = std::cos(q * t), st = std::sin(q * t), cp = std::cos(p * t), sp = std::sin(p * t);
        const glm::dvec3 c((R + r * ct) * cp, (R + r * ct) * sp, r * st);
        const glm::dvec3 dc(-r * q * st * cp - (R + r * ct) * p * sp, -r * q * st * sp + (R + r * ct) * p * cp,
                            r * q * ct);
        const glm::dvec3 tangent = glm::normalize(dc);
        const glm::dvec3 b = glm::normalize(glm::cross(tangent, c));
        return std::array<glm::dvec3, 3>{c, glm::cross(b, tangent), b};
    });
}

// Each patch is evaluated on an (n+1)² grid (u along the data's rows); positions, and normals
// from ∂S/∂v × ∂S/∂u (the data's patches are oriented so that this points outward), are
// rotated from the data's z-up to y-up: (x, y, z) -> (x, z, −y). The grids are welded at
// 1e-5 of the diagonal (seams are evaluated from the same control points, so they agree to
// rounding), after which the cusp rows of the knob and bottom patches collapse: their
// zero-area triangles (n per cusp patch) are dropped, and the cusp vertices, where the partial
// derivatives vanish, take the angle-weighted normal instead.
//
// Not closed — Newell's data has no shell thickness and no trimming. Measured after welding at
// n = 16 (tests/geometry/builtin_models_test.cpp checks it): 32·2n² − 8n = 16256 triangles, 8257
// vertices, 24512 edges, no non-manifold edges, 16n = 256 boundary edges in 6 loops (the rim's
// inner lip and the lid's edge, 4n each, with the classic gap between them; both ends of the
// handle and of the spout, 2n each, which pass into the body without sharing an edge), 3
// components (body + bottom + handle, lid, spout: the lower handle patch reuses a body corner
// control point, so the handle touches the body at one vertex, (−2, 0.9, 0)), Euler
// characteristic V − E + F = 1 (disk 1 + cylinder 0 − 1 shared vertex; lid disk 1; spout
// cylinder 0). Normals crease by design at the body/bottom seam (about 12°) and at the handle
// vertex.
Mesh teapot(int subdivisions) {
    // One quad per patch folds the handle and spout onto themselves (non-manifold edges).
    require(subdivisions >= 2 && subdivisions <= 1024, "teapot", "subdivisions must be in 2..1024");
    const int n = subdivisions;
    Mesh m;
    m.positions.reserve(32 * size_t(n + 1) * (n + 1));
    m.normals.reserve(m.positions.capacity());
    const auto y_up = [](const glm::dvec3& v) { return glm::vec3(v.x, v.z, -v.y); };
    for (const auto& patch : teapot_data::kPatches) {
        std::array<glm::dvec3, 16> cp;
        for (int k = 0; k < 16; ++k) {
            const float* xyz = teapot_data::kControlPoints[patch[k] - 1];
            cp[k] = glm::dvec3(xyz[0], xyz[1], xyz[2]);
        }
        const auto base = uint32_t(m.positions.size());
        for (int i = 0; i <= n; ++i) {
            const auto bu = bernstein(double(i) / n), du = bernstein_derivative(double(i) / n);
            for (int j = 0; j <= n; ++j) {
                const auto bv = bernstein(double(j) / n), dv = bernstein_derivative(double(j) / n);
                glm::dvec3 s(0.0), su(0.0), sv(0.0);
                for (int a = 0; a < 4; ++a)
                    for (int b = 0; b < 4; ++b) {
                        s += bu[a] * bv[b] * cp[4 * a + b];
                        su += du[a] * bv[b] * cp[4 * a + b];
                        sv += bu[a] * dv[b] * cp[4 * a + b];
                    }
                const glm::dvec3 normal = glm::cross(sv, su);
                const double len = glm::length(normal);
                m.positions.push_back(y_up(s));
                // Zero marks a cusp (vanishing derivative): filled in after welding.
                m.normals.push_back(len > 1e-9 * glm::length(su + sv) + 1e-12 ? y_up(normal / len) : glm::vec3(0.0f));
            }
        }
        const auto idx = [&](int i, int j) { return base + uint32_t(i * (n + 1) + j); };
        // Quads split as (a, c, b), (a, d, c): counter-clockwise around ∂v × ∂u.
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) add_quad(m, idx(i, j), idx(i, j + 1), idx(i + 1, j + 1), idx(i + 1, j));
    }

    geometry::weld(m, {.relative_epsilon = 1e-5f});
    std::erase_if(m.triangles, [](const glm::uvec3& t) { return t.x == t.y || t.y == t.z || t.x == t.z; });
    // A cusp's first copy may be a cusp-row vertex with a zero normal (weld keeps the first).
    const std::vector<glm::vec3> fallback = geometry::angle_weighted_vertex_normals(m);
    for (size_t v = 0; v < m.normals.size(); ++v)
        if (m.normals[v] == glm::vec3(0.0f)) m.normals[v] = fallback[v];

    float min_y = m.positions.empty() ? 0.0f : m.positions[0].y;
    for (const glm::vec3& p : m.positions) min_y = std::min(min_y, p.y);
    for (glm::vec3& p : m.positions) p.y -= min_y;  // base exactly on y = 0
    return m;
}

void add_ground(Mesh& mesh, int cells) {
    require(cells >= 1 && cells <= 4096, "ground", "cells must be in 1..4096");
    const BoundingBox box = mesh.bounds();
    const float half = 1.25f * std::max(box.max.x - box.min.x, box.max.z - box.min.z);
    const glm::vec3 centre(box.center().x, box.min.y, box.center().z);
    const uint32_t base = uint32_t(mesh.positions.size());
    const bool normals = mesh.normals.size() == mesh.positions.size();
    for (int j = 0; j <= cells; ++j)
        for (int i = 0; i <= cells; ++i) {
            mesh.positions.push_back(centre + glm::vec3(half * (2.0f * i / cells - 1.0f), 0.0f,
                                                        half * (1.0f - 2.0f * j / cells)));
            if (normals) mesh.normals.emplace_back(0.0f, 1.0f, 0.0f);
        }
    const auto idx = [&](int i, int j) { return base + uint32_t(j * (cells + 1) + i); };
    // Rows run towards −z, so (i, j) → (i + 1, j) → (i + 1, j + 1) turns counter-clockwise seen from +y.
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            mesh.triangles.emplace_back(idx(i, j), idx(i + 1, j), idx(i + 1, j + 1));
            mesh.triangles.emplace_back(idx(i, j), idx(i + 1, j + 1), idx(i, j + 1));
        }
}

std::vector<std::string> names() { return {"sphere", "torus", "torus-knot", "teapot"}; }

namespace {

// "key=value,key=value" after "NAME:" -> numbers, with unknown keys and bad numbers refused.
class BuiltinOptions {
public:
    BuiltinOptions(const std::string& spec, const std::string& model, std::vector<std::string> allowed) : spec_(spec) {
        size_t start = 0;
        while (start < model.size()) {
            size_t comma = model.find(',', start);
            std::string item = model.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
            start = comma == std::string::npos ? model.size() : comma + 1;
            size_t eq = item.find('=');
            std::string key = item.substr(0, eq);
            if (eq == std::string::npos || std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
                std::string list;
                for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
                throw InputError(spec_, "unknown option '" + item + "' (options: " + list + ")");
            }
            char* end = nullptr;
            std::string text = item.substr(eq + 1);
            double v = std::strtod(text.c_str(), &end);
            if (text.empty() || *end != '\0' || !std::isfinite(v))
                throw InputError(spec_, "option " + key + ": '" + text + "' is not a number");
            values_[key] = v;
        }
    }
    float real(const std::string& key, float fallback) const {
        auto it = values_.find(key);
        return it == values_.end() ? fallback : float(it->second);
    }
    int integer(const std::string& key, int fallback) const {
        auto it = values_.find(key);
        if (it == values_.end()) return fallback;
        if (it->second != std::floor(it->second) || std::abs(it->second) > 1e6)
            throw InputError(spec_, "option " + key + " must be an integer up to 1000000");
        return int(it->second);
    }

private:
    std::string spec_;
    std::map<std::string, double> values_;
};

// Tessellations beyond this many triangles are refused before allocating (~3 GB of mesh).
constexpr double kMaxBuiltinTriangles = 1e8;

void check_size(const std::string& spec, double triangles) {
    if (triangles > kMaxBuiltinTriangles)
        throw InputError(
            spec, "tessellation would make " + std::to_string(int64_t(triangles)) + " triangles (limit 100000000)");
}

}  // namespace

Mesh by_name(const std::string& name) {
    const std::string spec = "builtin:" + name;
    const size_t colon = name.find(':');
    const std::string model = name.substr(0, colon);
    const std::string opts = colon == std::string::npos ? "" : name.substr(colon + 1);
    if (model == "sphere") {
        BuiltinOptions o(spec, opts, {"rings", "segments", "radius"});
        int rings = o.integer("rings", 64), segments = o.integer("segments", 128);
        check_size(spec, 2.0 * rings * segments);
        return sphere(rings, segments, o.real("radius", 1.0f));
    }
    if (model == "torus") {
        BuiltinOptions o(spec, opts, {"major", "minor", "major-segments", "minor-segments"});
        int a = o.integer("major-segments", 128), b = o.integer("minor-segments", 64);
        check_size(spec, 2.0 * a * b);
        return torus(o.real("major", 1.0f), o.real("minor", 0.4f), a, b);
    }
    if (model == "torus-knot") {
        BuiltinOptions o(spec, opts, {"p", "q", "tube", "segments", "tube-segments"});
        int a = o.integer("segments", 512), b = o.integer("tube-segments", 32);
        check_size(spec, 2.0 * a * b);
        return torus_knot(o.integer("p", 2), o.integer("q", 3), o.real("tube", 0.15f), a, b);
    }
    if (model == "teapot") {
        BuiltinOptions o(spec, opts, {"subdivisions", "ground"});
        int n = o.integer("subdivisions", 16), g = o.integer("ground", 0);
        check_size(spec, 64.0 * n * n + 2.0 * g * g);
        Mesh m = teapot(n);
        if (g != 0) add_ground(m, g);
        return m;
    }
    throw InputError(spec, "unknown built-in model (choose sphere, torus, torus-knot, teapot)");
}

}  // namespace inkshade::builtin
