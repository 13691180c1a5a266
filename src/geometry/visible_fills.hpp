// The visible faces of a mesh as filled image regions, one per material: the fills the SVG
// writer puts under the strokes (`--svg-fill`, as the Freestyle SVG exporter's fill option).
#pragma once
#include <optional>
#include <vector>

#include "inkshade/camera.hpp"
#include "inkshade/line_drawing.hpp"
#include "inkshade/mesh.hpp"
#include "inkshade/section_plane.hpp"

namespace inkshade::geometry {

// Exact in the image, up to 1/1024 px: each face's visible part is its projection minus the
// parts of the faces in front of it where their projections overlap (two faces that do not
// cross in space keep one depth order over their whole overlap, which is convex, so one test
// at its centroid decides), then the parts are joined per material. Faces on the cut-away
// side of `section` and in front of the near plane are clipped off first; on a closed mesh
// (is_closed_outward) without a section, back faces are skipped, hidden by the
// front ones.
// Faces that cross each other are ordered at the centroid of their overlap. `base_color`
// fills a mesh without materials.
std::vector<FillRegion> visible_fills(const Mesh& mesh, const Camera& camera, int width, int height,
                                      const std::optional<SectionPlane>& section, glm::vec3 base_color);

}  // namespace inkshade::geometry
