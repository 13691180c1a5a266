// Integer hash of 3-D lattice cells for cellular patterns (voronoi, stipple): pcg3d from
// Jarzynski & Olano, "Hash Functions for GPU Rendering", JCGT 9(3), 2020. Integer arithmetic
// only, so the tests reproduce it bit for bit on the CPU (tests/render/cell_hash.hpp).
uvec3 pcg3d(uvec3 v) {
    v = v * 1664525u + 1013904223u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v ^= v >> 16u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    return v;
}

// Three uniform values in [0, 1) (24-bit mantissas: exact in float on CPU and GPU).
vec3 hash_to_unit(uvec3 h) { return vec3(h >> 8u) * (1.0 / 16777216.0); }

// The jittered feature point of cell c (Worley 1996: one point per cell), in cell units.
vec3 cell_point(ivec3 c) { return vec3(c) + hash_to_unit(pcg3d(uvec3(c))); }

// A cheaper one-word hash of a cell for patterns that need no CPU twin (stipple): the cell's
// coordinates times kCellHashMul, xor-ed (so neighbouring cells cost an add), then the
// lowbias32 finaliser (C. Wellons, "Hash function prospector", 2018).
const uvec3 kCellHashMul = uvec3(0x8da6b343u, 0xd8163841u, 0xcb1ab31fu);
uint cell_hash_mix(uint h) {
    h ^= h >> 16u;
    h *= 0x7feb352du;
    h ^= h >> 15u;
    h *= 0x846ca68bu;
    h ^= h >> 16u;
    return h;
}

// The four bytes of h as values in [0, 1).
vec4 bytes_to_unit(uint h) { return vec4(uvec4(h >> 24u, h >> 16u, h >> 8u, h) & 255u) * (1.0 / 256.0); }
