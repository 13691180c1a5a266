// Loose lines (line type `loose`): the line primitives of a file (OBJ `l`, glTF LINES,
// LINE_STRIP, LINE_LOOP), kept in Mesh::line_segments, drawn as lines of their own with the
// same exact visibility against the surfaces as every object-space type.
#pragma once
#include <vector>

#include "geometry/contours.hpp"
#include "inkshade/mesh.hpp"

namespace inkshade::geometry {

// One segment per entry of mesh.line_segments, in order: ends keyed vertex_key of their vertex
// (segments sharing a vertex chain, as creases do), on no face (face = face_b = kNoFace: every
// surface can hide them). Entries with an index out of range or equal ends give none.
std::vector<LineSegment> extract_loose_lines(const Mesh& mesh);

}  // namespace inkshade::geometry
