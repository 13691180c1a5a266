#include "geometry/vertex_faces.hpp"

#include <algorithm>
#include <numeric>

namespace inkshade::geometry {

namespace {

// Counts each listed vertex's corners into offsets[v + 2], sums them, then lists the faces
// with offsets[v + 1] as the fill position, which leaves it at the star's end: no second
// array of fill positions. Both passes split the vertices among the threads (for_vertex_ranges)
// when many are listed; for a few, one scan of the faces costs less than one per thread.
template <class Listed>
VertexFaces stars_of(const Mesh& mesh, Listed listed, bool many) {
    const size_t n = mesh.positions.size(), parts = many ? ~size_t(0) : 1;
    VertexFaces vf;
    vf.offsets.assign(n + 2, 0);
    auto count = [&](size_t lo, size_t hi) {
        for (const glm::uvec3& t : mesh.triangles)
            for (int k = 0; k < 3; ++k)
                if (t[k] >= lo && t[k] < hi && listed(t[k])) ++vf.offsets[t[k] + 2];
    };
    for_vertex_ranges(n, count, parts);
    std::partial_sum(vf.offsets.begin(), vf.offsets.end(), vf.offsets.begin());
    vf.faces.resize(vf.offsets[n + 1]);
    auto fill = [&](size_t lo, size_t hi) {
        for (size_t f = 0; f < mesh.triangles.size(); ++f)
            for (int k = 0; k < 3; ++k) {
                const uint32_t v = mesh.triangles[f][k];
                if (v >= lo && v < hi && listed(v)) vf.faces[vf.offsets[v + 1]++] = uint32_t(f);
            }
    };
    for_vertex_ranges(n, fill, parts);
    vf.offsets.pop_back();
    return vf;
}

}  // namespace

VertexFaces vertex_faces(const Mesh& mesh) {
    return stars_of(
        mesh, [](uint32_t) { return true; }, true);
}

VertexFaces vertex_faces(const Mesh& mesh, const std::vector<uint8_t>& only) {
    const size_t listed = size_t(std::count_if(only.begin(), only.end(), [](uint8_t o) { return o != 0; }));
    return stars_of(
        mesh, [&](uint32_t v) { return only[v] != 0; }, 2 * listed >= only.size());
}

EdgeMate edge_mate(const Mesh& mesh, const VertexFaces& vf, uint32_t face, uint32_t v, uint32_t w) {
    EdgeMate mate;
    for (const uint32_t* g = vf.begin(v); g != vf.end(v); ++g) {
        if (*g == face || (g != vf.begin(v) && g[-1] == *g)) continue;  // itself, or listed twice
        const glm::uvec3 t = mesh.triangles[*g];
        if (t.x == w || t.y == w || t.z == w)
            if (mate.count++ == 0) mate.face = *g;
    }
    return mate;
}

}  // namespace inkshade::geometry
