// RayScene::occlusion_levels (visibility.hpp): rays from the viewer to each point, every
// surface crossing counted once by an Embree occlusion filter, a line's own faces (PointOn) and
// a contour sample's own fold (FoldWalk) left out.
#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry/own_neighbourhood.hpp"
#include "geometry/ray_scene_impl.hpp"
#include "geometry/triangle_vertices.hpp"

namespace inkshade::geometry {

namespace {

// Hits recorded per ray for counting each crossing once (levels past this are rare and are
// counted without that check).
constexpr int kRecordedHits = 16;
// Hits that may be on the point's own surface (OcclusionQuery::own_depth), held per ray until
// the trace ends; more are counted at once (as hiding: never a line drawn through a surface).
constexpr int kDeferredHits = 8;

struct RayState;

// rtcOccluded1M's context, extended with what the filter reads (Embree's documented way to hand
// per-ray data to a filter function: the context is passed through unchanged).
struct OcclusionContext {
    RTCIntersectContext rtc;
    const Mesh* mesh = nullptr;
    const glm::uvec3* triangles = nullptr;
    const EdgeNeighbours* around = nullptr;
    const OcclusionQuery* queries = nullptr;  // indexed by the ray's id
    RayState* states = nullptr;               // likewise
    int cap = 1;
    glm::dvec3 eye{0.0}, forward{0.0, 0.0, -1.0};
    bool orthographic = false;
};

// Does triangle `prim` contain the point (by topology)?
bool contains_point(const OcclusionContext& ctx, const PointOn& on, uint32_t prim, const glm::uvec3& t) {
    if (prim == on.face || prim == on.face_b) return true;
    switch (on.kind) {
        case PointOn::Faces: return false;
        case PointOn::Edge: return has_vertex(t, on.u) && has_vertex(t, on.v);
        case PointOn::Vertex: return has_vertex(t, on.u);
        case PointOn::FaceNeighbours:
            for (uint32_t f : {on.face, on.face_b})
                if (f != kNoFace && shared_vertices(t, ctx.triangles[f]) >= 2) return true;
            return false;
    }
    return false;
}

// A contour point's fold (RayScene::occlusion_levels): walking the mesh's cross-section in the
// plane through the ray and the point's normal, both ways from the point, the faces where the
// section stays within `fold_band` of the ray's line, and the one where it meets that line on
// leaving the band. Walked lazily, one step of each way in turn (a fold hit is usually next to
// the point), and kept: a ray's later hits continue the same walk.
class FoldWalk {
public:
    // Is face `target` in q's fold?
    bool contains(const OcclusionContext& ctx, const OcclusionQuery& q, uint32_t target) {
        if (!started_) start(ctx, q);
        if (std::find(seen_.begin(), seen_.end(), target) != seen_.end()) return true;
        while (!ways_[0].done || !ways_[1].done)
            for (Way& w : ways_) {
                if (w.done) continue;
                const uint32_t face = advance(ctx, w);
                if (face == kNoFace) continue;
                seen_.push_back(face);
                if (face == target) return true;
            }
        return false;
    }

private:
    // One way from p: from `face` (entered by edge (in_a, in_b); kNoFace when p is inside it
    // and `rising` picks the way), out by its other cut edge, until the section leaves the band.
    struct Way {
        uint32_t face = kNoFace, in_a = kNoFace, in_b = kNoFace;
        bool rising = true;
        double h_in = 0.0;
        int step = 0;
        bool done = true;
    };

