// Curvature and curvature derivatives, Rusinkiewicz 2004, "Estimating Curvatures and Their
// Derivatives on Triangle Meshes" (3DPVT). For every face, the second fundamental form II is
// fitted by least squares in a frame (t, b) of the face plane from the normal differences along
// its three edges: II·e = Δn. Each face's II is rotated into the tangent frame of its three
// vertices and averaged with the mixed Voronoi areas of Meyer et al. 2003; the per-vertex tensor
// is then diagonalised. The derivative tensor C = ∇II is fitted the same way from the
// differences of the per-vertex II (rotated into the face frame) along the edges, and averaged
// back into each vertex's principal frame.
//
// Per-face work runs in parallel (TBB) and writes per-face, per-corner results; accumulation into
// vertices is a sequential scatter in face order, so the output is identical for any thread count.
#include "geometry/curvature.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace inkshade::geometry {
namespace {

constexpr size_t kGrain = 8192;  // faces or vertices per TBB task

constexpr int next(int j) { return j == 2 ? 0 : j + 1; }
constexpr int prev(int j) { return j == 0 ? 2 : j - 1; }

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finite(const glm::vec4& v) { return finite(glm::vec3(v)) && std::isfinite(v.w); }

template <class Body>
void for_each_index(size_t n, const Body& body) {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, kGrain), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t i = r.begin(); i != r.end(); ++i) body(i);
    });
}

// Unit tangent u with (u, n × u, n) right-handed orthonormal, continuous except across n.z = 0
// (Duff et al. 2017, "Building an Orthonormal Basis, Revisited"). n must be unit length.
glm::vec3 any_tangent(const glm::vec3& n) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    return {1.0f + sign * n.x * n.x * a, sign * n.x * n.y * a, -sign * n.x};
}

// Solves the symmetric tridiagonal system (diag d, off-diagonal o) in place of rhs; false when a
// pivot is not clearly positive (the normal equations of a degenerate face).
template <int N>
[[gnu::always_inline]] inline bool solve_tridiagonal(std::array<float, N> d, const std::array<float, N - 1>& o,
                                                     std::array<float, N>& rhs) {
    const float eps = 1e-6f * (std::abs(d[0]) + std::abs(d[N - 1]));
    std::array<float, N> inv;  // reciprocal pivots: N divisions instead of 2N - 1
    for (int i = 1; i < N; ++i) {
        if (!(d[i - 1] > eps)) return false;
        inv[i - 1] = 1.0f / d[i - 1];
        const float l = o[i - 1] * inv[i - 1];
        d[i] -= l * o[i - 1];
        rhs[i] -= l * rhs[i - 1];
    }
    if (!(d[N - 1] > eps)) return false;
    rhs[N - 1] /= d[N - 1];
    for (int i = N - 2; i >= 0; --i) rhs[i] = (rhs[i] - o[i] * rhs[i + 1]) * inv[i];
    return true;
}

// Area of the face owned by each corner: the Voronoi region of the corner inside the triangle, or
// for an obtuse triangle A/2 at the obtuse corner and A/4 at the others (Meyer et al. 2003,
// "Discrete Differential-Geometry Operators for Triangulated 2-Manifolds", Section 3.3).
// l2[j] is the squared length of the edge opposite corner j. Zero for a degenerate face.
[[gnu::always_inline]] inline glm::vec3 corner_areas(const glm::vec3& l2, float area) {
    if (!(area > 0.0f) || !std::isfinite(area)) return glm::vec3(0.0f);
    // ew[j] = 4A·|e_j|²·cot(angle j): the Voronoi area of corner j is (ew[j+1] + ew[j+2]) / (32 A)
    // and the three ew sum to 16 A², so normalising by their sum keeps the split exact.
    glm::vec3 ew;
    for (int j = 0; j < 3; ++j) ew[j] = l2[j] * (l2[next(j)] + l2[prev(j)] - l2[j]);
    for (int j = 0; j < 3; ++j)
        if (ew[j] <= 0.0f) {  // corner j is right or obtuse
            glm::vec3 out(0.25f * area);
            out[j] = 0.5f * area;
            return out;
        }
    const float scale = 0.5f * area / (ew[0] + ew[1] + ew[2]);
    return {scale * (ew[1] + ew[2]), scale * (ew[2] + ew[0]), scale * (ew[0] + ew[1])};
}

