// The indexed triangle mesh every part of Inkshade works on.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace inkshade {

struct Material {
    std::string name;
    glm::vec3 diffuse{0.8f, 0.8f, 0.8f};  // MTL Kd / base colour, linear as written in the file
};

struct BoundingBox {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
    glm::vec3 center() const { return 0.5f * (min + max); }
    float diagonal() const { return glm::length(max - min); }
};

struct Mesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::uvec3> triangles;     // indices into positions, counter-clockwise = front
    std::vector<glm::vec3> normals;        // per vertex; empty = compute (angle-weighted)
    std::vector<glm::vec3> colors;         // per vertex RGB in [0,1]; empty = material colour
    std::vector<glm::vec2> uvs;            // per vertex; may be empty
    std::vector<Material> materials;       // may be empty (default material)
    std::vector<uint32_t> face_materials;  // per triangle index into materials; may be empty
    bool welded = false;                   // true when duplicate positions were merged

    size_t vertex_count() const { return positions.size(); }
    size_t triangle_count() const { return triangles.size(); }
    BoundingBox bounds() const;
};

}  // namespace inkshade
