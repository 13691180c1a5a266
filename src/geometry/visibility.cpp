#include "geometry/visibility.hpp"

#include <embree3/rtcore.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <numeric>
#include <tuple>
#include <string>

#include "geometry/chaining.hpp"
#include "geometry/face_segments.hpp"
#include "inkshade/error.hpp"
#include "inkshade/lines.hpp"

namespace inkshade::geometry {

// ---- ImageProjection ---------------------------------------------------------------------

ImageProjection::ImageProjection(const Camera& camera, int width, int height)
    : camera_(camera), width_(width), height_(height) {
    // The same float matrices the renderer uploads, then evaluated in double.
    const float aspect = float(width) / float(height);
    clip_from_world_ = glm::dmat4(camera.projection(aspect)) * glm::dmat4(camera.view());
    eye_ = glm::dvec3(camera.eye);
    const glm::dvec3 f = glm::dvec3(camera.target) - eye_;
    const double len = glm::length(f);
    forward_ = len > 0.0 ? f / len : glm::dvec3(0, 0, -1);
}

glm::dvec3 ImageProjection::project(const glm::vec3& p) const {
    const glm::dvec4 clip = clip_from_world_ * glm::dvec4(glm::dvec3(p), 1.0);
    const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
    // glViewport mapping, then y flipped: image row j = height − 1 − GL row.
    return {(ndc.x + 1.0) * 0.5 * width_, (1.0 - ndc.y) * 0.5 * height_, (ndc.z + 1.0) * 0.5};
}

double ImageProjection::view_depth(const glm::vec3& p) const { return glm::dot(glm::dvec3(p) - eye_, forward_); }

bool ImageProjection::clipped(const glm::vec3& p) const {
    const double z = view_depth(p);
    return !(z >= double(camera_.near_plane) && z <= double(camera_.far_plane));
}

// ---- RayScene ----------------------------------------------------------------------------

namespace {

bool has_vertex(const glm::uvec3& t, uint32_t v) { return t.x == v || t.y == v || t.z == v; }

// Does triangle t index only vertices below nv? (Other triangles are never hit nor walked.)
bool in_range(const glm::uvec3& t, size_t nv) { return t.x < nv && t.y < nv && t.z < nv; }

int shared_vertices(const glm::uvec3& t, const glm::uvec3& u) {
    return int(has_vertex(t, u.x)) + int(has_vertex(t, u.y)) + int(has_vertex(t, u.z));
}

// Hits recorded per ray for counting each crossing once (levels past this are rare and are
// counted without that check).
constexpr int kRecordedHits = 16;

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
};

// Counts each crossing once and lets the ray go on until the cap is reached.
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
        bool seen = false;
        for (int k = 0; k < st.recorded && !seen; ++k)
            seen = st.prim[k] == prim ||
                   (std::abs(st.t[k] - t) <= st.same_point && shared_vertices(tri, ctx->triangles[st.prim[k]]) > 0);
        if (seen) continue;
        if (st.recorded < kRecordedHits) st.t[st.recorded] = t, st.prim[st.recorded] = prim, ++st.recorded;
        if (++st.level >= ctx->cap) args->valid[i] = -1;  // enough: the ray stops here
    }
}

std::string device_error_text(RTCDevice device) {
    switch (rtcGetDeviceError(device)) {
        case RTC_ERROR_NONE: return "no error";
        case RTC_ERROR_OUT_OF_MEMORY: return "out of memory";
        case RTC_ERROR_INVALID_ARGUMENT: return "invalid argument";
        case RTC_ERROR_UNSUPPORTED_CPU: return "unsupported CPU";
        default: return "error " + std::to_string(int(rtcGetDeviceError(device)));
    }
}

}  // namespace

struct RayScene::Impl {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    const Mesh* mesh = nullptr;
    std::vector<glm::uvec3> own_triangles;  // used when the mesh has out-of-range indices
    const glm::uvec3* triangles = nullptr;

    ~Impl() {
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }
};

