// Intersection priority (Blender's Line Art: an object's "intersection priority"): the line where
// two objects cross belongs to the object of higher priority, so it is drawn with that object's
// lines. Here an intersection segment's owner is the object of its `face` (the other surface is
// `face_b`); objects are the mesh's connected pieces (connected_objects.hpp), numbered 0, 1, 2,
// … in the order of their first face.
#pragma once
#include <cstdint>
#include <vector>

#include "geometry/contours.hpp"

namespace inkshade::geometry {

// Per face, the number of its object: the labels of face_objects renumbered 0, 1, 2, … in the
// order of their first face (kNoObject stays kNoObject).
std::vector<uint32_t> object_numbers(const std::vector<uint32_t>& face_objects);

// Swaps face and face_b of each segment whose face_b's object has the higher priority
// (`priorities[k]` for object k, 0 past the list), so that `face` is on the owner, and marks it
// `owned` when the priorities differ (a line set then takes it by its owner's face alone, as
// Line Art gives the line to the owner's collection); on a tie the segment stays as extracted
// (face < face_b) and belongs to both objects. `objects`: object_numbers, one per face.
void assign_intersection_owners(std::vector<LineSegment>& segments, const std::vector<uint32_t>& objects,
                                const std::vector<float>& priorities);

}  // namespace inkshade::geometry