// Face frame: t along edge 0, b = n × t in the face plane; the edges in that frame and the
// corner areas, everything both passes need of a face.
struct FaceFrame {
    glm::vec3 t, b, n;
    std::array<float, 3> u, v;  // edge j (p[prev j] - p[next j], opposite corner j) in (t, b)
    glm::vec3 ca;               // corner areas; zero when the face is unusable
};

[[gnu::always_inline]] inline FaceFrame face_frame(const std::vector<glm::vec3>& p, const glm::uvec3& f) {
    FaceFrame fr;
    const glm::vec3 e0 = p[f[2]] - p[f[1]], e1 = p[f[0]] - p[f[2]], e2 = p[f[1]] - p[f[0]];
    const glm::vec3 l2(glm::dot(e0, e0), glm::dot(e1, e1), glm::dot(e2, e2));
    const glm::vec3 c = glm::cross(e0, e1);
    const float len0 = std::sqrt(l2[0]), twice_area = glm::length(c);
    // One division each: a vector divided by a scalar is three divisions, the slowest
    // instructions of this loop.
    fr.t = e0 * (1.0f / len0);
    fr.n = c * (1.0f / twice_area);
    fr.b = glm::cross(fr.n, fr.t);
    // e0 lies along t; e2 = -(e0 + e1).
    const float u1 = glm::dot(e1, fr.t), v1 = glm::dot(e1, fr.b);
    fr.u = {len0, u1, -(len0 + u1)};
    fr.v = {0.0f, v1, -v1};
    fr.ca = finite(fr.t) && finite(fr.n) ? corner_areas(l2, 0.5f * twice_area) : glm::vec3(0.0f);
    return fr;
}

// A frame change between two right-handed tangent frames, as the rotation angle θ of the new
// frame (nu, nv) relative to the old (ou, ov) once both lie in one plane: (cos θ, sin θ) are the
// components of nu in (ou, ov), and nv = (-sin θ, cos θ). Both frames are orthonormal and
// right-handed about their normals and the turn is a proper rotation, so two dot products
// give the whole 2x2 rotation.
struct Rotation {
    float c, s;
    Rotation inverse() const { return {c, -s}; }
};

// The frame (nu, nv) with normal nn, turned into the plane of (ou, ov) with normal on about
// nn × on (the "rot_coord_sys" step of Rusinkiewicz 2004, Section 3), as an angle relative to
// (ou, ov): how a tensor in (ou, ov) is re-expressed in (nu, nv).
[[gnu::always_inline]] inline Rotation frame_change(const glm::vec3& ou, const glm::vec3& ov, const glm::vec3& on,
                                                    glm::vec3 nu, const glm::vec3& nn) {
    const float ndot = glm::dot(nn, on);
    if (1.0f + ndot <= 1e-6f) {  // opposite normals: any half-turn will do
        nu = -nu;
    } else {
        nu -= (nn + on) * (glm::dot(nu, on - ndot * nn) / (1.0f + ndot));
    }
    return {glm::dot(nu, ou), glm::dot(nu, ov)};
}

