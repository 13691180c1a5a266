// The faces around each vertex (its star), in face order: what auto-smooth walks to find the
// faces on either side of an edge without a mesh-wide edge table (a few faces a vertex,
// typically six, so a look-up is a short scan).
#pragma once
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "inkshade/mesh.hpp"

namespace inkshade::geometry {

// A vector's allocator that leaves new elements uninitialised: a table that is filled at once
// then costs no pass of zeros over its pages first.
template <class T>
struct UninitialisedAllocator : std::allocator<T> {
    template <class U>
    struct rebind {
        using other = UninitialisedAllocator<U>;
    };
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        if constexpr (sizeof...(Args) == 0)
            ::new (static_cast<void*>(p)) U;
        else
            ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
};

// Calls body(lo, hi) for a few vertex ranges covering [0, n) in parallel (one per thread, at
// most max_parts): a pass that scatters per-corner values into per-vertex entries reads every
// face in each range and writes only its own vertices, so it needs no atomics and keeps face
// order. Each range reads all faces: worth it where most corners write something.
template <class Body>
void for_vertex_ranges(size_t n, Body&& body, size_t max_parts = ~size_t(0)) {
    const size_t threads = size_t(tbb::this_task_arena::max_concurrency());
    const size_t parts = std::clamp<size_t>(std::min(threads, max_parts), 1, n / 4096 + 1);
    tbb::parallel_for(size_t(0), parts, [&](size_t p) { body(n * p / parts, n * (p + 1) / parts); });
}

// faces[offsets[v] .. offsets[v + 1]) are the faces with a corner at v, in face order; a face
// with a repeated index is listed once per corner there, consecutively. Triangles must index
// existing vertices.
struct VertexFaces {
    std::vector<uint32_t> offsets;
    std::vector<uint32_t, UninitialisedAllocator<uint32_t>> faces;

    const uint32_t* begin(uint32_t v) const { return faces.data() + offsets[v]; }
    const uint32_t* end(uint32_t v) const { return faces.data() + offsets[v + 1]; }
};

VertexFaces vertex_faces(const Mesh& mesh);
// Only the stars of the vertices v with only[v] != 0 (one entry per vertex); the others are
// empty: what auto-smooth needs where few vertices are near a hard edge.
VertexFaces vertex_faces(const Mesh& mesh, const std::vector<uint8_t>& only);

// The faces other than `face` that have both v and w (v ≠ w): how many (distinct faces) and the
// first of them. On a manifold edge count is 1, on a border 0.
struct EdgeMate {
    uint32_t count = 0, face = 0;
};
EdgeMate edge_mate(const Mesh& mesh, const VertexFaces& vf, uint32_t face, uint32_t v, uint32_t w);

}  // namespace inkshade::geometry
