#include "geometry/surface_points.hpp"

#include "geometry/contours.hpp"

namespace inkshade::geometry {

std::vector<SurfacePoint> surface_points(const Polyline& chain, const ImageProjection& view) {
    std::vector<SurfacePoint> out(chain.points.size());
    for (size_t i = 0; i < out.size(); ++i) {
        SurfacePoint& s = out[i];
        s.world = chain.points[i];
        s.face = i < chain.faces.size() && chain.faces[i] != kNoFace ? int32_t(chain.faces[i]) : -1;
        s.w = float(view.clip_w(s.world));
    }
    return out;
}

namespace {

glm::vec3 barycentric(const Mesh& mesh, const SurfacePoint& s) {
    if (s.face < 0 || size_t(s.face) >= mesh.triangles.size()) return glm::vec3(0.0f);
    const glm::uvec3 t = mesh.triangles[size_t(s.face)];
    const glm::dvec3 a(mesh.positions[t.x]), b(mesh.positions[t.y]), c(mesh.positions[t.z]);
    const glm::dvec3 v0 = b - a, v1 = c - a, v2 = glm::dvec3(s.world) - a;
    const double d00 = glm::dot(v0, v0), d01 = glm::dot(v0, v1), d11 = glm::dot(v1, v1);
    const double d20 = glm::dot(v2, v0), d21 = glm::dot(v2, v1);
    const double denom = d00 * d11 - d01 * d01;
    if (!(denom > 0.0)) return glm::vec3(0.0f);  // a degenerate triangle: no weights
    const double v = (d11 * d20 - d01 * d21) / denom, w = (d00 * d21 - d01 * d20) / denom;
    return glm::vec3(float(1.0 - v - w), float(v), float(w));
}

}  // namespace

void fill_barycentrics(const Mesh& mesh, std::vector<LinePath>& paths) {
    for (LinePath& p : paths)
        for (SurfacePoint& s : p.surface) s.barycentric = barycentric(mesh, s);
}

}  // namespace inkshade::geometry
