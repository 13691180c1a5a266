// Ridges and valleys: per face, up to three edge crossings of the principal-curvature
// derivative, each found from its edge alone; faces in fixed-size blocks (TBB), joined in order.
#include "geometry/ridges.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>

#include "geometry/face_segments.hpp"
#include "geometry/feature_size.hpp"

namespace inkshade::geometry {
namespace {

struct Family {
    const std::vector<glm::vec3>& dir;  // pdir1 or pdir2
    const std::vector<float>& k;        // k1 or k2
    int component;                      // C111 (0) or C222 (3) in dcurv
    bool maximum;                       // ridge: maximum of k1; valley: minimum of k2
};

// The crossing of e = ∂k/∂s on edge (i, j), i < j, or nothing. j's direction (and with it the
// sign of e_j) is flipped to agree with i's; an extremum of the right kind and size only.
std::optional<glm::vec3> crossing(const Mesh& mesh, const Curvature& c, const Family& fam, double threshold, uint32_t i,
                                  uint32_t j) {
    if (j < i) std::swap(i, j);
    const glm::dvec3 di(fam.dir[i]), dj(fam.dir[j]);
    const double ei = c.dcurv[i][fam.component];
    const double ej = (glm::dot(di, dj) < 0.0 ? -1.0 : 1.0) * c.dcurv[j][fam.component];
    if (!std::isfinite(ei) || !std::isfinite(ej) || (ei >= 0.0) == (ej >= 0.0)) return {};
    const glm::dvec3 pi(mesh.positions[i]), pj(mesh.positions[j]);
    // Along di, e falls through zero at a maximum and rises at a minimum.
    const double along = glm::dot(pj - pi, di) * (ej - ei);
    if (fam.maximum ? !(along < 0.0) : !(along > 0.0)) return {};
    const double t = ei / (ei - ej);
    const double k = double(fam.k[i]) + t * (double(fam.k[j]) - double(fam.k[i]));
    if (fam.maximum ? !(k > threshold) : !(k < -threshold)) return {};
    return glm::vec3(pi + t * (pj - pi));
}

std::vector<LineSegment> extract(const Mesh& mesh, const Curvature& c, const Family& fam, double threshold) {
    const auto& tris = mesh.triangles;
    const size_t n = mesh.positions.size();
    return collect_face_segments(tris.size(), [&](size_t f, std::vector<LineSegment>& out) {
        const glm::uvec3 t = tris[f];
        if (t.x >= n || t.y >= n || t.z >= n || t.x == t.y || t.y == t.z || t.z == t.x) return;
        glm::vec3 p[3];
        uint64_t key[3];
        int count = 0;
        for (int s = 0; s < 3; ++s)
            if (const auto x = crossing(mesh, c, fam, threshold, t[s], t[(s + 1) % 3])) {
                p[count] = *x;
                key[count++] = edge_key(t[s], t[(s + 1) % 3]);
            }
        if (count != 2) return;
        LineSegment seg;
        seg.a = p[0];
        seg.b = p[1];
        seg.edge_a = key[0];
        seg.edge_b = key[1];
        seg.face = uint32_t(f);
        out.push_back(seg);
    });
}

}  // namespace

RidgeLines extract_ridges(const Mesh& mesh, const Curvature& curvature, const RidgeOptions& options) {
    const size_t n = mesh.positions.size();
    if (curvature.k1.size() != n || curvature.k2.size() != n || curvature.pdir1.size() != n ||
        curvature.pdir2.size() != n || curvature.dcurv.size() != n)
        throw std::invalid_argument("extract_ridges: need curvature per vertex");
    const double size =
        options.feature_size > 0.0f ? double(options.feature_size) : double(line_feature_size(mesh, curvature));
    const double threshold = double(options.threshold) / size;
    RidgeLines out;
    out.ridges = extract(mesh, curvature, {curvature.pdir1, curvature.k1, 0, true}, threshold);
    out.valleys = extract(mesh, curvature, {curvature.pdir2, curvature.k2, 3, false}, threshold);
    return out;
}

}  // namespace inkshade::geometry
