// Deterministic noise along a stroke's arc length, for the thickness noise and the sketchy
// passes (stroke_thickness.hpp, sketch_passes.hpp): the same seed and stream give the same
// values on every machine and run, another seed other values.
#pragma once
#include <cstdint>

namespace inkshade::geometry {

// Smooth 1D value noise in [-1, 1]: pseudo-random values at the integers, hashed from (seed,
// stream, i), blended with Perlin's quintic fade (Perlin 2002, "Improving Noise"), so the
// noise is C2 and a convex blend of lattice values: never outside [-1, 1]. `stream` tells
// apart independent noises of one seed (per path, per pass, per axis).
float value_noise(uint32_t seed, uint32_t stream, double x);

// A stream number for (a, b, c): hashes, so nearby triples give unrelated streams.
uint32_t noise_stream(uint32_t a, uint32_t b, uint32_t c = 0);

}  // namespace inkshade::geometry
