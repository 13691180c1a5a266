#include "render/gpu_mesh.hpp"

#include <cstddef>
#include <unordered_map>

namespace inkshade::render {

void build_vertex_stream(const Mesh& mesh, std::vector<GpuVertex>& vertices,
                         std::vector<glm::uvec3>& triangles) {
    const size_t n = mesh.positions.size();
    auto normal_of = [&](size_t i) { return i < mesh.normals.size() ? mesh.normals[i] : glm::vec3(0, 0, 1); };
    const bool per_face = mesh.colors.empty() && !mesh.materials.empty() &&
                          mesh.face_materials.size() == mesh.triangles.size();
    if (!per_face) {
        vertices.resize(n);
        for (size_t i = 0; i < n; ++i)
            vertices[i] = {mesh.positions[i], normal_of(i),
                           mesh.colors.size() == n ? mesh.colors[i] : glm::vec3(1.0f)};
        triangles = mesh.triangles;
        return;
    }
    // Split vertices by (vertex, material) so each face gets its material's colour.
    vertices.clear();
    vertices.reserve(n);
    triangles.resize(mesh.triangles.size());
    std::unordered_map<uint64_t, uint32_t> remap;
    remap.reserve(n * 2);
    for (size_t f = 0; f < mesh.triangles.size(); ++f) {
        uint32_t mat = mesh.face_materials[f];
        glm::vec3 color = mat < mesh.materials.size() ? mesh.materials[mat].diffuse : glm::vec3(1.0f);
        for (int k = 0; k < 3; ++k) {
            uint32_t v = mesh.triangles[f][k];
            uint64_t key = (uint64_t(mat) << 32) | v;
            auto [it, inserted] = remap.try_emplace(key, uint32_t(vertices.size()));
            if (inserted) vertices.push_back({mesh.positions[v], normal_of(v), color});
            triangles[f][k] = it->second;
        }
    }
}

GpuMesh::GpuMesh(const Mesh& mesh) {
    std::vector<GpuVertex> vertices;
    std::vector<glm::uvec3> triangles;
    build_vertex_stream(mesh, vertices, triangles);
    index_count_ = GLsizei(triangles.size() * 3);

    glCreateBuffers(1, &vbo_);
    glNamedBufferStorage(vbo_, GLsizeiptr(vertices.size() * sizeof(GpuVertex)), vertices.data(), 0);
    glCreateBuffers(1, &ibo_);
    glNamedBufferStorage(ibo_, GLsizeiptr(triangles.size() * sizeof(glm::uvec3)), triangles.data(), 0);

    glCreateVertexArrays(1, &vao_);
    glVertexArrayVertexBuffer(vao_, 0, vbo_, 0, sizeof(GpuVertex));
    glVertexArrayElementBuffer(vao_, ibo_);
    const GLuint offsets[3] = {offsetof(GpuVertex, position), offsetof(GpuVertex, normal),
                               offsetof(GpuVertex, color)};
    for (GLuint a = 0; a < 3; ++a) {
        glEnableVertexArrayAttrib(vao_, a);
        glVertexArrayAttribFormat(vao_, a, 3, GL_FLOAT, GL_FALSE, offsets[a]);
        glVertexArrayAttribBinding(vao_, a, 0);
    }
}

GpuMesh::~GpuMesh() {
    glDeleteVertexArrays(1, &vao_);
    glDeleteBuffers(1, &vbo_);
    glDeleteBuffers(1, &ibo_);
}

void GpuMesh::draw() const {
    glBindVertexArray(vao_);
    glDrawElements(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr);
}

}  // namespace inkshade::render
