// own_neighbourhood (own_neighbourhood.hpp): an Embree point query for the faces near a point,
// then their edge-connected part that holds the point's own faces (a union-find over the few
// faces of a ball a pixel or two across).
#include "geometry/own_neighbourhood.hpp"

#include <algorithm>
#include <numeric>
#include <tuple>

namespace inkshade::geometry {

namespace {

// Squared distance from p to triangle (a, b, c): Ericson, "Real-Time Collision Detection"
// 5.1.5, ClosestPtPointTriangle.
double squared_distance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    auto at = [&](const glm::dvec3& q) { return glm::dot(p - q, p - q); };
    if (d1 <= 0.0 && d2 <= 0.0) return at(a);
    const glm::dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return at(b);
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return at(a + (d1 / (d1 - d3)) * ab);
    const glm::dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return at(c);
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return at(a + (d2 / (d2 - d6)) * ac);
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
        return at(b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b));
    const double denom = va + vb + vc;
    if (!(std::abs(denom) > 0.0)) return std::min({at(a), at(b), at(c)});  // degenerate
    return at(a + (vb / denom) * ab + (vc / denom) * ac);
}

struct BallQuery {
    const glm::uvec3* triangles;
    const glm::vec3* positions;
    glm::dvec3 p;
    double radius2;
    size_t limit;
    std::vector<uint32_t> faces;
};

bool collect(RTCPointQueryFunctionArguments* args) {
    auto* q = static_cast<BallQuery*>(args->userPtr);
    if (q->faces.size() >= q->limit) return false;
    const glm::uvec3 t = q->triangles[args->primID];
    if (squared_distance(q->p, glm::dvec3(q->positions[t.x]), glm::dvec3(q->positions[t.y]),
                         glm::dvec3(q->positions[t.z])) <= q->radius2)
        q->faces.push_back(args->primID);
    return false;  // the radius stays: every face within it is wanted
}

// Squared distance from p to segment ab.
double squared_distance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    const glm::dvec3 d = p - (a + t * ab);
    return glm::dot(d, d);
}

uint32_t root(std::vector<uint32_t>& parent, uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

}  // namespace

bool joined(const glm::uvec3* triangles, const glm::vec3* positions, uint32_t f, uint32_t g, const glm::vec3& p,
            float radius) {
    if (f == g) return true;
    const glm::uvec3 a = triangles[f], b = triangles[g];
    const glm::dvec3 centre(p);
    const double radius2 = double(radius) * double(radius);
    uint32_t shared[3], n = 0;
    for (int k = 0; k < 3; ++k)
        if (a[k] == b.x || a[k] == b.y || a[k] == b.z) shared[n++] = a[k];
    for (uint32_t k = 0; k < n; ++k)
        if (glm::dot(glm::dvec3(positions[shared[k]]) - centre, glm::dvec3(positions[shared[k]]) - centre) <= radius2)
            return true;
    return n >= 2 &&
           squared_distance(centre, glm::dvec3(positions[shared[0]]), glm::dvec3(positions[shared[1]])) <= radius2;
}

std::vector<uint32_t> faces_near(RTCScene scene, const glm::uvec3* triangles, const glm::vec3* positions,
                                 const glm::vec3& p, float radius, size_t limit) {
    BallQuery q{triangles, positions, glm::dvec3(p), double(radius) * double(radius), limit, {}};
    RTCPointQuery query;
    query.x = p.x, query.y = p.y, query.z = p.z;
    query.time = 0.0f;
    query.radius = radius;
    RTCPointQueryContext context;
    rtcInitPointQueryContext(&context);
    rtcPointQuery(scene, &query, &context, collect, &q);
    return std::move(q.faces);
}

std::vector<uint32_t> connected_to_seeds(const glm::uvec3* triangles, const glm::vec3* positions,
                                         const std::vector<uint32_t>& faces, const std::vector<char>& seed,
                                         const glm::vec3& p, float radius) {
    const size_t n = faces.size();
    std::vector<uint32_t> parent(n);
    std::iota(parent.begin(), parent.end(), 0u);
    // Each face's three edges (vertex pair, face slot) and its vertices (vertex, vertex, face
    // slot), sorted: equal pairs are a shared edge or vertex.
    std::vector<std::tuple<uint32_t, uint32_t, uint32_t>> shared;
    shared.reserve(6 * n);
    for (uint32_t i = 0; i < n; ++i) {
        const glm::uvec3 t = triangles[faces[i]];
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = t[k], b = t[(k + 1) % 3];
            if (a != b) shared.emplace_back(std::min(a, b), std::max(a, b), i);
            shared.emplace_back(a, a, i);
        }
    }
    std::sort(shared.begin(), shared.end());
    const glm::dvec3 centre(p);
    const double radius2 = double(radius) * double(radius);
    for (size_t e = 1; e < shared.size(); ++e) {
        const auto [a, b, face] = shared[e];
        if (a != std::get<0>(shared[e - 1]) || b != std::get<1>(shared[e - 1])) continue;
        // Joined across this edge or vertex only where it comes within the radius.
        const double d2 = a == b ? glm::dot(glm::dvec3(positions[a]) - centre, glm::dvec3(positions[a]) - centre)
                                 : squared_distance(centre, glm::dvec3(positions[a]), glm::dvec3(positions[b]));
        if (d2 <= radius2) parent[root(parent, face)] = root(parent, std::get<2>(shared[e - 1]));
    }
    std::vector<char> own_root(n, 0);
    for (uint32_t i = 0; i < n; ++i)
        if (seed[i]) own_root[root(parent, i)] = 1;
    std::vector<uint32_t> out;
    for (uint32_t i = 0; i < n; ++i)
        if (own_root[root(parent, i)]) out.push_back(faces[i]);
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace inkshade::geometry
