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

// rtcOccluded1's context, extended with the sample's near vertices (Embree's documented way to
// hand per-ray data to a filter function: the context is passed through unchanged).
struct OcclusionContext {
    RTCIntersectContext rtc;
    const glm::uvec3* triangles = nullptr;
    const IncidentFaces* incident = nullptr;  // faces of the two-ring queries' near vertices
    const OcclusionQuery* queries = nullptr;  // indexed by the ray's id
};

bool shares_vertex(const glm::uvec3& t, uint32_t v) { return t.x == v || t.y == v || t.z == v; }

// Is triangle t within `rings` (1 or 2) face rings of the query's near vertices?
bool near_face(const OcclusionContext& ctx, const OcclusionQuery& q, const glm::uvec3& t) {
    for (int k = 0; k < q.near_count; ++k)
        if (shares_vertex(t, q.near[k])) return true;
    if (q.rings < 2) return false;
    for (int k = 0; k < q.near_count; ++k) {
        const auto [first, last] = ctx.incident->faces(q.near[k]);
        for (const uint32_t* f = first; f != last; ++f) {
            const glm::uvec3 u = ctx.triangles[*f];
            if (shares_vertex(t, u.x) || shares_vertex(t, u.y) || shares_vertex(t, u.z)) return true;
        }
    }
    return false;
}

