#include "geometry/vertex_faces.hpp"

#include <numeric>

namespace inkshade::geometry {

VertexFaces vertex_faces(const Mesh& mesh) {
    const size_t n = mesh.positions.size();
    VertexFaces vf;
    vf.offsets.assign(n + 1, 0);
    for (const glm::uvec3& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) ++vf.offsets[t[k] + 1];
    std::partial_sum(vf.offsets.begin(), vf.offsets.end(), vf.offsets.begin());
    vf.faces.resize(vf.offsets[n]);
    std::vector<uint32_t> fill(vf.offsets.begin(), vf.offsets.end() - 1);
    for (size_t f = 0; f < mesh.triangles.size(); ++f)
        for (int k = 0; k < 3; ++k) vf.faces[fill[mesh.triangles[f][k]]++] = uint32_t(f);
    return vf;
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