RayScene::RayScene(const Mesh& mesh) : impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
    tolerance_ = 1e-5 * std::max(double(mesh.bounds().diagonal()), 1e-30);
    // AVX2 at most: Debian's Embree 3.13.5 loops forever inside rtcOccluded1M on its AVX-512
    // kernels (seen on an AVX-512 Xeon with the line-drawing tests; the same rays finish at once
    // with max_isa=avx2 or sse4.2). CPUs without AVX2 still get their best ISA.
    m.device = rtcNewDevice("max_isa=avx2");
    if (!m.device) throw RuntimeError("ray casting: cannot create an Embree device");
    m.scene = rtcNewScene(m.device);
    // Robust mode: watertight edge tests, so a ray through a shared edge of an occluder
    // cannot slip between its two triangles and show a hidden line through the surface.
    rtcSetSceneFlags(m.scene, RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_COMPACT);

    const size_t nv = mesh.positions.size(), nf = mesh.triangles.size();
    m.mesh = &mesh;
    m.triangles = mesh.triangles.data();
    if (std::any_of(mesh.triangles.begin(), mesh.triangles.end(),
                    [&](const glm::uvec3& t) { return !in_range(t, nv); })) {
        // Embree skips such triangles too, but a hit must never index out of range here.
        m.own_triangles = mesh.triangles;
        for (auto& t : m.own_triangles)
            if (!in_range(t, nv)) t = glm::uvec3(0);  // never hit
        m.triangles = m.own_triangles.data();
    }
    if (nv > 0 && nf > 0) {
        RTCGeometry geom = rtcNewGeometry(m.device, RTC_GEOMETRY_TYPE_TRIANGLE);
        // Embree reads the last vertex with a 16-byte load: the mesh's own array serves when
        // its capacity covers those 4 bytes (60 MB saved at 10 M triangles), else a copy.
        if (mesh.positions.capacity() > nv) {
            rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, mesh.positions.data(), 0,
                                       sizeof(glm::vec3), nv);
        } else {
            auto* v = static_cast<float*>(
                rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), nv));
            if (v) std::copy_n(&mesh.positions[0].x, 3 * nv, v);
        }
        // Indices are shared (12-byte stride, no padding needed).
        rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, m.triangles, 0, sizeof(glm::uvec3),
                                   nf);
        rtcSetGeometryOccludedFilterFunction(geom, count_crossings);
        rtcCommitGeometry(geom);
        rtcAttachGeometry(m.scene, geom);
        rtcReleaseGeometry(geom);
    }
    rtcCommitScene(m.scene);
    if (rtcGetDeviceError(m.device) != RTC_ERROR_NONE)
        throw RuntimeError("ray casting: Embree failed to build the scene (" + device_error_text(m.device) + ")");
}

RayScene::~RayScene() = default;

void reserve_embree_padding(std::vector<glm::vec3>& positions) {
    if (positions.capacity() == positions.size()) positions.reserve(positions.size() + 1);
    positions.emplace_back(0.0f);  // the 4 bytes read past the end are then initialised
    positions.pop_back();
}

// ---- EdgeNeighbours ----------------------------------------------------------------------

namespace {

// Slot of an edge key in a table of `capacity` slots: a Fibonacci hash (neighbouring edges
// have neighbouring keys) scaled to the capacity by a multiply-high (any capacity, no modulo).
size_t slot_of(uint64_t key, size_t capacity) {
    const uint64_t hash = key * 0x9e3779b97f4a7c15ull;
    return size_t((static_cast<unsigned __int128>(hash ^ (hash >> 29)) * capacity) >> 64);
}

size_t next_slot(size_t h, size_t capacity) { return h + 1 == capacity ? 0 : h + 1; }

}  // namespace