// Tensors are rotated through their rotation-invariant parts (Fourier components on the unit
// circle), which turn by a multiple of θ: a symmetric 2-tensor II = (ku, kuv, kv) is its trace
// and the spin-2 part ((ku - kv) / 2, kuv); the symmetric 3-tensor C = (a, b, c, d) =
// (C111, C112, C122, C222) is its spin-1 part P = (a + c, b + d) and its spin-3 part
// T = (a - 3c, 3b - d). In the new frame a spin-k part is multiplied by e^(-ikθ). Equal to the
// component-wise rotation formulas of Rusinkiewicz 2004 (trimesh2's proj_curv, proj_dcurv) with
// a third of their multiplications.
struct Complex {
    float re, im;
};
[[gnu::always_inline]] inline Complex operator*(Complex a, Complex b) {
    return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re};
}
[[gnu::always_inline]] inline Complex turn(const Rotation& r) { return {r.c, -r.s}; }  // e^(-iθ)

// II = (ku, kuv, kv) expressed in the new frame.
[[gnu::always_inline]] inline glm::vec3 rotate_tensor(const glm::vec3& k, const Rotation& r) {
    const Complex e1 = turn(r), e2 = e1 * e1;
    const float mean = 0.5f * (k[0] + k[2]);
    const Complex z = Complex{0.5f * (k[0] - k[2]), k[1]} * e2;
    return {mean + z.re, z.im, mean - z.re};
}

// C = (C111, C112, C122, C222) expressed in the new frame.
[[gnu::always_inline]] inline glm::vec4 rotate_derivative(const glm::vec4& c, const Rotation& r) {
    const Complex e1 = turn(r), e3 = e1 * e1 * e1;
    const Complex p = Complex{c[0] + c[2], c[1] + c[3]} * e1;
    const Complex t = Complex{c[0] - 3.0f * c[2], 3.0f * c[1] - c[3]} * e3;
    return 0.25f * glm::vec4(3.0f * p.re + t.re, p.im + t.im, p.re - t.re, 3.0f * p.im - t.im);
}

// Per-corner results of one face, already multiplied by the corner's area.
using CornerValues = std::array<float, 12>;

// Runs `face(i, values)` for the faces in chunks, in parallel, and then `scatter(i, values)` for
// each face of the chunk, in face order, for which `face` returned true (it contributed). The
// chunk buffer stays in cache and is reused, so the per-face results never make a round trip
// through main memory.
template <class Face, class Scatter>
void for_each_face_chunk(size_t nf, const Face& face, const Scatter& scatter) {
    constexpr size_t kChunk = size_t(1) << 15;
    std::vector<CornerValues> buffer(std::min(nf, kChunk));
    std::vector<uint8_t> contributed(buffer.size());
    for (size_t begin = 0; begin < nf; begin += kChunk) {
        const size_t end = std::min(nf, begin + kChunk);
        tbb::parallel_for(tbb::blocked_range<size_t>(begin, end, kGrain / 4), [&](const tbb::blocked_range<size_t>& r) {
            for (size_t i = r.begin(); i != r.end(); ++i) contributed[i - begin] = face(i, buffer[i - begin]);
        });
        for (size_t i = begin; i != end; ++i)
            if (contributed[i - begin]) scatter(i, buffer[i - begin]);
    }
}

}  // namespace

