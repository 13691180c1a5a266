// EdgeNeighbours (visibility.hpp): the faces on either side of the edges around chosen
// vertices, in an open-addressing hash table filled in parallel.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>

#include "geometry/face_segments.hpp"
#include "geometry/triangle_vertices.hpp"
#include "geometry/visibility.hpp"

namespace inkshade::geometry {

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
                    if (key_found == kEmpty && slot.key.compare_exchange_strong(key_found, key))
                        key_found = key, ++added;
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
        const uint32_t f0 = slot.face[0].load(std::memory_order_relaxed),
                       f1 = slot.face[1].load(std::memory_order_relaxed);
        if (f1 == kNoFace || f1 == kMany) return kNoFace;  // a border, or non-manifold
        return f0 == face ? f1 : f1 == face ? f0 : kNoFace;
    }
}

}  // namespace inkshade::geometry