    void start(const OcclusionContext& ctx, const OcclusionQuery& q) {
        started_ = true;
        if (!ctx.around || q.on.face == kNoFace || !(q.fold_band > 0.0f)) return;
        p_ = glm::dvec3(q.point);
        const glm::dvec3 d = ctx.orthographic ? ctx.forward : glm::normalize(p_ - ctx.eye);
        up_ = glm::dvec3(q.normal) - glm::dot(glm::dvec3(q.normal), d) * d;  // in the plane, ⟂ ray
        const double up_len = glm::length(up_);
        if (!(up_len > 1e-12)) return;
        up_ /= up_len;
        m_ = glm::cross(d, up_);  // the plane's normal
        band_ = double(q.fold_band);
        if (q.on.kind == PointOn::Edge) {  // p on an edge: one way through each of its two faces
            ways_[0] = {q.on.face, q.on.u, q.on.v, true, 0.0, 1, false};
            ways_[1] = {ctx.around->across(q.on.face, q.on.u, q.on.v), q.on.u, q.on.v, true, 0.0, 1, false};
        } else {
            ways_[0] = {q.on.face, kNoFace, kNoFace, true, 0.0, 0, false};
            ways_[1] = {q.on.face, kNoFace, kNoFace, false, 0.0, 0, false};
        }
    }

    bool side(const Mesh& mesh, uint32_t v) const { return glm::dot(glm::dvec3(mesh.positions[v]) - p_, m_) >= 0.0; }

    // Where the plane cuts edge (a, b) (sides differ), from the ordered pair so that both faces
    // of the edge get the same point; its height above the ray's line.
    double height(const Mesh& mesh, uint32_t a, uint32_t b) const {
        if (a > b) std::swap(a, b);
        const glm::dvec3 pa(mesh.positions[a]), pb(mesh.positions[b]);
        const double sa = glm::dot(pa - p_, m_), sb = glm::dot(pb - p_, m_);
        const double t = sa / (sa - sb);
        return glm::dot(pa + t * (pb - pa) - p_, up_);
    }

    // One step of a way: the face it was in when that face belongs to the fold, else kNoFace.
    uint32_t advance(const OcclusionContext& ctx, Way& w) {
        if (w.face == kNoFace || w.step >= 256) {
            w.done = true;
            return kNoFace;
        }
        const Mesh& mesh = *ctx.mesh;
        const glm::uvec3 t = ctx.triangles[w.face];
        const bool first = w.step == 0 && w.in_a == kNoFace;
        uint32_t exit_a = kNoFace, exit_b = kNoFace;
        double h_out = 0.0;
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = t[k], b = t[(k + 1) % 3];
            if (side(mesh, a) == side(mesh, b) || (a == w.in_a && b == w.in_b) || (a == w.in_b && b == w.in_a))
                continue;
            const double h = height(mesh, a, b);
            // Inside p's face the section runs both ways: the rising way leaves by the higher
            // cut (by comparison, not sign: p lies on the face only up to float rounding).
            if (first && exit_a != kNoFace && (h > h_out) != w.rising) continue;
            exit_a = a, exit_b = b, h_out = h;
            if (!first) break;
        }
        if (exit_a == kNoFace) {
            w.done = true;
            return kNoFace;
        }
        // Inside this face the section stays within the band (a ray can only meet the face on
        // it: float rounding may make it do so where the exact section just misses), or it
        // meets the ray's line before leaving the band. p's own face aside.
        const bool inside = std::abs(h_out) <= band_;
        const uint32_t fold = w.step > 0 && (inside || (w.h_in <= 0.0) != (h_out <= 0.0)) ? w.face : kNoFace;
        if (!inside) {
            w.done = true;
        } else {
            w.in_a = exit_a, w.in_b = exit_b, w.h_in = h_out;
            w.face = ctx.around->across(w.face, exit_a, exit_b);
            ++w.step;
        }
        return fold;
    }

    bool started_ = false;
    glm::dvec3 p_{0.0}, up_{0.0}, m_{0.0};
    double band_ = 0.0;
    Way ways_[2];
    std::vector<uint32_t> seen_;  // fold faces walked so far
};

// What one ray has met so far (the filter's running count).
struct RayState {
    uint8_t level = 0;
    uint8_t recorded = 0;
    float same_point = 0.0f;  // two hits closer than this in t are at one point of the ray
    float t[kRecordedHits];
    uint32_t prim[kRecordedHits];
    FoldWalk fold;  // contour samples
    // Distance in front of the point of a hit at t: (t_point − t) · t_scale.
    float t_point = 1.0f, t_scale = 0.0f;
    // Held hits: within own_depth in front, on faces that may be the point's own neighbourhood.
    uint8_t deferred = 0;
    float deferred_t[kDeferredHits];
    uint32_t deferred_prim[kDeferredHits];