EdgeNeighbours::EdgeNeighbours(const Mesh& mesh, const std::vector<uint32_t>& vertices) {
    const size_t nv = mesh.positions.size(), nf = mesh.triangles.size();
    if (vertices.empty()) return;
    std::vector<uint64_t> chosen((nv + 63) / 64, 0);  // a bitmap stays in cache during the scans
    for (uint32_t v : vertices)
        if (v < nv) chosen[v / 64] |= uint64_t(1) << (v % 64);
    auto near = [&](const glm::uvec3& t) {
        if (!in_range(t, nv)) return false;
        bool hit = false;
        for (uint32_t v : {t.x, t.y, t.z}) hit |= ((chosen[v / 64] >> (v % 64)) & 1) != 0;
        return hit;
    };
    // One parallel scan gathers the faces around the chosen vertices (fixed blocks, joined in
    // order); their edges (at most three a face: the table is at most three quarters full) then
    // go in with compare-and-swap. Which slot an edge lands in depends on the threads; what a
    // lookup finds does not.
    const std::vector<uint32_t> faces = collect_per_face<uint32_t>(nf, [&](size_t f, std::vector<uint32_t>& out) {
        if (near(mesh.triangles[f])) out.push_back(uint32_t(f));
    });
    capacity_ = 4 * faces.size() + 16;
    slots_ = std::make_unique<Slot[]>(capacity_);
    std::atomic<size_t> distinct{0};
    tbb::parallel_for(tbb::blocked_range<size_t>(0, faces.size(), 4096), [&](const tbb::blocked_range<size_t>& r) {
        size_t added = 0;
        for (size_t i = r.begin(); i != r.end(); ++i) {
            const uint32_t f = faces[i];
            const glm::uvec3 t = mesh.triangles[f];
            for (int k = 0; k < 3; ++k) {
                if (t[k] == t[(k + 1) % 3]) continue;
                const uint64_t key = edge_key(t[k], t[(k + 1) % 3]);
                for (size_t h = slot_of(key, capacity_);; h = next_slot(h, capacity_)) {
                    Slot& slot = slots_[h];
                    uint64_t key_found = slot.key.load(std::memory_order_acquire);
                    if (key_found == kEmpty && slot.key.compare_exchange_strong(key_found, key)) key_found = key, ++added;
                    if (key_found != key) continue;
                    // Its faces: the first two, then "many" (a non-manifold edge).
                    uint32_t face = kNoFace;
                    if (slot.face[0].compare_exchange_strong(face, f) || face == f) break;
                    face = kNoFace;
                    if (slot.face[1].compare_exchange_strong(face, f) || face == f) break;
                    slot.face[1].store(kMany);
                    break;
                }
            }
        }
        distinct += added;
    });
    size_ = distinct.load();
}

uint32_t EdgeNeighbours::across(uint32_t face, uint32_t a, uint32_t b) const {
    if (a == b || !slots_) return kNoFace;
    const uint64_t key = edge_key(a, b);
    for (size_t h = slot_of(key, capacity_);; h = next_slot(h, capacity_)) {
        const Slot& slot = slots_[h];
        const uint64_t found = slot.key.load(std::memory_order_relaxed);
        if (found == kEmpty) return kNoFace;
        if (found != key) continue;
        const uint32_t f0 = slot.face[0].load(std::memory_order_relaxed), f1 = slot.face[1].load(std::memory_order_relaxed);
        if (f1 == kNoFace || f1 == kMany) return kNoFace;  // a border, or non-manifold
        return f0 == face ? f1 : f1 == face ? f0 : kNoFace;
    }
}

// ---- RayScene queries ----------------------------------------------------------------------

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
    // Samples come in mesh order (sorted by node key): neighbouring rays are nearly parallel,
    // so Embree traces them as packets (about 15 % less time than one rtcOccluded1 each).
    ctx.rtc.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
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
    for (size_t i = 0; i < count; ++i) levels[i] = states[i].level;
}

// ---- split_by_visibility -----------------------------------------------------------------

