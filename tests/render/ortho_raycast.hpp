// What each pixel of an orthographic view from any direction sees, recovered on the CPU: the
// nearest triangle under a pixel point, its barycentric weights and the interpolated vertex
// normal (what the GPU's fragment stage gets). Triangles are binned by their image bounding box
// so meshes of 100k triangles cast quickly.
#pragma once
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "inkshade/camera.hpp"
#include "inkshade/mesh.hpp"

namespace inkshade::test {

struct SurfaceHit {
    int triangle = -1;
    float t = 0.0f;          // distance along the view direction
    glm::vec3 point{0.0f};   // world position
    glm::vec3 normal{0.0f};  // interpolated vertex normal, normalised
};

class OrthoRaycaster {
public:
    // `camera` must be orthographic; the image is width x height pixels.
    OrthoRaycaster(const Mesh& mesh, const Camera& camera, int width, int height)
        : mesh_(mesh), width_(width), height_(height) {
        forward_ = glm::normalize(camera.target - camera.eye);
        right_ = glm::normalize(glm::cross(forward_, camera.up));
        up_ = glm::cross(right_, forward_);
        eye_ = camera.eye;
        half_h_ = 0.5f * camera.ortho_height;
        half_w_ = half_h_ * float(width) / float(height);
        cols_ = (width + kCell - 1) / kCell;
        rows_ = (height + kCell - 1) / kCell;
        cells_.resize(size_t(cols_) * size_t(rows_));
        for (size_t f = 0; f < mesh.triangles.size(); ++f) {
            glm::vec2 lo(1e30f), hi(-1e30f);
            for (int k = 0; k < 3; ++k) {
                const glm::vec2 q = to_pixel(mesh.positions[mesh.triangles[f][k]]);
                lo = glm::min(lo, q);
                hi = glm::max(hi, q);
            }
            const int x0 = std::max(0, int(std::floor(lo.x)) / kCell),
                      x1 = std::min(cols_ - 1, int(std::floor(hi.x)) / kCell);
            const int y0 = std::max(0, int(std::floor(lo.y)) / kCell),
                      y1 = std::min(rows_ - 1, int(std::floor(hi.y)) / kCell);
            for (int y = y0; y <= y1; ++y)
                for (int x = x0; x <= x1; ++x) cells_[size_t(y) * cols_ + x].push_back(uint32_t(f));
        }
    }

    glm::vec3 view_direction() const { return forward_; }
    glm::vec3 right() const { return right_; }
    glm::vec3 up() const { return up_; }

    // Image position (pixels, top-left origin) of a world point.
    glm::vec2 to_pixel(const glm::vec3& p) const {
        const glm::vec3 q = p - eye_;
        return {(glm::dot(q, right_) / half_w_ + 1.0f) * 0.5f * float(width_),
                (1.0f - glm::dot(q, up_) / half_h_) * 0.5f * float(height_)};
    }

    // The surface under image point (x, y) in pixels, or nullopt.
    std::optional<SurfaceHit> cast(float x, float y) const {
        if (x < 0 || y < 0 || x >= float(width_) || y >= float(height_)) return std::nullopt;
        const glm::vec3 origin = eye_ + right_ * ((x / float(width_) * 2.0f - 1.0f) * half_w_) +
                                 up_ * ((1.0f - y / float(height_) * 2.0f) * half_h_);
        const auto& cell = cells_[size_t(int(y) / kCell) * cols_ + size_t(int(x) / kCell)];
        std::optional<SurfaceHit> best;
        for (uint32_t f : cell) {
            const glm::uvec3 tri = mesh_.triangles[f];
            const glm::vec3 a = mesh_.positions[tri.x], b = mesh_.positions[tri.y], c = mesh_.positions[tri.z];
            const glm::vec3 e1 = b - a, e2 = c - a, pv = glm::cross(forward_, e2);
            const float det = glm::dot(e1, pv);
            if (std::abs(det) < 1e-14f) continue;
            const glm::vec3 tv = origin - a;
            const float u = glm::dot(tv, pv) / det;
            if (u < 0 || u > 1) continue;
            const glm::vec3 qv = glm::cross(tv, e1);
            const float v = glm::dot(forward_, qv) / det;
            if (v < 0 || u + v > 1) continue;
            const float t = glm::dot(e2, qv) / det;
            if (best && t >= best->t) continue;
            const glm::vec3 n =
                (1 - u - v) * mesh_.normals[tri.x] + u * mesh_.normals[tri.y] + v * mesh_.normals[tri.z];
            best = SurfaceHit{int(f), t, origin + t * forward_, glm::normalize(n)};
        }
        return best;
    }

    // The hit at the pixel centre when the whole pixel (its corners) lies on one smooth sheet of
    // the surface: no silhouette, no overlap edge inside it. Else nullopt.
    std::optional<SurfaceHit> interior(int px, int py) const {
        auto centre = cast(float(px) + 0.5f, float(py) + 0.5f);
        if (!centre) return std::nullopt;
        for (float dx : {-0.5f, 1.5f})
            for (float dy : {-0.5f, 1.5f}) {
                auto h = cast(float(px) + dx, float(py) + dy);
                if (!h || std::abs(h->t - centre->t) > 0.05f || glm::dot(h->normal, centre->normal) < 0.9f)
                    return std::nullopt;
            }
        return centre;
    }

private:
    static constexpr int kCell = 8;
    const Mesh& mesh_;
    int width_, height_;
    glm::vec3 eye_, forward_, right_, up_;
    float half_w_, half_h_;
    int cols_, rows_;
    std::vector<std::vector<uint32_t>> cells_;
};

}  // namespace inkshade::test
