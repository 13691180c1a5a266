// A mesh on the GPU: interleaved position/normal/colour vertices and a triangle index buffer,
// plus what the line passes need, each in its own buffer so the shading pass does not fetch
// them: welded normals for the inverted hull (attribute 3) and the object id (attribute 4,
// unsigned int, read `flat`; render/welded_attributes.hpp).
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
// (vertices shared by faces of different materials are duplicated), else white. `source`, when
// given, receives the mesh vertex each stream vertex came from. Faces keep their order.
void build_vertex_stream(const Mesh& mesh, std::vector<GpuVertex>& vertices,
                         std::vector<glm::uvec3>& triangles, std::vector<uint32_t>* source = nullptr);

class GpuMesh {
public:
    explicit GpuMesh(const Mesh& mesh);
    ~GpuMesh();
    GpuMesh(const GpuMesh&) = delete;
    GpuMesh& operator=(const GpuMesh&) = delete;
    void draw() const;

private:
    GLuint vao_ = 0, vbo_ = 0, ibo_ = 0, hull_normal_vbo_ = 0, object_id_vbo_ = 0;
    GLsizei index_count_ = 0;
};

}  // namespace inkshade::render