namespace {

constexpr uint8_t kClipped = 0xff;  // a sample outside the near/far range (not a level)

bool is_vertex_key(uint64_t key) { return uint32_t(key >> 32) == uint32_t(key); }
bool is_edge_key(uint64_t key) { return uint32_t(key >> 32) < uint32_t(key); }
bool is_pierce_key(uint64_t key) { return uint32_t(key >> 32) == 0xfffffffcu; }

// A segment along a mesh edge (crease, border, silhouette edge): vertex keys at both ends.
bool along_edge(const LineSegment& s) { return is_vertex_key(s.edge_a) && is_vertex_key(s.edge_b); }

// A face that exists and indexes only existing vertices (and shading normals, with hard edges).
bool valid_face(const Mesh& mesh, uint32_t f) {
    if (f >= mesh.triangles.size() || !in_range(mesh.triangles[f], mesh.positions.size())) return false;
    return !mesh.has_hard_edges() || in_range(mesh.shading_normal_ids[f], mesh.shading_normals.size());
}

// What the points strictly inside a segment lie on.
PointOn interior_on(const Mesh& mesh, const LineSegment& s) {
    PointOn on;
    if (valid_face(mesh, s.face)) on.face = s.face;
    if (valid_face(mesh, s.face_b)) on.face_b = s.face_b;
    if (s.face_b == kNoFace && along_edge(s)) {
        on.kind = PointOn::Edge;
        on.u = uint32_t(s.edge_a), on.v = uint32_t(s.edge_b);
    }
    return on;
}

// What a segment end with node key `key` lies on (key kinds: contours.hpp).
PointOn end_on(const Mesh& mesh, const LineSegment& s, uint64_t key) {
    PointOn on = interior_on(mesh, s);
    if (is_vertex_key(key)) {
        on.kind = PointOn::Vertex;
        on.u = uint32_t(key), on.v = kNoFace;
    } else if (is_edge_key(key)) {
        uint32_t a = uint32_t(key >> 32), b = uint32_t(key);
        if (on.face != kNoFace && on.face_b == kNoFace) {
            // An isoline's end on an edge of its face: the key names the edge by vertices, or on
            // a mesh with hard edges by the corners' shading normals (hard_edge_contours.hpp).
            const glm::uvec3 t = mesh.triangles[on.face];
            if (!(has_vertex(t, a) && has_vertex(t, b)) && mesh.has_hard_edges()) {
                const glm::uvec3 n = mesh.shading_normal_ids[on.face];
                uint32_t found[2], k_found = 0;
                for (int k = 0; k < 3; ++k)
                    if ((n[k] == a || n[k] == b) && k_found < 2) found[k_found++] = t[k];
                if (k_found == 2) a = found[0], b = found[1];
            }
            if (has_vertex(t, a) && has_vertex(t, b) && a != b) on.kind = PointOn::Edge, on.u = a, on.v = b;
        } else if (on.face == kNoFace && a < mesh.positions.size() && b < mesh.positions.size()) {
            on.kind = PointOn::Edge, on.u = a, on.v = b;
        }
        // A hard edge's piece (face and face_b: the edge's two faces) keeps its two faces.
    } else if (is_pierce_key(key)) {
        on.kind = PointOn::FaceNeighbours;
    }
    return on;
}

// The interpolated unit normal at p in face f (vertex normals, or the corners' shading normals
// on a mesh with hard edges, as the contour itself takes them); zero when undefined.
glm::vec3 interpolated_normal(const Mesh& mesh, uint32_t f, const glm::vec3& point) {
    const glm::uvec3 t = mesh.triangles[f];
    glm::dvec3 n[3];
    for (int k = 0; k < 3; ++k)
        n[k] = glm::dvec3(mesh.has_hard_edges() ? mesh.shading_normals[mesh.shading_normal_ids[f][k]]
                                                : mesh.normals[t[k]]);
    const glm::dvec3 P0(mesh.positions[t.x]), e1 = glm::dvec3(mesh.positions[t.y]) - P0,
        e2 = glm::dvec3(mesh.positions[t.z]) - P0;
    // Barycentric coordinates from the Gram matrix of (e1, e2).
    const double g11 = glm::dot(e1, e1), g12 = glm::dot(e1, e2), g22 = glm::dot(e2, e2);
    const double det = g11 * g22 - g12 * g12;
    if (!(std::abs(det) > 0.0)) return glm::vec3(0.0f);
    const glm::dvec3 x = glm::dvec3(point) - P0;
    const double r1 = glm::dot(x, e1), r2 = glm::dot(x, e2);
    const double b1 = (g22 * r1 - g12 * r2) / det, b2 = (g11 * r2 - g12 * r1) / det;
    const glm::dvec3 ni = (1.0 - b1 - b2) * n[0] + b1 * n[1] + b2 * n[2];
    const double len = glm::length(ni);
    return len > 0.0 ? glm::vec3(ni / len) : glm::vec3(0.0f);
}

// World size of a pixel at p's depth.
double pixel_size_at(const ImageProjection& view, const glm::vec3& p) {
    const Camera& cam = view.camera();
    if (cam.orthographic) return double(cam.ortho_height) / view.height();
    return view.view_depth(p) * 2.0 * std::tan(0.5 * glm::radians(double(cam.fov_degrees))) / view.height();
}

OcclusionQuery query_at(const Mesh& mesh, const ImageProjection& view, const glm::vec3& p, const PointOn& on,
                        float fold_px) {
    OcclusionQuery q;
    q.point = p;
    q.on = on;
    if (fold_px > 0.0f && on.face != kNoFace && on.face_b == kNoFace && on.kind != PointOn::Vertex) {
        q.normal = interpolated_normal(mesh, on.face, p);
        if (q.normal != glm::vec3(0.0f)) q.fold_band = float(fold_px * pixel_size_at(view, p));
    }
    return q;
}

struct Piece {
    double t0, t1;
    uint8_t level;
};

glm::vec3 lerp(const LineSegment& s, double t) {
    return glm::vec3(glm::dvec3(s.a) + t * (glm::dvec3(s.b) - glm::dvec3(s.a)));
}

double pixel_distance(const ImageProjection& view, const glm::vec3& a, const glm::vec3& b) {
    const glm::dvec3 pa = view.project(a), pb = view.project(b);
    return std::hypot(pa.x - pb.x, pa.y - pb.y);
}

// Key of a split point: high word 0xfffffffd, low word a counter below it — no edge key
// (high < low), vertex key (high == low), face_interior_key (high ≥ 0xfffffffe) or pierce key
// (0xfffffffc) has it.
constexpr uint64_t split_key(uint32_t counter) { return (uint64_t(0xfffffffdu) << 32) | counter; }

// A point to test and what it lies on.
struct Sample {
    glm::vec3 point;
    PointOn on;
};

struct Tester {
    const RayScene& scene;
    const Mesh& mesh;
    const ImageProjection& view;
    const EdgeNeighbours* around;
    int cap;
    float fold_px;  // contour samples: the fold band in pixels, else 0

