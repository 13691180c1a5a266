#include "geometry/intersection_priority.hpp"

#include <unordered_map>
#include <utility>

#include "geometry/connected_objects.hpp"

namespace inkshade::geometry {

std::vector<uint32_t> object_numbers(const std::vector<uint32_t>& face_objects) {
    std::unordered_map<uint32_t, uint32_t> number;
    std::vector<uint32_t> out(face_objects.size(), kNoObject);
    for (size_t f = 0; f < face_objects.size(); ++f)
        if (face_objects[f] != kNoObject)
            out[f] = number.try_emplace(face_objects[f], uint32_t(number.size())).first->second;
    return out;
}

void assign_intersection_owners(std::vector<LineSegment>& segments, const std::vector<uint32_t>& objects,
                                const std::vector<float>& priorities) {
    const auto priority = [&](uint32_t face) {
        const uint32_t k = face < objects.size() ? objects[face] : kNoObject;
        return k < priorities.size() ? priorities[k] : 0.0f;
    };
    for (LineSegment& s : segments) {
        if (s.face_b == kNoFace) continue;
        const float a = priority(s.face), b = priority(s.face_b);
        if (b > a) std::swap(s.face, s.face_b);
        s.owned = a != b;
    }
}

}  // namespace inkshade::geometry