    // Has a hit at t on triangle tri been counted already (at one point of the ray, sharing a
    // vertex: a ray through an edge or vertex of an occluder crosses one surface)?
    bool counted(const glm::uvec3* triangles, uint32_t face, const glm::uvec3& tri, float at) const {
        for (int k = 0; k < recorded; ++k)
            if (prim[k] == face || (std::abs(t[k] - at) <= same_point && shared_vertices(tri, triangles[prim[k]]) > 0))
                return true;
        return false;
    }
    void record(uint32_t face, float at) {
        if (recorded < kRecordedHits) t[recorded] = at, prim[recorded] = face, ++recorded;
        ++level;
    }
};

// Do faces g and f share a vertex where their shading normals are the same (not across a
// hard edge)?
bool smoothly_touch(const OcclusionContext& ctx, uint32_t g, uint32_t f) {
    const glm::uvec3 a = ctx.triangles[g], b = ctx.triangles[f];
    const bool hard = ctx.mesh->has_hard_edges();
    for (int k = 0; k < 3; ++k)
        for (int m = 0; m < 3; ++m)
            if (a[k] == b[m] && (!hard || ctx.mesh->shading_normal_id(g, k) == ctx.mesh->shading_normal_id(f, m)))
                return true;
    return false;
}

// How far in front a hit on face `prim` may lie and still be a contour sample's own surface
// (OcclusionQuery::slope_depth): slope_depth × tan of the angle between the face and the plane
// normal to the ray (its depth slope), capped at kMaxOwnSlope, for a face that touches the
// point's face, or a face across one of its edges, where the normals are smooth (a shared
// vertex with the same shading normal: the smooth surface the interpolated contour lies on
// ends at a hard edge); 0 for any other face.
// rtsc pushes every front face back by 5 px of its slope (glPolygonOffset(5, 30)); here only
// the faces around the point, so that the tube of a torus in front of its inner contour, a
// surface that comes back to the ray, still hides it.
float slope_allowance(const OcclusionContext& ctx, const OcclusionQuery& q, const RTCFilterFunctionNArguments* args,
                      unsigned i, uint32_t prim, const glm::uvec3& tri) {
    if (!(q.slope_depth > 0.0f) || q.on.face == kNoFace) return 0.0f;
    const uint32_t face = q.on.face;
    bool touches = smoothly_touch(ctx, prim, face);
    // ... or one of the faces across its edges: on a coarse sphere the polygon outline in front
    // of the contour is often the far half of the next quad.
    const glm::uvec3 own = ctx.triangles[face];
    for (int k = 0; k < 3 && !touches && ctx.around; ++k) {
        const uint32_t next = ctx.around->across(face, own[k], own[(k + 1) % 3]);
        touches = next != kNoFace && smoothly_touch(ctx, next, face) && smoothly_touch(ctx, prim, next);
    }
    if (!touches) return 0.0f;
    const glm::vec3* p = ctx.mesh->positions.data();
    const glm::dvec3 a(p[tri.x]), n = glm::cross(glm::dvec3(p[tri.y]) - a, glm::dvec3(p[tri.z]) - a);
    const glm::dvec3 d(RTCRayN_dir_x(args->ray, args->N, i), RTCRayN_dir_y(args->ray, args->N, i),
                       RTCRayN_dir_z(args->ray, args->N, i));
    const double nn = glm::dot(n, n), dd = glm::dot(d, d), c = glm::dot(n, d);
    if (!(nn > 0.0 && dd > 0.0)) return 0.0f;
    const double cos2 = c * c / (nn * dd), cap = double(kMaxOwnSlope);
    const double slope = cos2 > 0.0 ? std::min(std::sqrt(std::max(1.0 - cos2, 0.0) / cos2), cap) : cap;
    return float(double(q.slope_depth) * slope);
}

}  // namespace

