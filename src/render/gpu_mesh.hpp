// A mesh on the GPU: interleaved position/normal/colour vertices and a triangle index buffer.
#pragma once
#include <epoxy/gl.h>

#include <vector>

#include "inkshade/mesh.hpp"

namespace inkshade::render {

struct GpuVertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec3 color;
};

// CPU side of the upload: per-vertex colours from the mesh, else from its per-face materials
// (vertices shared by faces of different materials are duplicated), else white.
void build_vertex_stream(const Mesh& mesh, std::vector<GpuVertex>& vertices,
                         std::vector<glm::uvec3>& triangles);

class GpuMesh {
public:
    explicit GpuMesh(const Mesh& mesh);
    ~GpuMesh();
    GpuMesh(const GpuMesh&) = delete;
    GpuMesh& operator=(const GpuMesh&) = delete;
    void draw() const;

private:
    GLuint vao_ = 0, vbo_ = 0, ibo_ = 0;
    GLsizei index_count_ = 0;
};

}  // namespace inkshade::render
