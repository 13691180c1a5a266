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
// Faces are handled kLanes at a time: their vertices' data is gathered into structure-of-arrays
// blocks and the per-face arithmetic, free of branches (selects instead), runs in loops over the
// block that the compiler vectorises (4 faces an instruction with SSE2). IEEE arithmetic gives a
// lane the bits a scalar loop would, so results do not depend on where a face falls in a block.
#include "geometry/curvature.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace inkshade::geometry {
namespace {

constexpr size_t kGrain = 8192;  // faces or vertices per TBB task

constexpr int next(int j) { return j == 2 ? 0 : j + 1; }
constexpr int prev(int j) { return j == 0 ? 2 : j - 1; }

// Tests that sit inside the vectorised face loops: 0 or 1 as int32_t combined with &, no
// short-circuits, no std::isfinite, no bool (GCC 12 vectorises neither, nor bool masks mixed
// with float lanes). NaN compares false, so it is not finite.
[[gnu::always_inline]] inline int32_t finite(float x) { return std::fabs(x) <= std::numeric_limits<float>::max(); }
[[gnu::always_inline]] inline int32_t finite(const glm::vec3& v) { return finite(v.x) & finite(v.y) & finite(v.z); }
[[gnu::always_inline]] inline int32_t finite(const glm::vec4& v) { return finite(glm::vec3(v)) & finite(v.w); }
[[gnu::always_inline]] inline int32_t nonzero(const glm::vec3& v) {
    return int32_t(v.x != 0.0f) | int32_t(v.y != 0.0f) | int32_t(v.z != 0.0f);
}
// c ? a : b per component (a select of a whole struct would be a branch).
[[gnu::always_inline]] inline glm::vec3 pick(bool c, const glm::vec3& a, const glm::vec3& b) {
    return {c ? a.x : b.x, c ? a.y : b.y, c ? a.z : b.z};
}

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
// pivot is not clearly positive (the normal equations of a degenerate face): 0 or 1. No early
// exit, so that it vectorises across faces; a failed solve leaves garbage in rhs.
template <int N>
[[gnu::always_inline]] inline int32_t solve_tridiagonal(std::array<float, N> d, const std::array<float, N - 1>& o,
                                                        std::array<float, N>& rhs) {
    const float eps = 1e-6f * (std::abs(d[0]) + std::abs(d[N - 1]));
    std::array<float, N> inv;  // reciprocal pivots: N divisions instead of 2N - 1
    int32_t ok = 1;
#pragma GCC unroll 4
    for (int i = 1; i < N; ++i) {
        ok &= int32_t(d[i - 1] > eps);
        inv[i - 1] = 1.0f / d[i - 1];
        const float l = o[i - 1] * inv[i - 1];
        d[i] -= l * o[i - 1];
        rhs[i] -= l * rhs[i - 1];
    }
    ok &= int32_t(d[N - 1] > eps);
    rhs[N - 1] /= d[N - 1];
#pragma GCC unroll 4
    for (int i = N - 2; i >= 0; --i) rhs[i] = (rhs[i] - o[i] * rhs[i + 1]) * inv[i];
    return ok;
}

// Area of the face owned by each corner: the Voronoi region of the corner inside the triangle, or
// for an obtuse triangle A/2 at the obtuse corner and A/4 at the others (Meyer et al. 2003,
// "Discrete Differential-Geometry Operators for Triangulated 2-Manifolds", Section 3.3).
// l2[j] is the squared length of the edge opposite corner j. Zero for a degenerate face.
[[gnu::always_inline]] inline glm::vec3 corner_areas(const glm::vec3& l2, float area) {
    // ew[j] = 4A·|e_j|²·cot(angle j): the Voronoi area of corner j is (ew[j+1] + ew[j+2]) / (32 A)
    // and the three ew sum to 16 A², so normalising by their sum keeps the split exact.
    glm::vec3 ew;
#pragma GCC unroll 3
    for (int j = 0; j < 3; ++j) ew[j] = l2[j] * (l2[next(j)] + l2[prev(j)] - l2[j]);
    const float scale = 0.5f * area / (ew[0] + ew[1] + ew[2]);
    const glm::vec3 acute(scale * (ew[1] + ew[2]), scale * (ew[2] + ew[0]), scale * (ew[0] + ew[1]));
    // The first right or obtuse corner (ew <= 0) takes A/2, the others A/4.
    const bool o0 = ew[0] <= 0.0f, o1 = !o0 & (ew[1] <= 0.0f), o2 = !o0 & !o1 & (ew[2] <= 0.0f);
    const float q = 0.25f * area, h = 0.5f * area;
    const glm::vec3 obtuse(o0 ? h : q, o1 ? h : q, o2 ? h : q);
    const int32_t usable = int32_t(area > 0.0f) & finite(area);
    return pick(usable != 0, pick(o0 | o1 | o2, obtuse, acute), glm::vec3(0.0f));
}

// Face frame: t along edge 0, b = n × t in the face plane; the edges in that frame and the
// corner areas, everything both passes need of a face.
struct FaceFrame {
    glm::vec3 t, b, n;
    std::array<float, 3> u, v;  // edge j (p[prev j] - p[next j], opposite corner j) in (t, b)
    glm::vec3 ca;               // corner areas; zero when the face is unusable
};

[[gnu::always_inline]] inline FaceFrame face_frame(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2) {
    FaceFrame fr;
    const glm::vec3 e0 = p2 - p1, e1 = p0 - p2, e2 = p1 - p0;
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
    const glm::vec3 ca = corner_areas(l2, 0.5f * twice_area);
    fr.ca = pick((finite(fr.t) & finite(fr.n)) != 0, ca, glm::vec3(0.0f));
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
    const glm::vec3 turned = nu - (nn + on) * (glm::dot(nu, on - ndot * nn) / (1.0f + ndot));
    nu = pick(1.0f + ndot <= 1e-6f, -nu, turned);  // opposite normals: any half-turn will do
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

// Faces per block of the structure-of-arrays loops.
constexpr int kLanes = 16;

// A vertex attribute of the three corners of kLanes faces, one array per corner and component.
struct CornerBlock {
    float v[3][3][kLanes];
    void set(int j, int i, const glm::vec3& a) { v[j][0][i] = a.x, v[j][1][i] = a.y, v[j][2][i] = a.z; }
    glm::vec3 at(int j, int i) const { return {v[j][0][i], v[j][1][i], v[j][2][i]}; }
};

// Per-face results of a block: the corner values by entry, and whether the face contributes.
struct BlockResults {
    float values[12][kLanes];
    int32_t ok[kLanes];  // as wide as a float, so the loops vectorise with one vector size
};

// Runs `block(begin, count, results)` for the faces in blocks of kLanes (count <= kLanes), in
// parallel, and then `scatter(i, values)` for each face i, in face order, whose result is ok.
// The chunk buffer stays in cache and is reused, so the per-face results never make a round
// trip through main memory.
template <class Block, class Scatter>
void for_each_face_block(size_t nf, const Block& block, const Scatter& scatter) {
    constexpr size_t kChunk = size_t(1) << 15;  // a multiple of kLanes
    std::vector<CornerValues> buffer(std::min(nf, kChunk));
    std::vector<uint8_t> contributed(buffer.size());
    for (size_t begin = 0; begin < nf; begin += kChunk) {
        const size_t end = std::min(nf, begin + kChunk);
        const size_t blocks = (end - begin + kLanes - 1) / kLanes;
        tbb::parallel_for(tbb::blocked_range<size_t>(0, blocks, kGrain / 4 / kLanes),
                          [&](const tbb::blocked_range<size_t>& r) {
            BlockResults results;
            for (size_t b = r.begin(); b != r.end(); ++b) {
                const size_t first = begin + b * kLanes;
                const int count = int(std::min<size_t>(kLanes, end - first));
                block(first, count, results);
                for (int i = 0; i < count; ++i) {
                    contributed[first - begin + i] = results.ok[i];
                    for (int k = 0; k < 12; ++k) buffer[first - begin + i][k] = results.values[k][i];
                }
            }
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
    // Gathers the positions and normals of the faces of a block; faces past `count` or with bad
    // indices or zero normals get zeros and usable = false (no face is read out of range).
    const auto gather =
        [&](size_t first, int count, CornerBlock& pos, CornerBlock& nrm, int32_t* usable, const auto& more) {
        for (int i = 0; i < kLanes; ++i) {
            const glm::uvec3 f = i < count ? tris[first + i] : glm::uvec3(0);
            usable[i] = i < count && usable_indices(f) ? 1 : 0;
            for (int j = 0; j < 3; ++j) {
                pos.set(j, i, usable[i] ? p[f[j]] : glm::vec3(0.0f));
                nrm.set(j, i, usable[i] ? normal[f[j]] : glm::vec3(0.0f));
                more(j, i, usable[i] ? f[j] : uint32_t(0), usable[i]);
            }
        }
    };

    // Pass 1: second fundamental form per face, rotated into each corner's vertex frame.
    // values = (3 corner areas, then area-weighted (ku, kuv, kv) per corner).
    for_each_face_block(
        nf,
        [&](size_t first, int count, BlockResults& res) {
        CornerBlock pos, nrm, dir;  // dir: each vertex's initial tangent pdir1
        int32_t usable[kLanes];
        gather(first, count, pos, nrm, usable, [&](int j, int i, uint32_t v, bool ok) {
            dir.set(j, i, ok ? out.pdir1[v] : glm::vec3(1.0f, 0.0f, 0.0f));
        });
        for (int i = 0; i < kLanes; ++i) {
            const FaceFrame fr = face_frame(pos.at(0, i), pos.at(1, i), pos.at(2, i));
            // Least squares for II = [[ku, kuv], [kuv, kv]] from II·(u, v) = (dnu, dnv) on each edge.
            float uu = 0, uv = 0, vv = 0;
            std::array<float, 3> m{0, 0, 0};
#pragma GCC unroll 3
            for (int j = 0; j < 3; ++j) {
                const float u = fr.u[j], v = fr.v[j];
                uu += u * u, uv += u * v, vv += v * v;
                const glm::vec3 dn = nrm.at(prev(j), i) - nrm.at(next(j), i);
                const float dnu = glm::dot(dn, fr.t), dnv = glm::dot(dn, fr.b);
                m[0] += dnu * u;
                m[1] += dnu * v + dnv * u;
                m[2] += dnv * v;
            }
            const int32_t solved = solve_tridiagonal<3>({uu, uu + vv, vv}, {uv, uv}, m);
            const glm::vec3 ii{m[0], m[1], m[2]};
#pragma GCC unroll 3
            for (int j = 0; j < 3; ++j) {
                const Rotation r = frame_change(fr.t, fr.b, fr.n, dir.at(j, i), nrm.at(j, i));
                const glm::vec3 k = fr.ca[j] * rotate_tensor(ii, r);
                res.values[j][i] = fr.ca[j];
                res.values[3 + 3 * j][i] = k[0], res.values[4 + 3 * j][i] = k[1], res.values[5 + 3 * j][i] = k[2];
            }
            res.ok[i] = usable[i] & nonzero(fr.ca) & solved & finite(ii);
        }
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
    for_each_face_block(
        nf,
        [&](size_t first, int count, BlockResults& res) {
        CornerBlock pos, nrm, dir1, dir2;
        float k1[3][kLanes], k2[3][kLanes];
        int32_t usable[kLanes];
        gather(first, count, pos, nrm, usable, [&](int j, int i, uint32_t v, bool ok) {
            dir1.set(j, i, ok ? out.pdir1[v] : glm::vec3(1.0f, 0.0f, 0.0f));
            dir2.set(j, i, ok ? out.pdir2[v] : glm::vec3(0.0f, 1.0f, 0.0f));
            k1[j][i] = ok ? out.k1[v] : 0.0f;
            k2[j][i] = ok ? out.k2[v] : 0.0f;
        });
        for (int i = 0; i < kLanes; ++i) {
            const FaceFrame fr = face_frame(pos.at(0, i), pos.at(1, i), pos.at(2, i));
            // r[j]: the face frame rotated into vertex j's tangent plane, in its principal
            // frame. Its inverse takes the derivative tensor from the face frame back.
            std::array<Rotation, 3> r;
            std::array<glm::vec3, 3> fcurv;  // each vertex's II in the face frame
#pragma GCC unroll 3
            for (int j = 0; j < 3; ++j) {
                r[j] = frame_change(dir1.at(j, i), dir2.at(j, i), nrm.at(j, i), fr.t, fr.n);
                fcurv[j] = rotate_tensor({k1[j][i], 0.0f, k2[j][i]}, r[j]);
            }
            // Least squares for C from ΔII(e) = C(e): d ku = a u + b v, d kuv = b u + c v,
            // d kv = c u + d v (the kuv equation counts twice, as the off-diagonal entry of
            // II does).
            float uu = 0, uv = 0, vv = 0;
            std::array<float, 4> m{0, 0, 0, 0};
#pragma GCC unroll 3
            for (int j = 0; j < 3; ++j) {
                const float u = fr.u[j], v = fr.v[j];
                uu += u * u, uv += u * v, vv += v * v;
                const glm::vec3 d = fcurv[prev(j)] - fcurv[next(j)];
                m[0] += u * d[0];
                m[1] += v * d[0] + 2.0f * u * d[1];
                m[2] += 2.0f * v * d[1] + u * d[2];
                m[3] += v * d[2];
            }
            const int32_t solved =
                solve_tridiagonal<4>({uu, 2.0f * uu + vv, uu + 2.0f * vv, vv}, {uv, 2.0f * uv, uv}, m);
            const glm::vec4 dc{m[0], m[1], m[2], m[3]};
#pragma GCC unroll 3
            for (int j = 0; j < 3; ++j) {
                const glm::vec4 d = fr.ca[j] * rotate_derivative(dc, r[j].inverse());
#pragma GCC unroll 4
                for (int k = 0; k < 4; ++k) res.values[4 * j + k][i] = d[k];
            }
            res.ok[i] = usable[i] & nonzero(fr.ca) & solved & finite(dc);
        }
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