// Rejects hits on faces near the tested point: the ray continues past them.
void skip_near_faces(const RTCFilterFunctionNArguments* args) {
    const auto* ctx = reinterpret_cast<const OcclusionContext*>(args->context);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const OcclusionQuery& q = ctx->queries[RTCRayN_id(args->ray, args->N, i)];
        if (near_face(*ctx, q, ctx->triangles[RTCHitN_primID(args->hit, args->N, i)])) args->valid[i] = 0;
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
    tolerance_ = 1e-4 * std::max(double(mesh.bounds().diagonal()), 1e-30);
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
        rtcSetGeometryOccludedFilterFunction(geom, skip_near_faces);
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

// ---- IncidentFaces -----------------------------------------------------------------------

IncidentFaces::IncidentFaces(const Mesh& mesh, const std::vector<uint32_t>& vertices) {
    const size_t nv = mesh.positions.size(), nf = mesh.triangles.size();
    if (vertices.empty()) return;
    // Dense slots (4 B a vertex for the view's duration) make a lookup one load; the scan tests
    // a bitmap first (600 kB at 5 M vertices: it stays in cache, the slots would not).
    slot_.assign(nv, kNone);
    std::vector<uint64_t> chosen((nv + 63) / 64, 0);
    uint32_t count = 0;
    for (uint32_t v : vertices)
        if (v < nv && slot_[v] == kNone) {
            slot_[v] = count++;
            chosen[v / 64] |= uint64_t(1) << (v % 64);
        }
    // Blocks of faces in parallel, each listing (slot, face) for its chosen vertices; blocks are
    // concatenated in order, so each vertex's faces come out ascending.
    constexpr size_t kBlock = size_t(1) << 16;
    std::vector<std::vector<glm::uvec2>> found((nf + kBlock - 1) / kBlock);
    tbb::parallel_for(size_t(0), found.size(), [&](size_t b) {
        for (size_t f = b * kBlock, end = std::min(nf, f + kBlock); f < end; ++f) {
            const glm::uvec3 t = mesh.triangles[f];
            if (t.x >= nv || t.y >= nv || t.z >= nv) continue;
            for (uint32_t v : {t.x, t.y, t.z})
                if ((chosen[v / 64] >> (v % 64)) & 1) found[b].emplace_back(slot_[v], uint32_t(f));
        }
    });
    offset_.assign(size_t(count) + 1, 0);
    for (const auto& list : found)
        for (const glm::uvec2& x : list) ++offset_[x.x + 1];
    for (size_t i = 0; i < count; ++i) offset_[i + 1] += offset_[i];
    faces_.resize(offset_.back());
    std::vector<uint32_t> fill(offset_.begin(), offset_.end() - 1);
    for (const auto& list : found)
        for (const glm::uvec2& x : list) faces_[fill[x.x]++] = x.y;
}

std::pair<const uint32_t*, const uint32_t*> IncidentFaces::faces(uint32_t v) const {
    if (v >= slot_.size() || slot_[v] == kNone) return {nullptr, nullptr};
    return {faces_.data() + offset_[slot_[v]], faces_.data() + offset_[slot_[v] + 1]};
}

// ---- RayScene queries ----------------------------------------------------------------------

bool RayScene::occluded(const ImageProjection& view, const glm::vec3& p, const uint32_t* near_vertices, int near_count,
                        int rings, double clearance, const IncidentFaces* incident) const {
    const OcclusionQuery query{p, near_vertices, near_count, rings, clearance};
    uint8_t hidden = 0;
    occluded(view, &query, 1, &hidden, incident);
    return hidden != 0;
}

void RayScene::occluded(const ImageProjection& view, const OcclusionQuery* queries, size_t count, uint8_t* hidden,
                        const IncidentFaces* incident) const {
    IncidentFaces own;
    if (!incident) {
        std::vector<uint32_t> ring_vertices;
        for (size_t i = 0; i < count; ++i)
            if (queries[i].rings >= 2)
                ring_vertices.insert(ring_vertices.end(), queries[i].near, queries[i].near + queries[i].near_count);
        own = IncidentFaces(*impl_->mesh, ring_vertices);
        incident = &own;
    }
    const Camera& cam = view.camera();
    const double near = double(cam.near_plane);
    const glm::dvec3 eye(cam.eye);
    const glm::dvec3 forward = glm::normalize(glm::dvec3(cam.target) - eye);
    std::vector<RTCRay> rays(count);
    for (size_t i = 0; i < count; ++i) {
        const OcclusionQuery& q = queries[i];
        const double tolerance = std::max(tolerance_, q.clearance);
        const double z = view.view_depth(q.point);
        glm::dvec3 org, dir;
        double tnear = 0.0, tfar = 0.0;
        if (cam.orthographic) {
            // From the near plane along the view direction, unit speed: t is a distance.
            const double s = z - near;
            org = glm::dvec3(q.point) - s * forward;
            dir = forward;
            tfar = s - tolerance;
        } else {
            // From the eye, t = 1 at p; starts where the ray crosses the near plane.
            org = eye;
            dir = glm::dvec3(q.point) - org;
            const double len = glm::length(dir);
            tnear = z > 0.0 ? near / z : 1.0;
            tfar = len > 0.0 ? 1.0 - tolerance / len : 0.0;
        }
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
    ctx.triangles = impl_->triangles;
    ctx.incident = incident;
    ctx.queries = queries;
    if (count == 1)
        rtcOccluded1(impl_->scene, &ctx.rtc, &rays[0]);
    else if (count > 1)
        rtcOccluded1M(impl_->scene, &ctx.rtc, rays.data(), unsigned(count), sizeof(RTCRay));
    for (size_t i = 0; i < count; ++i) hidden[i] = rays[i].tfar < 0.0f;  // −inf on a hit
}

// ---- split_by_visibility -----------------------------------------------------------------

namespace {

enum class Sight : uint8_t { Visible, Hidden, Clipped };

// Vertices whose faces a sample ignores, from a node key (see contours.hpp for the key kinds).
struct NearSet {
    uint32_t v[8];
    int n = 0;
    void add(uint32_t x) {
        for (int i = 0; i < n; ++i)
            if (v[i] == x) return;
        if (n < 8) v[n++] = x;
    }
};

void add_face(NearSet& s, const Mesh& mesh, uint32_t face) {
    if (face >= mesh.triangles.size()) return;
    const glm::uvec3 t = mesh.triangles[face];
    s.add(t.x), s.add(t.y), s.add(t.z);
}

NearSet near_of_key(const Mesh& mesh, uint64_t key, uint32_t face) {
    NearSet s;
    const uint32_t hi = uint32_t(key >> 32), lo = uint32_t(key);
    if (hi < lo)
        s.add(hi), s.add(lo);  // mesh edge
    else if (hi == lo)
        s.add(hi);  // mesh vertex
    else
        add_face(s, mesh, face);  // inside a face
    return s;
}

struct Piece {
    double t0, t1;
    Sight sight;
};

glm::vec3 lerp(const LineSegment& s, double t) {
    return glm::vec3(glm::dvec3(s.a) + t * (glm::dvec3(s.b) - glm::dvec3(s.a)));
}

double pixel_distance(const ImageProjection& view, const glm::vec3& a, const glm::vec3& b) {
    const glm::dvec3 pa = view.project(a), pb = view.project(b);
    return std::hypot(pa.x - pb.x, pa.y - pb.y);
}

// Key of a split point: high word 0xfffffffd, low word a counter below it — no edge key
// (high < low), vertex key (high == low) or face_interior_key (high ≥ 0xfffffffe) has it.
constexpr uint64_t split_key(uint32_t counter) { return (uint64_t(0xfffffffdu) << 32) | counter; }

// How a segment's samples are tested: lines along mesh edges (vertex keys at both ends) lie
// on their faces, one ring; isolines graze, two rings and a clearance of the face's size.
struct SampleRule {
    int rings = 1;
    double clearance = 0.0;
};

SampleRule rule_of(const Mesh& mesh, const LineSegment& s, const VisibilityOptions& options) {
    const bool on_edges =
        uint32_t(s.edge_a >> 32) == uint32_t(s.edge_a) && uint32_t(s.edge_b >> 32) == uint32_t(s.edge_b);
    if (on_edges) return {1, 0.0};
    SampleRule rule{options.exclusion_rings, 0.0};
    if (s.face < mesh.triangles.size()) {
        const glm::uvec3 t = mesh.triangles[s.face];
        const size_t nv = mesh.positions.size();
        if (t.x < nv && t.y < nv && t.z < nv) {
            const glm::vec3 a = mesh.positions[t.x], b = mesh.positions[t.y], c = mesh.positions[t.z];
            rule.clearance = options.isoline_clearance *
                             double(std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)}));
        }
    }
    return rule;
}

