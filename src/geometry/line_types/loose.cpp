// `loose`: the file's line primitives (OBJ `l`, glTF LINES, LINE_STRIP, LINE_LOOP;
// extract_loose_lines), hidden where a surface lies in front of them.
#include "geometry/line_types/object_line_registry.hpp"
#include "geometry/loose_lines.hpp"

namespace inkshade::geometry {

namespace {

std::vector<LineSegment> extract(MeshLineData& data, const LineView&, const LineSettings&) {
    return extract_loose_lines(data.mesh());
}

const ObjectLineRegistration registration{
    {.name = "loose",
     .summary = "loose lines: the file's line primitives (OBJ l, glTF LINES, LINE_STRIP, LINE_LOOP)",
     .params = object_line_params(glm::vec3(0.0f), 1.0f, {}, 0.0f)},
    extract};

}  // namespace

}  // namespace inkshade::geometry