// The occlusion filter (ray_scene_impl.hpp).
void count_crossings(const RTCFilterFunctionNArguments* args) {
    const auto* ctx = reinterpret_cast<const OcclusionContext*>(args->context);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const unsigned id = RTCRayN_id(args->ray, args->N, i);
        const OcclusionQuery& q = ctx->queries[id];
        RayState& st = ctx->states[id];
        const uint32_t prim = RTCHitN_primID(args->hit, args->N, i);
        const glm::uvec3 tri = ctx->triangles[prim];
        args->valid[i] = 0;  // rejected unless it completes the count
        if (contains_point(*ctx, q.on, prim, tri)) continue;
        if (q.fold_band > 0.0f && st.fold.contains(*ctx, q, prim)) continue;
        const float t = RTCRayN_tfar(args->ray, args->N, i);
        if (st.counted(ctx->triangles, prim, tri, t)) continue;
        const float in_front = (st.t_point - t) * st.t_scale;
        // A contour's own faces by their slope (the largest allowance first: most hits are far
        // beyond it; none for other samples).
        if (q.slope_depth > 0.0f && in_front <= q.slope_depth * kMaxOwnSlope &&
            in_front < slope_allowance(*ctx, q, args, i, prim, tri))
            continue;
        // Near enough to be the point's own surface: judged when the trace is done.
        if (in_front <= q.own_depth && st.deferred < kDeferredHits) {
            st.deferred_t[st.deferred] = t, st.deferred_prim[st.deferred] = prim, ++st.deferred;
            continue;
        }
        st.record(prim, t);
        if (st.level >= ctx->cap) args->valid[i] = -1;  // enough: the ray stops here
    }
}

namespace {

// The held hits of a traced ray that are not on the point's own neighbourhood, counted
// (OcclusionQuery::own_depth; a held hit is within own_depth ≤ own_radius of the point, so on
// a face within the radius).
void count_deferred(RTCScene scene, const OcclusionContext& ctx, const OcclusionQuery& q, RayState& st) {
    if (st.deferred == 0 || st.level >= ctx.cap) return;
    const glm::vec3* positions = ctx.mesh->positions.data();
    // Most such hits are on a face next to the point's own, across a vertex or an edge near it:
    // that face is in the neighbourhood (joined within the radius) without the point query.
    uint8_t open[kDeferredHits], left = 0;
    for (uint8_t k = 0; k < st.deferred; ++k) {
        bool own = false;
        for (uint32_t f : {q.on.face, q.on.face_b})
            own = own ||
                  (f != kNoFace && joined(ctx.triangles, positions, st.deferred_prim[k], f, q.point, q.own_radius));
        if (!own) open[left++] = k;
    }
    if (left == 0) return;
    const std::vector<uint32_t> own =
        own_neighbourhood(scene, ctx.triangles, positions, q.point, q.own_radius,
                          [&](uint32_t f) { return contains_point(ctx, q.on, f, ctx.triangles[f]); });
    for (uint8_t i = 0; i < left && st.level < ctx.cap; ++i) {
        const uint8_t k = open[i];
        const uint32_t prim = st.deferred_prim[k];
        if (std::binary_search(own.begin(), own.end(), prim)) continue;
        if (st.counted(ctx.triangles, prim, ctx.triangles[prim], st.deferred_t[k])) continue;
        st.record(prim, st.deferred_t[k]);
    }
}

}  // namespace

bool RayScene::occluded(const ImageProjection& view, const glm::vec3& p, const PointOn& on) const {
    OcclusionQuery query;
    query.point = p;
    query.on = on;
    uint8_t level = 0;
    occlusion_levels(view, &query, 1, &level, 1);
    return level != 0;
}