Sight sight_of(const RayScene& scene, const ImageProjection& view, const glm::vec3& p, const NearSet& near,
               const SampleRule& rule, const IncidentFaces& incident) {
    if (view.clipped(p)) return Sight::Clipped;
    return scene.occluded(view, p, near.v, near.n, rule.rings, rule.clearance, &incident) ? Sight::Hidden
                                                                                          : Sight::Visible;
}

// Sight of every segment end, each shared node tested once: neighbouring segments of a chain
// meet at bit-identical points with equal keys (contours.hpp), so about half the rays of a
// per-segment test are saved, and both segments agree on the shared end by construction.
std::vector<Sight> end_sights(const RayScene& scene, const Mesh& mesh, const ImageProjection& view,
                              const std::vector<LineSegment>& segments, const std::vector<SampleRule>& rules,
                              const IncidentFaces& incident) {
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
    std::vector<Sight> sights(2 * n);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, starts.size() - 1, 64), [&](const tbb::blocked_range<size_t>& r) {
        // One stream of rays per block (rtcOccluded1M); clipped nodes need no ray.
        std::vector<NearSet> near(r.size());
        std::vector<OcclusionQuery> queries;
        std::vector<size_t> query_group;
        queries.reserve(r.size());
        for (size_t g = r.begin(); g != r.end(); ++g) {
            const End& first = ends[starts[g]];
            const LineSegment& s = segments[first.index / 2];
            const glm::vec3 p = (first.index & 1) ? s.b : s.a;
            if (view.clipped(p)) {
                for (uint32_t k = starts[g]; k < starts[g + 1]; ++k) sights[ends[k].index] = Sight::Clipped;
                continue;
            }
            SampleRule rule;
            for (uint32_t k = starts[g]; k < starts[g + 1]; ++k) {
                const SampleRule& r2 = rules[ends[k].index / 2];
                rule.rings = std::max(rule.rings, r2.rings);
                rule.clearance = std::max(rule.clearance, r2.clearance);
            }
            NearSet& ns = near[g - r.begin()];
            ns = near_of_key(mesh, first.key, s.face);
            queries.push_back({p, ns.v, ns.n, rule.rings, rule.clearance});
            query_group.push_back(g);
        }
        std::vector<uint8_t> hidden(queries.size());
        scene.occluded(view, queries.data(), queries.size(), hidden.data(), &incident);
        for (size_t q = 0; q < queries.size(); ++q) {
            const size_t g = query_group[q];
            for (uint32_t k = starts[g]; k < starts[g + 1]; ++k)
                sights[ends[k].index] = hidden[q] ? Sight::Hidden : Sight::Visible;
        }
    });
    return sights;
}

}  // namespace

IncidentFaces incident_faces_of(const Mesh& mesh, const std::vector<const std::vector<LineSegment>*>& lists,
                                const VisibilityOptions& options) {
    // Every near vertex of a two-ring sample: the segment's face and its end keys' vertices.
    std::vector<uint32_t> ring_vertices;
    for (const std::vector<LineSegment>* list : lists)
        for (const LineSegment& s : *list) {
            if (rule_of(mesh, s, options).rings < 2) continue;
            for (const NearSet& e : {near_of_key(mesh, s.edge_a, s.face), near_of_key(mesh, s.edge_b, s.face)})
                ring_vertices.insert(ring_vertices.end(), e.v, e.v + e.n);
            if (s.face < mesh.triangles.size())
                for (int k = 0; k < 3; ++k) ring_vertices.push_back(mesh.triangles[s.face][k]);
        }
    return IncidentFaces(mesh, ring_vertices);
}

