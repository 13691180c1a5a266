#include "geometry/visibility.hpp"

#include <embree3/rtcore.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <tuple>
#include <string>

#include "inkshade/error.hpp"

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

int shared_vertices(const glm::uvec3& t, const glm::uvec3& u) {
    return int(has_vertex(t, u.x)) + int(has_vertex(t, u.y)) + int(has_vertex(t, u.z));
}

// Hits recorded per ray for counting each crossing once (levels past this are rare and are
// counted without that check).
constexpr int kRecordedHits = 16;
constexpr int kFoldFaces = 32;  // fold faces kept per contour sample

// What one ray has met so far (the filter's running count).
struct RayState {
    uint8_t level = 0;
    uint8_t recorded = 0;
    bool fold_known = false;
    uint8_t fold_count = 0;
    uint32_t fold[kFoldFaces];  // a contour point's fold faces, once walked
    float same_point = 0.0f;      // two hits closer than this in t are at one point of the ray
    float t[kRecordedHits];
    uint32_t prim[kRecordedHits];
};

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

// The faces of a contour point's fold (RayScene::occlusion_levels): walking the mesh's
// cross-section in the plane through the ray and the point's normal, both ways from the point,
// the faces where it stays within `fold_band` of the ray's line, and the one where it meets
// that line on leaving the band. Writes up to kFoldFaces faces; returns how many.
int fold_faces(const OcclusionContext& ctx, const OcclusionQuery& q, uint32_t* out) {
    if (!ctx.around || q.on.face == kNoFace || !(q.fold_band > 0.0f)) return 0;
    const Mesh& mesh = *ctx.mesh;
    const glm::dvec3 p(q.point);
    const glm::dvec3 d = ctx.orthographic ? ctx.forward : glm::normalize(p - ctx.eye);
    glm::dvec3 up = glm::dvec3(q.normal) - glm::dot(glm::dvec3(q.normal), d) * d;  // in the plane, ⟂ ray
    const double up_len = glm::length(up);
    if (!(up_len > 1e-12)) return 0;
    up /= up_len;
    const glm::dvec3 m = glm::cross(d, up);  // the plane's normal
    const double band = double(q.fold_band);
    auto side = [&](uint32_t v) { return glm::dot(glm::dvec3(mesh.positions[v]) - p, m) >= 0.0; };
    // Where the plane cuts edge (a, b) (sides differ), from the ordered pair so that both faces
    // of the edge get the same point; its height above the ray's line.
    auto height = [&](uint32_t a, uint32_t b) {
        if (a > b) std::swap(a, b);
        const glm::dvec3 pa(mesh.positions[a]), pb(mesh.positions[b]);
        const double sa = glm::dot(pa - p, m), sb = glm::dot(pb - p, m);
        const double t = sa / (sa - sb);
        return glm::dot(pa + t * (pb - pa) - p, up);
    };
    int n = 0;
    // One way: from `face` (entered by edge (in_a, in_b); kNoFace when p is inside it and
    // `rising` picks the way), out by its other cut edge, until the section leaves the band.
    auto walk = [&](uint32_t face, uint32_t in_a, uint32_t in_b, bool rising) {
        double h_in = 0.0;
        for (int step = 0; step < 256 && face != kNoFace; ++step) {
            const glm::uvec3 t = ctx.triangles[face];
            uint32_t exit_a = kNoFace, exit_b = kNoFace;
            double h_out = 0.0;
            for (int k = 0; k < 3; ++k) {
                const uint32_t a = t[k], b = t[(k + 1) % 3];
                if (side(a) == side(b) || (a == in_a && b == in_b) || (a == in_b && b == in_a)) continue;
                const double h = height(a, b);
                // Inside p's face the section runs both ways: the rising way leaves by the higher
                // cut (by comparison, not sign: p lies on the face only up to float rounding).
                if (step == 0 && in_a == kNoFace && exit_a != kNoFace && (h > h_out) != rising) continue;
                exit_a = a, exit_b = b, h_out = h;
                if (step > 0 || in_a != kNoFace) break;
            }
            if (exit_a == kNoFace) return;
            // Inside this face the section stays within the band (a ray can only meet the face
            // on it: float rounding may make it do so where the exact section just misses),
            // or it meets the ray's line before leaving the band. p's own face aside.
            const bool inside = std::abs(h_out) <= band;
            if (step > 0 && (inside || (h_in <= 0.0) != (h_out <= 0.0)) && n < kFoldFaces) out[n++] = face;
            if (!inside) return;
            in_a = exit_a, in_b = exit_b, h_in = h_out;
            face = ctx.around->across(face, exit_a, exit_b);
        }
    };
    if (q.on.kind == PointOn::Edge) {
        // p on an edge: one way through each of its two faces.
        walk(q.on.face, q.on.u, q.on.v, true);
        walk(ctx.around->across(q.on.face, q.on.u, q.on.v), q.on.u, q.on.v, true);
    } else {
        walk(q.on.face, kNoFace, kNoFace, true);
        walk(q.on.face, kNoFace, kNoFace, false);
    }
    return n;
}

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
        if (q.fold_band > 0.0f) {
            if (!st.fold_known) st.fold_count = uint8_t(fold_faces(*ctx, q, st.fold)), st.fold_known = true;
            if (std::find(st.fold, st.fold + st.fold_count, prim) != st.fold + st.fold_count) continue;
        }
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
                    [&](const glm::uvec3& t) { return t.x >= nv || t.y >= nv || t.z >= nv; })) {
        // Embree skips such triangles too, but a hit must never index out of range here.
        m.own_triangles = mesh.triangles;
        for (auto& t : m.own_triangles)
            if (t.x >= nv || t.y >= nv || t.z >= nv) t = glm::uvec3(0);  // never hit
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

EdgeNeighbours::EdgeNeighbours(const Mesh& mesh, const std::vector<uint32_t>& vertices) {
    const size_t nv = mesh.positions.size(), nf = mesh.triangles.size();
    if (vertices.empty()) return;
    std::vector<uint64_t> chosen((nv + 63) / 64, 0);  // a bitmap stays in cache during the scan
    for (uint32_t v : vertices)
        if (v < nv) chosen[v / 64] |= uint64_t(1) << (v % 64);
    // Blocks of faces in parallel, each listing the edges of its faces that touch a chosen vertex.
    constexpr size_t kBlock = size_t(1) << 16;
    std::vector<std::vector<std::pair<uint64_t, uint32_t>>> found((nf + kBlock - 1) / kBlock);
    tbb::parallel_for(size_t(0), found.size(), [&](size_t b) {
        for (size_t f = b * kBlock, end = std::min(nf, f + kBlock); f < end; ++f) {
            const glm::uvec3 t = mesh.triangles[f];
            if (t.x >= nv || t.y >= nv || t.z >= nv) continue;
            bool near = false;
            for (uint32_t v : {t.x, t.y, t.z}) near |= ((chosen[v / 64] >> (v % 64)) & 1) != 0;
            if (!near) continue;
            for (int k = 0; k < 3; ++k)
                if (t[k] != t[(k + 1) % 3]) found[b].emplace_back(edge_key(t[k], t[(k + 1) % 3]), uint32_t(f));
        }
    });
    size_t total = 0;
    for (const auto& list : found) total += list.size();
    edges_.reserve(total);
    for (const auto& list : found) edges_.insert(edges_.end(), list.begin(), list.end());
    tbb::parallel_sort(edges_.begin(), edges_.end());
    edges_.erase(std::unique(edges_.begin(), edges_.end()), edges_.end());  // a face with a repeated edge
}

uint32_t EdgeNeighbours::across(uint32_t face, uint32_t a, uint32_t b) const {
    if (a == b) return kNoFace;
    const uint64_t key = edge_key(a, b);
    auto it = std::lower_bound(edges_.begin(), edges_.end(), std::make_pair(key, uint32_t(0)));
    uint32_t found = kNoFace;
    int count = 0;
    for (; it != edges_.end() && it->first == key; ++it, ++count)
        if (it->second != face) found = it->second;
    return count == 2 ? found : kNoFace;  // a border (1) or non-manifold edge (3+): no one neighbour
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
    std::vector<RTCRay> rays(count);
    std::vector<RayState> states(count);
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
    ctx.states = states.data();
    ctx.cap = cap;
    ctx.eye = eye;
    ctx.forward = forward;
    ctx.orthographic = cam.orthographic;
    if (count == 1)
        rtcOccluded1(impl_->scene, &ctx.rtc, &rays[0]);
    else if (count > 1)
        rtcOccluded1M(impl_->scene, &ctx.rtc, rays.data(), unsigned(count), sizeof(RTCRay));
    for (size_t i = 0; i < count; ++i) levels[i] = states[i].level;
}

// ---- split_by_visibility -----------------------------------------------------------------

namespace {

constexpr uint8_t kClipped = 0xff;  // a sample outside the near/far range (levels are ≤ 255 − 1)

bool is_vertex_key(uint64_t key) { return uint32_t(key >> 32) == uint32_t(key); }
bool is_edge_key(uint64_t key) { return uint32_t(key >> 32) < uint32_t(key); }
bool is_pierce_key(uint64_t key) { return uint32_t(key >> 32) == 0xfffffffcu; }

// A segment along a mesh edge (crease, border, silhouette edge): vertex keys at both ends.
bool along_edge(const LineSegment& s) { return is_vertex_key(s.edge_a) && is_vertex_key(s.edge_b); }

bool valid_face(const Mesh& mesh, uint32_t f) {
    if (f >= mesh.triangles.size()) return false;
    const glm::uvec3 t = mesh.triangles[f];
    const size_t nv = mesh.positions.size();
    return t.x < nv && t.y < nv && t.z < nv;
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

struct Tester {
    const RayScene& scene;
    const Mesh& mesh;
    const ImageProjection& view;
    const EdgeNeighbours* around;
    int cap;
    float fold_px;  // contour samples: the fold band in pixels, else 0

    uint8_t level(const glm::vec3& p, const PointOn& on) const {
        if (view.clipped(p)) return kClipped;
        const OcclusionQuery q = query_at(mesh, view, p, on, fold_px);
        uint8_t level = 0;
        scene.occlusion_levels(view, &q, 1, &level, cap, around);
        return level;
    }
};

// Level of every segment end, each shared node tested once: neighbouring segments of a chain
// meet at bit-identical points with equal keys (contours.hpp), so about half the rays of a
// per-segment test are saved, and both segments agree on the shared end by construction.
std::vector<uint8_t> end_levels(const Tester& tester, const std::vector<LineSegment>& segments) {
    struct End {
        uint64_t key;
        uint32_t px, py, pz;  // position bits: a node is one key at one point
        uint32_t index;       // 2 × segment + (0 for a, 1 for b)
        bool operator<(const End& o) const {
            return std::tie(key, px, py, pz, index) < std::tie(o.key, o.px, o.py, o.pz, o.index);
        }
    };
    const size_t n = segments.size();
    std::vector<End> ends(2 * n);
    tbb::parallel_for(size_t(0), n, [&](size_t i) {
        const LineSegment& s = segments[i];
        for (int e = 0; e < 2; ++e) {
            const glm::vec3 p = e ? s.b : s.a;
            End& x = ends[2 * i + size_t(e)];
            x.key = e ? s.edge_b : s.edge_a;
            std::memcpy(&x.px, &p.x, 4), std::memcpy(&x.py, &p.y, 4), std::memcpy(&x.pz, &p.z, 4);
            x.index = uint32_t(2 * i + size_t(e));
        }
    });
    tbb::parallel_sort(ends.begin(), ends.end());
    // Group starts: one test per run of equal (key, point).
    std::vector<uint32_t> starts;
    for (size_t k = 0; k < ends.size(); ++k)
        if (k == 0 || ends[k].key != ends[k - 1].key || ends[k].px != ends[k - 1].px || ends[k].py != ends[k - 1].py ||
            ends[k].pz != ends[k - 1].pz)
            starts.push_back(uint32_t(k));
    starts.push_back(uint32_t(ends.size()));
    std::vector<uint8_t> levels(2 * n);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, starts.size() - 1, 64), [&](const tbb::blocked_range<size_t>& r) {
        // One stream of rays per block (rtcOccluded1M); clipped nodes need no ray.
        std::vector<OcclusionQuery> queries;
        std::vector<size_t> query_group;
        queries.reserve(r.size());
        for (size_t g = r.begin(); g != r.end(); ++g) {
            const End& first = ends[starts[g]];
            const LineSegment& s = segments[first.index / 2];
            const glm::vec3 p = (first.index & 1) ? s.b : s.a;
            if (tester.view.clipped(p)) {
                for (uint32_t k = starts[g]; k < starts[g + 1]; ++k) levels[ends[k].index] = kClipped;
                continue;
            }
            queries.push_back(query_at(tester.mesh, tester.view, p, end_on(tester.mesh, s, first.key), tester.fold_px));
            query_group.push_back(g);
        }
        std::vector<uint8_t> found(queries.size());
        tester.scene.occlusion_levels(tester.view, queries.data(), queries.size(), found.data(), tester.cap,
                                      tester.around);
        for (size_t q = 0; q < queries.size(); ++q) {
            const size_t g = query_group[q];
            for (uint32_t k = starts[g]; k < starts[g + 1]; ++k) levels[ends[k].index] = found[q];
        }
    });
    return levels;
}

}  // namespace