    // The levels of many samples (kClipped outside the near/far range) as ray streams
    // (rtcOccluded1M), in fixed blocks on TBB tasks: the same blocks, so the same ray packets,
    // whatever the thread count. Coherent rays (a chain's nodes) trace faster as packets; the
    // bisection's scattered rounds gain nothing, but go through here for the fixed blocks.
    void levels(const std::vector<Sample>& samples, std::vector<uint8_t>& out) const {
        constexpr size_t kBlock = 64;
        out.resize(samples.size());
        tbb::parallel_for(size_t(0), (samples.size() + kBlock - 1) / kBlock, [&](size_t block) {
            OcclusionQuery queries[kBlock];
            uint8_t found[kBlock];
            size_t where[kBlock];
            size_t m = 0;
            const size_t end = std::min(samples.size(), (block + 1) * kBlock);
            for (size_t i = block * kBlock; i < end; ++i) {
                if (view.clipped(samples[i].point)) {
                    out[i] = kClipped;
                    continue;
                }
                queries[m] = query_at(mesh, view, samples[i].point, samples[i].on, fold_px);
                where[m++] = i;
            }
            scene.occlusion_levels(view, queries, m, found, cap, around);
            for (size_t k = 0; k < m; ++k) out[where[k]] = found[k];
        });
    }
};

// A segment whose ends differ in level, or longer than the sample spacing: sampled inside at
// `steps` equal parts, each change of level then bisected.
struct SegmentTask {
    uint32_t segment;
    uint8_t level_a, level_b;
    uint32_t steps;
    size_t first;  // its steps − 1 interior samples' index in the task list's sample array
};

// Samples parts of a segment when it is longer than `spacing` in the image (1 part when an end
// is clipped or the camera degenerate).
uint32_t segment_steps(const ImageProjection& view, const LineSegment& s, double spacing) {
    if (view.clipped(s.a) || view.clipped(s.b)) return 1;
    const double px = pixel_distance(view, s.a, s.b);
    // NaN (a degenerate camera) keeps one step instead of an undefined conversion.
    return std::isfinite(px) ? uint32_t(std::clamp(std::ceil(px / spacing), 1.0, 16384.0)) : 1;
}

// A change of level inside a task's segment, between parameters lo (level `level_lo`) and hi.
struct Bracket {
    uint32_t task;
    double lo, hi;
    uint8_t level_lo;
};

// Each task's pieces (into `pieces`, or `whole` when its samples agree): interior samples in
// one stream, then every change bisected in rounds of one stream each until its bracket is
// `precision` pixels long.
void resolve_segments(const Tester& tester, const std::vector<LineSegment>& segments,
                      const std::vector<SegmentTask>& tasks, double precision, std::vector<uint8_t>& whole,
                      std::vector<std::vector<Piece>>& pieces) {
    const ImageProjection& view = tester.view;
    const size_t interior = tasks.empty() ? 0 : tasks.back().first + tasks.back().steps - 1;
    std::vector<Sample> samples(interior);
    tbb::parallel_for(size_t(0), tasks.size(), [&](size_t i) {
        const SegmentTask& t = tasks[i];
        const LineSegment& s = segments[t.segment];
        const PointOn inside = interior_on(tester.mesh, s);
        for (uint32_t k = 1; k < t.steps; ++k) samples[t.first + k - 1] = {lerp(s, double(k) / t.steps), inside};
    });
    std::vector<uint8_t> levels;
    tester.levels(samples, levels);
    auto level_at = [&](const SegmentTask& t, uint32_t k) {
        return k == 0 ? t.level_a : k == t.steps ? t.level_b : levels[t.first + k - 1];
    };

    std::vector<Bracket> brackets;
    for (uint32_t i = 0; i < tasks.size(); ++i) {
        const SegmentTask& t = tasks[i];
        for (uint32_t k = 0; k < t.steps; ++k)
            if (level_at(t, k) != level_at(t, k + 1))
                brackets.push_back({i, double(k) / t.steps, double(k + 1) / t.steps, level_at(t, k)});
    }
    std::vector<uint32_t> active(brackets.size());
    for (uint32_t b = 0; b < active.size(); ++b) active[b] = b;
    std::vector<char> done;
    std::vector<uint8_t> found;
    for (int iter = 0; iter < 60 && !active.empty(); ++iter) {
        samples.resize(active.size());
        done.assign(active.size(), 0);
        tbb::parallel_for(size_t(0), active.size(), [&](size_t i) {
            const Bracket& b = brackets[active[i]];
            const LineSegment& s = segments[tasks[b.task].segment];
            const glm::vec3 plo = lerp(s, b.lo), phi = lerp(s, b.hi);
            const bool measurable = !view.clipped(plo) && !view.clipped(phi);
            done[i] = measurable ? pixel_distance(view, plo, phi) <= precision : b.hi - b.lo < 1e-7;
            samples[i] = {lerp(s, 0.5 * (b.lo + b.hi)), interior_on(tester.mesh, s)};
        });
        size_t kept = 0;
        for (size_t i = 0; i < active.size(); ++i)
            if (!done[i]) samples[kept] = samples[i], active[kept++] = active[i];
        samples.resize(kept);
        active.resize(kept);
        tester.levels(samples, found);
        for (size_t i = 0; i < kept; ++i) {
            Bracket& b = brackets[active[i]];
            (found[i] == b.level_lo ? b.lo : b.hi) = 0.5 * (b.lo + b.hi);
        }
    }

    // Runs of equal level, split at the middle of each change's bracket.
    size_t next = 0;
    for (uint32_t i = 0; i < tasks.size(); ++i) {
        const SegmentTask& t = tasks[i];
        if (next == brackets.size() || brackets[next].task != i) {
            whole[t.segment] = t.level_a;  // every sample agrees
            continue;
        }
        std::vector<Piece>& out = pieces[t.segment];
        double start = 0.0;
        for (; next < brackets.size() && brackets[next].task == i; ++next) {
            const Bracket& b = brackets[next];
            const double at = 0.5 * (b.lo + b.hi);
            out.push_back({start, at, b.level_lo});
            start = at;
        }
        out.push_back({start, 1.0, t.level_b});
    }
}

// One node of a chain (chaining.hpp): node i is where segment i starts in walking order, node
// k (k segments) where the last one ends. Its point and what it lies on come from the segment
// end there.
struct ChainNode {
    const LineSegment* segment;
    bool at_b;  // the node is the segment's b end
};

ChainNode chain_node(const std::vector<LineSegment>& segments, const Chain& chain, size_t i) {
    const size_t k = chain.segments.size();
    if (i < k) return {&segments[chain.segments[i]], chain.reversed[i] != 0};
    return {&segments[chain.segments[k - 1]], chain.reversed[k - 1] == 0};
}

glm::vec3 node_point(const ChainNode& n) { return n.at_b ? n.segment->b : n.segment->a; }

PointOn node_on(const Mesh& mesh, const ChainNode& n) {
    return end_on(mesh, *n.segment, n.at_b ? n.segment->edge_b : n.segment->edge_a);
}

Sample node_sample(const Mesh& mesh, const ChainNode& n) { return {node_point(n), node_on(mesh, n)}; }

}  // namespace