void RayScene::occlusion_levels(const ImageProjection& view, const OcclusionQuery* queries, size_t count,
                                uint8_t* levels, int cap, const EdgeNeighbours* around) const {
    cap = std::clamp(cap, 1, 255);
    const Camera& cam = view.camera();
    const double near = double(cam.near_plane);
    const glm::dvec3 eye(cam.eye);
    const glm::dvec3 forward = glm::normalize(glm::dvec3(cam.target) - eye);
    // One query (the bisection's many single samples) needs no allocation.
    RTCRay one_ray;
    RayState one_state;
    std::vector<RTCRay> many_rays(count > 1 ? count : 0);
    std::vector<RayState> many_states(count > 1 ? count : 0);
    RTCRay* rays = count > 1 ? many_rays.data() : &one_ray;
    RayState* states = count > 1 ? many_states.data() : &one_state;
    for (size_t i = 0; i < count; ++i) {
        const OcclusionQuery& q = queries[i];
        const double z = view.view_depth(q.point);
        glm::dvec3 org, dir;
        double tnear = 0.0, tfar = 0.0, same_point = 0.0;
        if (cam.orthographic) {
            // From the near plane along the view direction, unit speed: t is a distance.
            const double s = z - near;
            org = glm::dvec3(q.point) - s * forward;
            dir = forward;
            tfar = s - tolerance_;
            same_point = 1e-6 * std::abs(s);
        } else {
            // From the eye, t = 1 at p; starts where the ray crosses the near plane.
            org = eye;
            dir = glm::dvec3(q.point) - org;
            const double len = glm::length(dir);
            tnear = z > 0.0 ? near / z : 1.0;
            tfar = len > 0.0 ? 1.0 - tolerance_ / len : 0.0;
            same_point = 1e-6;
        }
        states[i].same_point = float(same_point);
        states[i].t_point = float(cam.orthographic ? z - near : 1.0);
        states[i].t_scale = float(cam.orthographic ? 1.0 : glm::length(glm::dvec3(q.point) - eye));
        RTCRay& ray = rays[i];
        ray.org_x = float(org.x), ray.org_y = float(org.y), ray.org_z = float(org.z);
        ray.dir_x = float(dir.x), ray.dir_y = float(dir.y), ray.dir_z = float(dir.z);
        ray.time = 0.0f;
        ray.mask = 0xffffffffu;
        ray.id = unsigned(i);
        ray.flags = 0;
        // Nothing between the start and p: an inactive ray (tnear > tfar), reported visible.
        const bool active = tfar > tnear && std::isfinite(tfar) && std::isfinite(tnear);
        ray.tnear = active ? float(tnear) : 1.0f;
        ray.tfar = active ? float(tfar) : 0.0f;
    }
    OcclusionContext ctx;
    rtcInitIntersectContext(&ctx.rtc);
    // One ray at a time through the stream (Embree's incoherent mode), not as packets: these
    // rays graze surfaces near their ends and stop the filter at many hits, so a packet's lanes
    // part early; single rays took 0.83 × the time of packets on the noisy knot's suggestive
    // contours and 0.91 × on its contours, with identical results (docs/benchmarks.md,
    // "A 40 ms view"); packets of samples in image order gained nothing either.
    ctx.rtc.flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    ctx.mesh = impl_->mesh;
    ctx.triangles = impl_->triangles;
    ctx.around = around;
    ctx.queries = queries;
    ctx.states = states;
    ctx.cap = cap;
    ctx.eye = eye;
    ctx.forward = forward;
    ctx.orthographic = cam.orthographic;
    if (count == 1)
        rtcOccluded1(impl_->scene, &ctx.rtc, rays);
    else if (count > 1)
        rtcOccluded1M(impl_->scene, &ctx.rtc, rays, unsigned(count), sizeof(RTCRay));
    for (size_t i = 0; i < count; ++i) {
        count_deferred(impl_->scene, ctx, queries[i], states[i]);
        levels[i] = states[i].level;
    }
}

}  // namespace inkshade::geometry
