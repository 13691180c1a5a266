// The surface-field AOVs at each pixel (docs/aov.md): the per-vertex values of the fields pass
// (render/field_vertices.hpp) interpolated over the visible triangle at the pixel centre, as a
// rasteriser interpolates vertex attributes (perspective-correct), with the barycentric
// coordinates of the point where the pixel's ray meets the triangle the aov pass drew there.
#pragma once
#include <cstdint>
#include <vector>

#include "render/frame.hpp"

namespace inkshade::render {

// Fills `out`'s fields among `want` (AovSet::fields()) and out.field_scales from `faces`
// (width x height, top row first: the face drawn at the pixel + 1, 0 = background).
void interpolate_fields(const Frame& frame, AovSet want, const std::vector<uint32_t>& faces, AovImages& out);

// numpy.percentile(|v|, 90) (linear interpolation between the two nearest ranks) over the
// pixels where faces is not 0; 0 without such a pixel. `channels` floats per pixel, the
// first read.
float visible_p90(const std::vector<float>& values, const std::vector<uint32_t>& faces, int channels = 1);

}  // namespace inkshade::render