VisibilitySplit split_by_visibility(const RayScene& scene, const Mesh& mesh, const ImageProjection& view,
                                    const std::vector<LineSegment>& segments, const VisibilityOptions& options,
                                    const IncidentFaces* incident) {
    const size_t n = segments.size();
    const double spacing = std::max(double(options.sample_spacing_px), 1e-3);
    const double precision = std::max(double(options.transition_precision_px), 1e-4);
    constexpr uint8_t kSplit = 0xff;
    std::vector<uint8_t> whole(n, kSplit);      // Sight of an unsplit segment, else kSplit
    std::vector<std::vector<Piece>> pieces(n);  // pieces of split segments only
    std::vector<SampleRule> rules(n);
    tbb::parallel_for(size_t(0), n, [&](size_t i) { rules[i] = rule_of(mesh, segments[i], options); });
    IncidentFaces own;
    if (!incident) {
        own = incident_faces_of(mesh, {&segments}, options);
        incident = &own;
    }
    const std::vector<Sight> ends = end_sights(scene, mesh, view, segments, rules, *incident);

    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 64), [&](const tbb::blocked_range<size_t>& r) {
        std::vector<Sight> sights;
        for (size_t i = r.begin(); i != r.end(); ++i) {
            const LineSegment& s = segments[i];
            const SampleRule& rule = rules[i];
            NearSet inside;  // samples strictly inside the segment
            add_face(inside, mesh, s.face);
            for (const NearSet& e : {near_of_key(mesh, s.edge_a, s.face), near_of_key(mesh, s.edge_b, s.face)})
                for (int k = 0; k < e.n; ++k) inside.add(e.v[k]);
            int steps = 1;
            if (!view.clipped(s.a) && !view.clipped(s.b)) {
                const double px = pixel_distance(view, s.a, s.b);
                // NaN (a degenerate camera) keeps one step instead of an undefined conversion.
                if (std::isfinite(px)) steps = int(std::clamp(std::ceil(px / spacing), 1.0, 16384.0));
            }
            sights.resize(size_t(steps) + 1);
            sights[0] = ends[2 * i];
            sights[size_t(steps)] = ends[2 * i + 1];
            for (int k = 1; k < steps; ++k)
                sights[size_t(k)] = sight_of(scene, view, lerp(s, double(k) / steps), inside, rule, *incident);
            if (std::all_of(sights.begin(), sights.end(), [&](Sight x) { return x == sights[0]; })) {
                whole[i] = uint8_t(sights[0]);
                continue;
            }
            // Runs of equal sight; each change bisected between its two samples.
            std::vector<Piece>& out = pieces[i];
            double start = 0.0;
            for (int k = 0; k < steps; ++k) {
                if (sights[size_t(k)] == sights[size_t(k) + 1]) continue;
                double lo = double(k) / steps, hi = double(k + 1) / steps;
                for (int iter = 0; iter < 60; ++iter) {
                    const glm::vec3 plo = lerp(s, lo), phi = lerp(s, hi);
                    const bool measurable = !view.clipped(plo) && !view.clipped(phi);
                    if (measurable ? pixel_distance(view, plo, phi) <= precision : hi - lo < 1e-7) break;
                    const double mid = 0.5 * (lo + hi);
                    (sight_of(scene, view, lerp(s, mid), inside, rule, *incident) == sights[size_t(k)] ? lo : hi) = mid;
                }
                const double t = 0.5 * (lo + hi);
                out.push_back({start, t, sights[size_t(k)]});
                start = t;
            }
            out.push_back({start, 1.0, sights[size_t(steps)]});
        }
    });

    // Serial gather in input order, so split keys and output order are deterministic.
    VisibilitySplit result;
    uint32_t counter = 0;
    for (size_t i = 0; i < n; ++i) {
        const LineSegment& s = segments[i];
        if (whole[i] != kSplit) {
            if (Sight(whole[i]) == Sight::Visible)
                result.visible.push_back(s);
            else if (Sight(whole[i]) == Sight::Hidden)
                result.hidden.push_back(s);
            continue;
        }
        for (const Piece& p : pieces[i]) {
            if (p.sight == Sight::Clipped) continue;
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
            (p.sight == Sight::Visible ? result.visible : result.hidden).push_back(part);
        }
    }
    return result;
}

}  // namespace inkshade::geometry