Curvature compute_curvature(const Mesh& mesh, const std::vector<glm::vec3>& vertex_normals,
                            const CurvatureOptions& /*options*/) {
    const auto& p = mesh.positions;
    const auto& tris = mesh.triangles;
    const size_t nv = p.size(), nf = tris.size();

    Curvature out;
    out.pdir1.resize(nv);
    out.pdir2.resize(nv);
    out.k1.resize(nv);
    out.k2.resize(nv);
    out.dcurv.resize(nv);
    out.point_area.resize(nv);

    // Unit normals (zero = unusable) and an initial tangent frame per vertex. dcurv.xyz first
    // accumulates the area-weighted second fundamental form (ku, kuv, kv) in that frame.
    std::vector<glm::vec3> normal(nv);
    for_each_index(nv, [&](size_t v) {
        glm::vec3 n = v < vertex_normals.size() ? vertex_normals[v] : glm::vec3(0.0f);
        const float len = glm::length(n);
        const bool ok = len > 0.0f && std::isfinite(len) && finite(p[v]);
        normal[v] = ok ? n / len : glm::vec3(0.0f);
        n = ok ? normal[v] : glm::vec3(0.0f, 0.0f, 1.0f);
        out.pdir1[v] = any_tangent(n);
        out.pdir2[v] = glm::cross(n, out.pdir1[v]);
        out.k1[v] = out.k2[v] = out.point_area[v] = 0.0f;
        out.dcurv[v] = glm::vec4(0.0f);
    });

    const auto usable_indices = [&](const glm::uvec3& f) {
        return f.x < nv && f.y < nv && f.z < nv && f.x != f.y && f.y != f.z && f.z != f.x &&
               normal[f.x] != glm::vec3(0.0f) && normal[f.y] != glm::vec3(0.0f) && normal[f.z] != glm::vec3(0.0f);
    };
    // Face i's frame and corner areas, or false for a face both passes skip (bad indices, zero
    // normals, zero area, non-finite frame).
    const auto usable_face = [&](size_t i, FaceFrame& fr) {
        if (!usable_indices(tris[i])) return false;
        fr = face_frame(p, tris[i]);
        return fr.ca != glm::vec3(0.0f);
    };

    // Pass 1: second fundamental form per face, rotated into each corner's vertex frame.
    // values = (3 corner areas, then area-weighted (ku, kuv, kv) per corner).
    for_each_face_chunk(
        nf,
        [&](size_t i, CornerValues& cv) {
            FaceFrame fr;
            if (!usable_face(i, fr)) return false;
            const glm::vec3& ca = fr.ca;
            const glm::uvec3 f = tris[i];

            // Least squares for II = [[ku, kuv], [kuv, kv]] from II·(u, v) = (dnu, dnv) on each edge.
            float uu = 0, uv = 0, vv = 0;
            std::array<float, 3> m{0, 0, 0};
            for (int j = 0; j < 3; ++j) {
                const float u = fr.u[j], v = fr.v[j];
                uu += u * u, uv += u * v, vv += v * v;
                const glm::vec3 dn = normal[f[prev(j)]] - normal[f[next(j)]];
                const float dnu = glm::dot(dn, fr.t), dnv = glm::dot(dn, fr.b);
                m[0] += dnu * u;
                m[1] += dnu * v + dnv * u;
                m[2] += dnv * v;
            }
            if (!solve_tridiagonal<3>({uu, uu + vv, vv}, {uv, uv}, m)) return false;
            const glm::vec3 ii{m[0], m[1], m[2]};
            if (!finite(ii)) return false;

            for (int j = 0; j < 3; ++j) {
                const uint32_t v = f[j];
                const Rotation r = frame_change(fr.t, fr.b, fr.n, out.pdir1[v], normal[v]);
                const glm::vec3 k = ca[j] * rotate_tensor(ii, r);
                cv[j] = ca[j];
                cv[3 + 3 * j] = k[0], cv[4 + 3 * j] = k[1], cv[5 + 3 * j] = k[2];
            }
            return true;
        },
        [&](size_t i, const CornerValues& cv) {
            const glm::uvec3 f = tris[i];
            for (int j = 0; j < 3; ++j) {
                out.point_area[f[j]] += cv[j];
                out.dcurv[f[j]] += glm::vec4(cv[3 + 3 * j], cv[4 + 3 * j], cv[5 + 3 * j], 0.0f);
            }
        });

    // Diagonalise per vertex (one Jacobi rotation), k1 >= k2.
    for_each_index(nv, [&](size_t v) {
        const float area = out.point_area[v];
        const glm::vec3 k = glm::vec3(out.dcurv[v]) * (1.0f / area);
        out.dcurv[v] = glm::vec4(0.0f);
        if (!(area > 0.0f)) return;
        const float ku = k[0], kuv = k[1], kv = k[2];
        float c = 1.0f, s = 0.0f, tt = 0.0f;
        if (kuv != 0.0f) {
            const float h = 0.5f * (kv - ku) / kuv;
            tt = h < 0.0f ? 1.0f / (h - std::sqrt(1.0f + h * h)) : 1.0f / (h + std::sqrt(1.0f + h * h));
            c = 1.0f / std::sqrt(1.0f + tt * tt);
            s = tt * c;
        }
        float k1 = ku - tt * kuv, k2 = kv + tt * kuv;  // eigenvectors (c, -s) and (s, c)
        const glm::vec3 u = out.pdir1[v], w = out.pdir2[v];
        glm::vec3 d1 = c * u - s * w;
        if (k1 < k2) {
            std::swap(k1, k2);
            d1 = s * u + c * w;
        }
        if (!std::isfinite(k1) || !std::isfinite(k2) || !finite(d1)) return;  // keep zero / initial frame
        out.k1[v] = k1;
        out.k2[v] = k2;
        out.pdir1[v] = d1;
        out.pdir2[v] = glm::cross(normal[v], d1);
    });

    // Pass 2: derivative tensor per face from the differences of the vertices' II along the edges.
    // values = area-weighted (C111, C112, C122, C222) per corner, in the corner's principal frame.
    for_each_face_chunk(
        nf,
        [&](size_t i, CornerValues& cv) {
            FaceFrame fr;
            if (!usable_face(i, fr)) return false;
            const glm::vec3& ca = fr.ca;
            const glm::uvec3 f = tris[i];

            // r[j]: the face frame rotated into vertex j's tangent plane, in its principal frame.
            // Its inverse takes the derivative tensor from the face frame back to the vertex's.
            std::array<Rotation, 3> r;
            std::array<glm::vec3, 3> fcurv;  // each vertex's II in the face frame
            for (int j = 0; j < 3; ++j) {
                const uint32_t v = f[j];
                r[j] = frame_change(out.pdir1[v], out.pdir2[v], normal[v], fr.t, fr.n);
                fcurv[j] = rotate_tensor({out.k1[v], 0.0f, out.k2[v]}, r[j]);
            }
            // Least squares for C from ΔII(e) = C(e): d ku = a u + b v, d kuv = b u + c v,
            // d kv = c u + d v (the kuv equation counts twice, as the off-diagonal entry of II does).
            float uu = 0, uv = 0, vv = 0;
            std::array<float, 4> m{0, 0, 0, 0};
            for (int j = 0; j < 3; ++j) {
                const float u = fr.u[j], v = fr.v[j];
                uu += u * u, uv += u * v, vv += v * v;
                const glm::vec3 d = fcurv[prev(j)] - fcurv[next(j)];
                m[0] += u * d[0];
                m[1] += v * d[0] + 2.0f * u * d[1];
                m[2] += 2.0f * v * d[1] + u * d[2];
                m[3] += v * d[2];
            }
            if (!solve_tridiagonal<4>({uu, 2.0f * uu + vv, uu + 2.0f * vv, vv}, {uv, 2.0f * uv, uv}, m)) return false;
            const glm::vec4 dc{m[0], m[1], m[2], m[3]};
            if (!finite(dc)) return false;
            for (int j = 0; j < 3; ++j) {
                const glm::vec4 d = ca[j] * rotate_derivative(dc, r[j].inverse());
                for (int k = 0; k < 4; ++k) cv[4 * j + k] = d[k];
            }
            return true;
        },
        [&](size_t i, const CornerValues& cv) {
            const glm::uvec3 f = tris[i];
            for (int j = 0; j < 3; ++j)
                out.dcurv[f[j]] += glm::vec4(cv[4 * j], cv[4 * j + 1], cv[4 * j + 2], cv[4 * j + 3]);
        });

    for_each_index(nv, [&](size_t v) {
        const float area = out.point_area[v];
        const glm::vec4 d = out.dcurv[v] * (1.0f / area);
        out.dcurv[v] = area > 0.0f && finite(d) ? d : glm::vec4(0.0f);
    });
    return out;
}

}  // namespace inkshade::geometry
