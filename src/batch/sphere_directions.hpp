// Deterministic sets of unit directions for view sets (parse_views: fibonacci, ico, random), in
// the camera math's frame: +y is the up axis, azimuth 0 looks from +z and 90 from +x
// (CameraOptions), so a direction d is the view from azimuth atan2(d.x, d.z), elevation asin(d.y).
#pragma once
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace inkshade::batch {

// The Fibonacci lattice of n points (Gonzalez 2010, "Measurement of areas on a sphere using
// Fibonacci and latitude-longitude lattices", written for any n rather than 2N + 1): point i
// has up coordinate y_i = 1 - (2i + 1) / n (equal-area latitude bands, each point at its band's
// centre) and azimuth i times the golden angle pi (3 - sqrt 5) radians (137.5078 degrees),
// reduced to [0, 2 pi). Point 0 is nearest the top.
std::vector<glm::dvec3> fibonacci_directions(int n);

// The vertices of an icosahedron with one vertex at each pole (+y, -y) and two rings of five at
// elevation +-atan(1/2), the upper ring at azimuths 0, 72, ..., the lower at 36, 108, ...; each
// subdivision splits every triangle into four at its edge midpoints, pushed out to the sphere.
// 10 * 4^level + 2 vertices: the 12 of the icosahedron first, then each level's new ones in
// the order their edges are met (faces in order, each face's edges in order).
std::vector<glm::dvec3> icosphere_directions(int level);

// SplitMix64 (Steele, Lea, Flood 2014, "Fast splittable pseudorandom number generators"; the
// seeding generator of Vigna's xoshiro): the same sequence on every platform and library, unlike
// std::uniform_real_distribution.
class SplitMix64 {
public:
    explicit SplitMix64(uint64_t seed) : state_(seed) {}
    uint64_t next();
    // Uniform in [0, 1): the top 53 bits as a double's mantissa.
    double uniform() { return double(next() >> 11) * 0x1.0p-53; }

private:
    uint64_t state_;
};

// A direction uniform on the sphere (Archimedes' hat-box theorem: y uniform in [-1, 1], azimuth
// uniform in [0, 2 pi)), from two draws of `random`: y = 1 - 2 u1, azimuth = 2 pi u2.
glm::dvec3 uniform_direction(SplitMix64& random);

// Azimuth and elevation in degrees of the view from direction d (unit): atan2(d.x, d.z) in
// [0, 360), asin(d.y).
glm::dvec2 azimuth_elevation(const glm::dvec3& d);

}  // namespace inkshade::batch
