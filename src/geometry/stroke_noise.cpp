#include "geometry/stroke_noise.hpp"

#include <cmath>

namespace inkshade::geometry {

namespace {

// SplitMix64's finaliser (Steele, Lea & Flood 2014, "Fast Splittable Pseudorandom Number
// Generators"): a bijective mix whose every output bit depends on every input bit.
uint64_t mix64(uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

// The lattice value at integer i, uniform in [-1, 1].
double lattice(uint32_t seed, uint32_t stream, int64_t i) {
    const uint64_t h = mix64(mix64((uint64_t(seed) << 32) | stream) ^ uint64_t(i) * 0x9e3779b97f4a7c15ull);
    return double(h >> 11) * (2.0 / double(1ull << 53)) - 1.0;
}

}  // namespace

float value_noise(uint32_t seed, uint32_t stream, double x) {
    if (!std::isfinite(x)) return 0.0f;
    const double cell = std::floor(x);
    const double f = x - cell;
    const double fade = f * f * f * (f * (f * 6.0 - 15.0) + 10.0);
    const auto i = int64_t(cell);
    const double a = lattice(seed, stream, i), b = lattice(seed, stream, i + 1);
    return float(a + (b - a) * fade);
}

uint32_t noise_stream(uint32_t a, uint32_t b, uint32_t c) { return uint32_t(mix64(mix64(mix64(a) ^ b) ^ c)); }

}  // namespace inkshade::geometry
