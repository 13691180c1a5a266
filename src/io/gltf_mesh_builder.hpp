// A glTF scene's mesh instances appended to one Mesh (glTF 2.0 section 3.7): TRIANGLES,
// TRIANGLE_STRIP and TRIANGLE_FAN primitives (points skipped, and counted; lines kept as
// Mesh::line_segments, placed by their node but not deformed by a pose), each
// deformed by the pose, placed by its world transform (normals by the inverse transpose; a
// mirroring transform flips the winding so front faces stay counter-clockwise), with its
// material, object (its node's name) and face marks (_FACEMARK). Attributes present in only some primitives are
// completed (uvs with 0, colours with the material colour) or dropped (normals: load_mesh computes them).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "inkshade/mesh.hpp"
#include "io/gltf_accessors.hpp"
#include "io/gltf_materials.hpp"
#include "io/gltf_scene_nodes.hpp"

namespace tinygltf {
class Model;
struct Primitive;
}  // namespace tinygltf

namespace inkshade::io {

class GltfPose;

class GltfMeshBuilder {
public:
    GltfMeshBuilder(const tinygltf::Model& model, const std::string& path, Mesh& mesh,
                    const GltfAccessorReader& reader);

    // A mesh instance, each primitive deformed by the pose (morph targets, skin) first. Throws
    // InputError(path, ...) for a bad accessor or a scene over the vertex or triangle limits.
    void add(const GltfInstance& instance, const GltfPose& pose);

    // Drops incomplete normals and warns about skipped primitives.
    void finish();
    size_t skipped() const { return skipped_; }  // point primitives

private:
    // The optional vertex attributes of a primitive, `n` elements each where present.
    struct Attributes {
        std::vector<float> normals, uvs, colours;
        int colour_components = 0;
    };
    struct Range {
        size_t end;  // one past the primitive's last vertex
        glm::vec3 colour;
    };

    void add_primitive(const tinygltf::Primitive& prim, const GltfInstance& instance, const GltfPose& pose,
                       const std::string& where);
    void add_lines(const tinygltf::Primitive& prim, const GltfInstance& instance, int mode, const std::string& where);
    std::vector<glm::uvec3> triangles(const tinygltf::Primitive& prim, int mode, size_t n, bool mirror,
                                      const std::string& where);
    // The primitive's vertex indices: its index accessor's (checked against `n`), else 0..n-1.
    std::vector<uint32_t> vertex_indices(const tinygltf::Primitive& prim, size_t n, const std::string& where);
    Attributes attributes(const tinygltf::Primitive& prim, size_t n, const std::string& where);
    uint32_t object_of(int node);
    std::vector<uint8_t> face_marks(const tinygltf::Primitive& prim, const std::vector<glm::uvec3>& tris, size_t n,
                                    const std::string& where);
    void append_positions_and_normals(const std::vector<float>& positions, const std::vector<float>& normals, size_t n,
                                      const glm::dmat4& transform);
    void append_uvs_and_colours(const Attributes& a, size_t base, size_t n, const glm::vec3& base_colour);

    const tinygltf::Model& model_;
    const std::string& path_;
    Mesh& mesh_;
    const GltfAccessorReader& reader_;
    GltfMaterialTable materials_;
    std::vector<Range> ranges_;
    bool normals_complete_ = true;
    size_t skipped_ = 0;
};

}  // namespace inkshade::io
