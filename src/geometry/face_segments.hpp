// The parallel loop every per-face line extractor runs (contours, suggestive contours, ridges),
// and the visibility test's gathering of the faces around the contours:
// faces in fixed-size blocks on TBB tasks, each block collecting its items in face order, the
// blocks joined in order, so the output is in face order whatever the thread count.
#pragma once
#include <tbb/parallel_for.h>

#include <algorithm>
#include <utility>
#include <vector>

#include "geometry/contours.hpp"

namespace inkshade::geometry {

constexpr size_t kFaceGrain = 16384;  // faces per TBB task: small meshes stay on one thread

// Calls per_face(f, out) for f in [0, face_count); per_face appends what face f gives (segments,
// face indices, ...) to out.
template <class T, class PerFace>
std::vector<T> collect_per_face(size_t face_count, PerFace&& per_face) {
    const size_t blocks = (face_count + kFaceGrain - 1) / kFaceGrain;
    std::vector<std::vector<T>> found(blocks);
    tbb::parallel_for(size_t(0), blocks, [&](size_t block) {
        const size_t end = std::min(face_count, (block + 1) * kFaceGrain);
        for (size_t f = block * kFaceGrain; f < end; ++f) per_face(f, found[block]);
    });
    size_t total = 0;
    for (const auto& list : found) total += list.size();
    std::vector<T> out;
    out.reserve(total);
    for (const auto& list : found) out.insert(out.end(), list.begin(), list.end());
    return out;
}

// The line extractors' case: per_face(f, out) appends the face's segments.
template <class PerFace>
std::vector<LineSegment> collect_face_segments(size_t face_count, PerFace&& per_face) {
    return collect_per_face<LineSegment>(face_count, std::forward<PerFace>(per_face));
}

}  // namespace inkshade::geometry