EdgeNeighbours contour_surroundings(const Mesh& mesh, const std::vector<LineSegment>& contours) {
    std::vector<uint32_t> vertices;
    vertices.reserve(3 * contours.size());
    for (const LineSegment& s : contours)
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
        own = contour_surroundings(mesh, segments);
        around = &own;
    }
    const Tester tester{scene, mesh, view, around, std::clamp(options.count_levels_to, 1, 253),
                        options.contour ? std::max(options.contour_fold_px, 0.0f) : 0.0f};
    constexpr uint8_t kSplit = 0xfe;  // not a level (levels ≤ 253) nor kClipped
    std::vector<uint8_t> whole(n, kSplit);      // level of an unsplit segment, else kSplit
    std::vector<std::vector<Piece>> pieces(n);  // pieces of split segments only
    const std::vector<uint8_t> ends = end_levels(tester, segments);

    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 64), [&](const tbb::blocked_range<size_t>& r) {
        std::vector<uint8_t> levels;
        for (size_t i = r.begin(); i != r.end(); ++i) {
            const LineSegment& s = segments[i];
            const PointOn inside = interior_on(mesh, s);
            int steps = 1;
            if (!view.clipped(s.a) && !view.clipped(s.b)) {
                const double px = pixel_distance(view, s.a, s.b);
                // NaN (a degenerate camera) keeps one step instead of an undefined conversion.
                if (std::isfinite(px)) steps = int(std::clamp(std::ceil(px / spacing), 1.0, 16384.0));
            }
            levels.resize(size_t(steps) + 1);
            levels[0] = ends[2 * i];
            levels[size_t(steps)] = ends[2 * i + 1];
            for (int k = 1; k < steps; ++k) levels[size_t(k)] = tester.level(lerp(s, double(k) / steps), inside);
            if (std::all_of(levels.begin(), levels.end(), [&](uint8_t x) { return x == levels[0]; })) {
                whole[i] = levels[0];
                continue;
            }
            // Runs of equal level; each change bisected between its two samples.
            std::vector<Piece>& out = pieces[i];
            double start = 0.0;
            for (int k = 0; k < steps; ++k) {
                if (levels[size_t(k)] == levels[size_t(k) + 1]) continue;
                double lo = double(k) / steps, hi = double(k + 1) / steps;
                for (int iter = 0; iter < 60; ++iter) {
                    const glm::vec3 plo = lerp(s, lo), phi = lerp(s, hi);
                    const bool measurable = !view.clipped(plo) && !view.clipped(phi);
                    if (measurable ? pixel_distance(view, plo, phi) <= precision : hi - lo < 1e-7) break;
                    const double mid = 0.5 * (lo + hi);
                    (tester.level(lerp(s, mid), inside) == levels[size_t(k)] ? lo : hi) = mid;
                }
                const double t = 0.5 * (lo + hi);
                out.push_back({start, t, levels[size_t(k)]});
                start = t;
            }
            out.push_back({start, 1.0, levels[size_t(steps)]});
        }
    });

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
