// Integer hash of 3-D lattice cells for cellular patterns (voronoi, stipple). Integer arithmetic
// only, so the tests reproduce it bit for bit on the CPU (tests/render/cell_hash.hpp).
// One 32-bit word per cell: the coordinates times kCellHashMul, xor-ed, then the lowbias32
// finaliser (C. Wellons, "Hash function prospector", 2018): 2 multiplies a cell (pcg3d, used
// before, took 9), and the products of neighbouring cells differ by an add, so a search over
// the 2x2x2 cells around a point computes them once (a = base * kCellHashMul, b = a + kCellHashMul).
const uvec3 kCellHashMul = uvec3(0x8da6b343u, 0xd8163841u, 0xcb1ab31fu);

uint cell_hash_mix(uint h) {
    h ^= h >> 16u;
    h *= 0x7feb352du;
    h ^= h >> 15u;
    h *= 0x846ca68bu;
    h ^= h >> 16u;
    return h;
}

uint cell_hash(ivec3 c) {
    uvec3 k = uvec3(c) * kCellHashMul;
    return cell_hash_mix(k.x ^ k.y ^ k.z);
}

// Three values in [0, 1) from the top 30 bits of h, 10 bits each (exact in float). Converted
// through int: llvmpipe has no single-instruction unsigned-to-float conversion.
vec3 cell_jitter(uint h) { return vec3(ivec3(uvec3(h >> 22u, h >> 12u, h >> 2u) & 1023u)) * (1.0 / 1024.0); }

// The four bytes of h as values in [0, 1).
vec4 bytes_to_unit(uint h) { return vec4(ivec4(uvec4(h >> 24u, h >> 16u, h >> 8u, h) & 255u)) * (1.0 / 256.0); }

// Voronoi's feature points lie within kCellJitter of their cell's centre along each axis
// (Worley 1996 jitters over the whole cell). At <= 0.25 the nearest point is always among the
// 2x2x2 cells whose centres surround x; at 0.3 the cells look closer to Worley's and the
// 2x2x2 search misses the nearest point for ~6e-5 of all positions (docs/shading.md).
const float kCellJitter = 0.3;
vec3 cell_offset(uint h) { return (0.5 - kCellJitter) + (2.0 * kCellJitter) * cell_jitter(h); }

// The jittered feature point of cell c (one point per cell), in cell units.
vec3 cell_point(ivec3 c) { return vec3(c) + cell_offset(cell_hash(c)); }
