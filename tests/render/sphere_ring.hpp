// Measuring an outline ring around the unit sphere (hull, threejs-outline): the surface is
// green, the line blue, the background white; rings are walked outwards from the image centre.
#pragma once
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "inkshade/camera.hpp"
#include "inkshade/image.hpp"

namespace inkshade::test {

enum class Kind { Surface, Line, Background };
// Mixed (anti-aliased) pixels count as their dominant part.
inline Kind kind_of(const uint8_t* p) {
    if (p[0] > 128) return Kind::Background;  // white
    return p[1] > p[2] ? Kind::Surface : Kind::Line;
}

struct Ring {
    float inner = 0, outer = 0;  // pixels from the image centre
};

// Walks outwards from `centre` along `angle` in quarter pixels; the first radius where the
// pixel stops being surface and the first where it becomes background.
inline Ring ring_along(const Image& img, glm::vec2 centre, float angle) {
    Ring r{-1, -1};
    const glm::vec2 d(std::cos(angle), std::sin(angle));
    for (float t = 0; t < float(img.width); t += 0.25f) {
        const glm::vec2 q = centre + t * d;
        const int x = int(std::floor(q.x)), y = int(std::floor(q.y));
        if (x < 0 || y < 0 || x >= img.width || y >= img.height) break;
        const Kind k = kind_of(img.pixel(x, y));
        if (r.inner < 0 && k != Kind::Surface) r.inner = t;
        if (k == Kind::Background) {
            r.outer = t;
            break;
        }
    }
    return r;
}

// Checks the ring around the image centre at 32 angles against [inner, outer] (pixels) within 1 px.
inline void expect_ring(const Image& img, float inner, float outer, const std::string& what) {
    const glm::vec2 centre(0.5f * float(img.width), 0.5f * float(img.height));
    for (int i = 0; i < 32; ++i) {
        const float a = 2.0f * float(M_PI) * (float(i) + 0.3f) / 32.0f;
        const Ring r = ring_along(img, centre, a);
        EXPECT_NEAR(r.inner, inner, 1.0f) << what << " angle " << a;
        EXPECT_NEAR(r.outer, outer, 1.0f) << what << " angle " << a;
    }
}

// A 30° perspective camera on the +z axis looking at the origin.
inline Camera perspective(float distance) {
    Camera c;
    c.eye = {0, 0, distance};
    c.fov_degrees = 30.0f;
    c.near_plane = 0.5f;
    c.far_plane = 50.0f;
    return c;
}

// Pixels from the image centre to the unit sphere's silhouette (size x size image; perspective:
// the silhouette cone's half-angle tan = 1 / sqrt(d^2 - 1)).
inline float silhouette_radius(const Camera& c, int size) {
    if (c.orthographic) return float(size) / c.ortho_height;
    const float d = glm::length(c.eye);
    return 1.0f / std::sqrt(d * d - 1.0f) / std::tan(glm::radians(0.5f * c.fov_degrees)) * 0.5f * float(size);
}

}  // namespace inkshade::test
