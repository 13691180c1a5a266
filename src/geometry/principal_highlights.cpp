// Principal highlights: per vertex e1, v·e1 and the strength test for the view, then per face
// up to three edge crossings, each found from its edge alone (as ridges.cpp does for its line
// field); faces in fixed-size blocks (TBB), joined in order.
#include "geometry/principal_highlights.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>

#include "geometry/face_segments.hpp"
#include "geometry/feature_size.hpp"

namespace inkshade::geometry {
namespace {

// One vertex for the view: e1 (the principal direction of larger |k|), that curvature, v·e1 and
// rtsc's test (k1² − k2²)(n·v). `valid` is false where an input is not finite.
struct VertexView {
    glm::vec3 e1{0.0f};
    float k1 = 0.0f, dot = 0.0f, test = 0.0f;
    bool valid = false;
};

VertexView vertex_view(const glm::vec3& normal, const glm::dvec3& v, const Curvature& c, size_t i) {
    const bool first = std::abs(c.k1[i]) >= std::abs(c.k2[i]);
    const double k1 = first ? c.k1[i] : c.k2[i], k2 = first ? c.k2[i] : c.k1[i];
    const glm::dvec3 e1(first ? c.pdir1[i] : c.pdir2[i]);
    const double dot = glm::dot(v, e1);
    const double test = (k1 * k1 - k2 * k2) * glm::dot(v, glm::dvec3(normal));
    VertexView out;
    out.valid = std::isfinite(k1) && std::isfinite(dot) && std::isfinite(test) && glm::dot(e1, e1) > 0.0;
    if (!out.valid) return out;
    out.e1 = glm::vec3(e1);
    out.k1 = float(k1);
    out.dot = float(dot);
    out.test = float(test);
    return out;
}

constexpr float kCos45 = 0.70710678f;

struct Crossing {
    glm::vec3 p{0.0f};
    float strength = 1.0f;
};

}  // namespace

std::vector<LineSegment> extract_principal_highlights(const Mesh& mesh, const std::vector<glm::vec3>& normals,
                                                      const Curvature& curvature, const Camera& camera,
                                                      const PrincipalHighlightOptions& options) {
    const size_t n = mesh.positions.size();
    const Curvature& c = curvature;
    if (normals.size() != n || c.k1.size() != n || c.k2.size() != n || c.pdir1.size() != n || c.pdir2.size() != n)
        throw std::invalid_argument("principal highlights: need normals and curvature per vertex");
    const double size =
        options.feature_size > 0.0f ? double(options.feature_size) : double(line_feature_size(mesh, curvature));
    const double threshold = double(options.threshold) / (size * size);
    const ViewVector view(camera);

    std::vector<VertexView> at(n);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, kFaceGrain), [&](const auto& range) {
        for (size_t i = range.begin(); i != range.end(); ++i)
            at[i] = vertex_view(normals[i], view.at(mesh.positions[i]), c, i);
    });

    // The zero of v·e1 on edge (i, j), j's e1 turned to agree with i's, if the test passes there.
    auto crossing = [&](uint32_t i, uint32_t j) -> std::optional<Crossing> {
        if (j < i) std::swap(i, j);
        const VertexView &a = at[i], &b = at[j];
        const double di = a.dot;
        const double dj = (glm::dot(a.e1, b.e1) < 0.0f ? -1.0 : 1.0) * double(b.dot);
        if ((di >= 0.0) == (dj >= 0.0)) return {};
        const double t = di / (di - dj);
        const double test = double(a.test) + t * (double(b.test) - double(a.test));
        if (!(test > threshold)) return {};
        const glm::dvec3 pi(mesh.positions[i]), pj(mesh.positions[j]);
        Crossing x;
        x.p = glm::vec3(pi + t * (pj - pi));
        x.strength = options.fade ? float((test - threshold) / test) : 1.0f;
        return x;
    };

    const auto& tris = mesh.triangles;
    return collect_face_segments(tris.size(), [&](size_t f, std::vector<LineSegment>& out) {
        const glm::uvec3 t = tris[f];
        if (t.x >= n || t.y >= n || t.z >= n || t.x == t.y || t.y == t.z || t.z == t.x) return;
        const VertexView* v[3] = {&at[t.x], &at[t.y], &at[t.z]};
        if (!v[0]->valid || !v[1]->valid || !v[2]->valid) return;
        // One kind of bend at all three corners, and that kind asked for.
        const bool convex = v[0]->k1 >= 0.0f && v[1]->k1 >= 0.0f && v[2]->k1 >= 0.0f;
        const bool concave = v[0]->k1 <= 0.0f && v[1]->k1 <= 0.0f && v[2]->k1 <= 0.0f;
        if (!(convex && options.convex) && !(concave && options.concave)) return;
        // The three e1 within 45° of the one with the largest |k1|.
        int ref = 0;
        for (int k = 1; k < 3; ++k)
            if (std::abs(v[k]->k1) > std::abs(v[ref]->k1)) ref = k;
        for (int k = 0; k < 3; ++k)
            if (std::abs(glm::dot(v[k]->e1, v[ref]->e1)) < kCos45) return;
        Crossing x[2];
        uint64_t key[2];
        int count = 0;
        for (int s = 0; s < 3; ++s)
            if (const auto found = crossing(t[s], t[(s + 1) % 3])) {
                if (count == 2) return;  // three: the field turns inside the face
                x[count] = *found;
                key[count++] = edge_key(t[s], t[(s + 1) % 3]);
            }
        if (count != 2) return;
        LineSegment seg;
        seg.a = x[0].p;
        seg.b = x[1].p;
        seg.strength_a = x[0].strength;
        seg.strength_b = x[1].strength;
        seg.edge_a = key[0];
        seg.edge_b = key[1];
        seg.face = uint32_t(f);
        out.push_back(seg);
    });
}

}  // namespace inkshade::geometry
