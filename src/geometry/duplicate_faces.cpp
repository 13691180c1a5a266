#include "geometry/duplicate_faces.hpp"

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <utility>

namespace inkshade::geometry {
namespace {

// A face's sorted vertex indices and its position in the mesh: 16 bytes, compared on the
// indices only (the first occurrence of a run is found afterwards, so the sort need not be
// stable).
struct FaceKey {
    uint64_t low_mid = 0;  // smallest index << 32 | middle index
    uint32_t high = 0;     // largest index
    uint32_t face = 0;
    bool operator<(const FaceKey& o) const { return low_mid < o.low_mid || (low_mid == o.low_mid && high < o.high); }
    bool same_vertices(const FaceKey& o) const { return low_mid == o.low_mid && high == o.high; }
};

FaceKey key_of(glm::uvec3 t, uint32_t face) {
    uint32_t a = t.x, b = t.y, c = t.z;
    if (a > b) std::swap(a, b);
    if (b > c) std::swap(b, c);
    if (a > b) std::swap(a, b);
    return FaceKey{(uint64_t(a) << 32) | b, c, face};
}

}  // namespace

std::vector<uint8_t> find_duplicate_faces(const std::vector<glm::uvec3>& triangles) {
    const size_t n = triangles.size();
    std::vector<uint8_t> duplicate(n, 0);
    if (n < 2) return duplicate;
    std::vector<FaceKey> keys(n);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 1 << 16), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t i = r.begin(); i != r.end(); ++i) keys[i] = key_of(triangles[i], uint32_t(i));
    });
    tbb::parallel_sort(keys.begin(), keys.end());
    // In each run of equal vertex sets, every face but the earliest is a duplicate.
    for (size_t i = 0; i < n;) {
        size_t j = i + 1;
        while (j < n && keys[j].same_vertices(keys[i])) ++j;
        if (j - i > 1) {
            uint32_t first = keys[i].face;
            for (size_t k = i + 1; k < j; ++k) first = std::min(first, keys[k].face);
            for (size_t k = i; k < j; ++k)
                if (keys[k].face != first) duplicate[keys[k].face] = 1;
        }
        i = j;
    }
    return duplicate;
}

size_t drop_duplicate_faces(Mesh& mesh) {
    const std::vector<uint8_t> duplicate = find_duplicate_faces(mesh.triangles);
    const size_t n = mesh.triangles.size();
    const bool materials = mesh.face_materials.size() == n;
    const bool objects = mesh.face_objects.size() == n, marks = mesh.face_marks.size() == n;
    size_t kept = 0;
    for (size_t i = 0; i < n; ++i) {
        if (duplicate[i]) continue;
        mesh.triangles[kept] = mesh.triangles[i];
        if (materials) mesh.face_materials[kept] = mesh.face_materials[i];
        if (objects) mesh.face_objects[kept] = mesh.face_objects[i];
        if (marks) mesh.face_marks[kept] = mesh.face_marks[i];
        ++kept;
    }
    const size_t dropped = n - kept;
    mesh.triangles.resize(kept);
    if (materials) mesh.face_materials.resize(kept);
    if (objects) mesh.face_objects.resize(kept);
    if (marks) mesh.face_marks.resize(kept);
    return dropped;
}

}  // namespace inkshade::geometry