EdgeNeighbours contour_surroundings(const Mesh& mesh, const std::vector<const std::vector<LineSegment>*>& contours) {
    std::vector<uint32_t> vertices;
    for (const std::vector<LineSegment>* list : contours)
        for (const LineSegment& s : *list)
            for (uint32_t f : {s.face, s.face_b})
                if (valid_face(mesh, f))
                    for (int k = 0; k < 3; ++k) vertices.push_back(mesh.triangles[f][k]);
    return EdgeNeighbours(mesh, vertices);
}

VisibilitySplit split_by_visibility(const RayScene& scene, const Mesh& mesh, const ImageProjection& view,
                                    const std::vector<LineSegment>& segments, const VisibilityOptions& options,
                                    const EdgeNeighbours* around) {
    const size_t n = segments.size();
    const double spacing = std::max(double(options.sample_spacing_px), 1e-3);
    const double precision = std::max(double(options.transition_precision_px), 1e-4);
    EdgeNeighbours own;
    if (!around && options.contour) {
        own = contour_surroundings(mesh, {&segments});
        around = &own;
    }
    const Tester tester{scene, mesh, view, around, std::clamp(options.count_levels_to, 1, kMaxOcclusionLevel),
                        options.contour ? std::max(options.contour_fold_px, 0.0f) : 0.0f};
    constexpr uint8_t kSplit = 0xfe;  // not a level (levels ≤ kMaxOcclusionLevel) nor kClipped
    static_assert(kMaxOcclusionLevel < kSplit && kSplit < kClipped);
    std::vector<uint8_t> whole(n, kSplit);      // level of an unsplit segment, else kSplit
    std::vector<std::vector<Piece>> pieces(n);  // pieces of split segments only

    // Samples go along chains, not segments: on a fine mesh a segment is a fraction of a pixel,
    // and testing each node would cost several rays a pixel. A chain is sampled at nodes no
    // more than `spacing` apart in the image (and inside segments longer than that); between
    // two samples of one level the segments take it, between two of different levels the
    // nodes in between are searched for the change, then the segment with it is bisected.
    std::vector<Chain> chains = chain_order(segments);
    {
        std::vector<char> chained(n, 0);
        for (const Chain& c : chains)
            for (uint32_t s : c.segments) chained[s] = 1;
        for (uint32_t s = 0; s < n; ++s)  // left out of chains (both ends one key): alone
            if (!chained[s]) chains.push_back({{s}, {0}, false});
    }
    // The sampled nodes of every chain, chosen in parallel.
    std::vector<std::vector<uint32_t>> sampled(chains.size());
    tbb::parallel_for(size_t(0), chains.size(), [&](size_t c) {
        const Chain& chain = chains[c];
        const size_t k = chain.segments.size();
        // Image length of each segment; infinite where an end is clipped (or the camera is
        // degenerate), which makes both its nodes samples.
        std::vector<double> step(k, std::numeric_limits<double>::infinity());
        const glm::vec3 p0 = node_point(chain_node(segments, chain, 0));
        bool prev_ok = !view.clipped(p0);
        glm::dvec3 prev = prev_ok ? view.project(p0) : glm::dvec3(0.0);
        for (size_t i = 0; i < k; ++i) {
            const glm::vec3 p = node_point(chain_node(segments, chain, i + 1));
            const bool ok = !view.clipped(p);
            const glm::dvec3 q = ok ? view.project(p) : glm::dvec3(0.0);
            const double d = std::hypot(q.x - prev.x, q.y - prev.y);
            if (ok && prev_ok && std::isfinite(d)) step[i] = d;
            prev = q, prev_ok = ok;
        }
        // A whole chain shorter than the caller keeps: every part of it would be shorter too.
        if (chain.component && options.min_length_px > 0.0f &&
            std::accumulate(step.begin(), step.end(), 0.0) + 1e-3 < double(options.min_length_px))
            return;  // no samples: its segments are left out of the result
        // Greedy: from each sample, the farthest node within `spacing`, or the next node.
        std::vector<uint32_t>& out = sampled[c];
        out.push_back(0);
        for (size_t i = 0; i < k;) {
            size_t j = i + 1;
            double length = step[i];
            while (j < k && length + step[j] <= spacing) length += step[j++];
            out.push_back(uint32_t(j));
            i = j;
        }
    });
    // The levels of chosen nodes of every chain (`nodes[c]`), in one stream: chain c's are at
    // first[c] onwards in `levels`.
    auto node_levels_of = [&](const std::vector<std::vector<uint32_t>>& nodes, std::vector<size_t>& first,
                              std::vector<uint8_t>& levels) {
        first.assign(chains.size() + 1, 0);
        for (size_t c = 0; c < chains.size(); ++c) first[c + 1] = first[c] + nodes[c].size();
        std::vector<Sample> samples(first.back());
        tbb::parallel_for(size_t(0), chains.size(), [&](size_t c) {
            for (size_t k = 0; k < nodes[c].size(); ++k)
                samples[first[c] + k] = node_sample(mesh, chain_node(segments, chains[c], nodes[c][k]));
        });
        tester.levels(samples, levels);
    };
    std::vector<size_t> first;
    std::vector<uint8_t> node_levels;
    node_levels_of(sampled, first, node_levels);

    // Between two samples of one level, every segment takes it. Between samples of different
    // levels, every node in between is tested as well (one stream for all), then each segment
    // whose ends differ, or that is longer than `spacing`, is resolved (resolve_segments).
    std::vector<std::vector<uint32_t>> inner(chains.size());  // nodes inside changing gaps
    tbb::parallel_for(size_t(0), chains.size(), [&](size_t c) {
        const std::vector<uint32_t>& nodes = sampled[c];
        for (size_t m = 0; m + 1 < nodes.size(); ++m)
            if (node_levels[first[c] + m] != node_levels[first[c] + m + 1])
                for (uint32_t i = nodes[m] + 1; i < nodes[m + 1]; ++i) inner[c].push_back(i);
    });
    std::vector<size_t> inner_first;
    std::vector<uint8_t> inner_levels;
    node_levels_of(inner, inner_first, inner_levels);

    std::vector<std::vector<SegmentTask>> chain_tasks(chains.size());
    tbb::parallel_for(size_t(0), chains.size(), [&](size_t c) {
        const Chain& chain = chains[c];
        const std::vector<uint32_t>& nodes = sampled[c];
        const uint8_t* inner_level = inner_levels.data() + inner_first[c];
        // Levels at a segment's start and end in walking order, to its a and b ends.
        auto set_segment = [&](size_t i, uint8_t level_start, uint8_t level_end) {
            const uint32_t s = chain.segments[i];
            const bool rev = chain.reversed[i] != 0;
            const uint8_t la = rev ? level_end : level_start, lb = rev ? level_start : level_end;
            const uint32_t steps = segment_steps(view, segments[s], spacing);
            if (la == lb && steps == 1)
                whole[s] = la;
            else
                chain_tasks[c].push_back({s, la, lb, steps, 0});
        };
        for (size_t m = 0; m + 1 < nodes.size(); ++m) {
            const size_t lo = nodes[m], end = nodes[m + 1];
            const uint8_t level_lo = node_levels[first[c] + m], level_end = node_levels[first[c] + m + 1];
            if (level_lo == level_end && end - lo > 1) {
                for (size_t i = lo; i < end; ++i) whole[chain.segments[i]] = level_lo;
                continue;
            }
            uint8_t level = level_lo;
            for (size_t i = lo; i < end; ++i) {
                const uint8_t next = i + 1 == end ? level_end : *inner_level++;
                set_segment(i, level, next);
                level = next;
            }
        }
    });
    std::vector<SegmentTask> tasks;
    for (std::vector<SegmentTask>& list : chain_tasks)
        for (SegmentTask& t : list) {
            t.first = tasks.empty() ? 0 : tasks.back().first + tasks.back().steps - 1;
            tasks.push_back(t);
        }
    resolve_segments(tester, segments, tasks, precision, whole, pieces);

    // Serial gather in input order, so split keys and output order are deterministic.
    VisibilitySplit result;
    auto emit = [&](const LineSegment& part, uint8_t level) {
        if (level == kClipped) return;
        if (level == 0) {
            result.visible.push_back(part);
        } else {
            result.hidden.push_back(part);
            result.hidden_levels.push_back(level);
        }
    };
    uint32_t counter = 0;
    for (size_t i = 0; i < n; ++i) {
        const LineSegment& s = segments[i];
        if (whole[i] != kSplit) {
            emit(s, whole[i]);
            continue;
        }
        for (const Piece& p : pieces[i]) {
            if (p.level == kClipped) continue;
            LineSegment part = s;
            if (p.t0 > 0.0) {
                part.a = lerp(s, p.t0);
                part.edge_a = split_key(counter++);
                part.strength_a = float(s.strength_a + p.t0 * (s.strength_b - s.strength_a));
            }
            if (p.t1 < 1.0) {
                part.b = lerp(s, p.t1);
                part.edge_b = split_key(counter++);
                part.strength_b = float(s.strength_a + p.t1 * (s.strength_b - s.strength_a));
            }
            emit(part, p.level);
        }
    }
    return result;
}

}  // namespace inkshade::geometry
