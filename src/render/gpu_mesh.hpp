// A mesh on the GPU: interleaved position/normal/colour vertices and a triangle index buffer,
// plus what the line passes need, each in its own buffer so the shading pass does not fetch
// them: welded normals for the inverted hull (attribute 3) and the object id (attribute 4,
// unsigned int, read `flat`; render/welded_attributes.hpp). A textured mesh (uvs and at least
// one material texture) also gets its uvs (attribute 5) and one GL texture per distinct image;
// the vertex attributes shading models declare take locations 6 on (set_attribute).
#pragma once
#include <epoxy/gl.h>

#include <array>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "gpu/base_texture.hpp"
#include "gpu/gl_handle.hpp"
#include "inkshade/mesh.hpp"
#include "render/mtoon_textures.hpp"

namespace inkshade::render {

struct GpuVertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec3 color;
};

// CPU side of the upload: per-vertex colours from the mesh, else from its per-face materials
// (vertices shared by faces of different materials are duplicated), else white. Returns true
// when vertices were split: `triangles` and `source` (the mesh vertex of each stream vertex)
// are then filled. False: the stream is the mesh's own vertices in order, and `triangles` and
// `source` stay empty (use mesh.triangles; no copy of them, 120 MB at 10 M triangles).
// Faces keep their order.
bool build_vertex_stream(const Mesh& mesh, std::vector<GpuVertex>& vertices, std::vector<glm::uvec3>& triangles,
                         std::vector<uint32_t>& source);

class GpuMesh {
public:
    explicit GpuMesh(const Mesh& mesh);
    // All faces in one call (depth, hull and G-buffer passes).
    void draw() const;
    // The faces in `mesh`'s own order (the mesh this was made from), each with three vertices
    // of its own (attribute 0) that carry its number + 1 (attribute 4, unsigned int, read
    // `flat`): the face at each pixel for the surface fields (render/field_samples_pass.cpp),
    // numbered as the mesh is even where draw() sorts the faces by material. The buffer (16
    // bytes a corner) is made on the first call. A flat attribute instead of gl_PrimitiveID
    // takes that pass in about two thirds of the time on llvmpipe.
    void draw_face_numbers(const Mesh& mesh);

    // Uvs and a texture are uploaded: shaders read them under INKSHADE_BASE_TEXTURE.
    bool textured() const { return !textures_.empty(); }
    // Some material has MToon textures (Material::mtoon_textures): each draw_by_material range
    // binds them (render/mtoon_textures.hpp). A mesh without uvs reads them at uv (0, 0), but
    // for the matcap, read at the normal.
    bool has_mtoon_textures() const { return !mtoon_textures_.empty(); }
    // Some material carries VRM MToon values (Material::mtoon).
    bool has_material_params() const { return has_material_params_; }
    // Colours of its own: a vertex or material colour other than white, or a texture (what a
    // style's base colour does not tint: BaseColorUse::Fallback).
    bool has_own_colors() const { return has_own_colors_; }
    // The faces material by material (sorted by material when the mesh is textured or has
    // material parameters, else one range in file order, exactly as draw()). Before each range
    // its texture is bound to `texture_unit` (a white texel for materials without one), read as
    // `texels` says, when the mesh is textured, its MToon textures to the units after it (an
    // absent one as its slot's fallback; colour ones read as `texels` says, data as stored) when
    // the mesh has them, and `before` gets the range's material (null: none) and says whether
    // to draw it (mtoon's outline skips materials without one).
    void draw_by_material(GLuint texture_unit, gpu::Texels texels,
                          const std::function<bool(const Material*)>& before) const;
    // Some material is drawn without lighting (Material::unlit).
    bool has_unlit_materials() const { return has_unlit_materials_; }
    // Some material has a glTF alpha mode other than OPAQUE or glTF sides (Material::alpha_mode,
    // Material::sides): draws go material by material.
    bool has_material_rules() const { return has_material_rules_; }
    // Some material is MASK or BLEND (the variant INKSHADE_MATERIAL_ALPHA), or BLEND.
    bool has_alpha_materials() const { return has_alpha_materials_; }
    bool has_blend_materials() const { return has_blend_materials_; }

    // The ranges draw_by_material draws, one material each: the material (null: none), the
    // centre of its faces' bounding box (blended ones are sorted by it), and a draw of one range
    // binding its textures as draw_by_material does.
    size_t range_count() const { return ranges_.size(); }
    const Material* range_material(size_t range) const;
    glm::vec3 range_center(size_t range) const { return ranges_[range].center; }
    void draw_range(size_t range, GLuint texture_unit, gpu::Texels texels) const;
    // The range's material has its own MToon texture in `slot` (kMtoonTextureSlots), not the
    // slot's fallback.
    bool range_has_mtoon_texture(size_t range, int slot) const;

    // The (part, material) ids of each object id (attribute 4) from 1: the id and material AOVs.
    const std::vector<glm::uvec2>& object_parts() const { return object_parts_; }

    // The vertex attributes shading models declare (render/shading_inputs.hpp), by provider name.
    // Uploads `per_mesh_vertex`, `floats` a mesh vertex, as the buffer of attribute `name`
    // (stream vertices duplicated per material take their source vertex's values) and remembers
    // the `key` they were computed for.
    void set_attribute(const std::string& name, const std::vector<float>& per_mesh_vertex, size_t floats,
                       std::vector<float> key);
    // The key `name`'s values were uploaded with; null: none uploaded.
    const std::vector<float>* attribute_key(const std::string& name) const;
    // Where an uploaded attribute is read: `count` elements of `components` floats at locations
    // `location` on.
    struct AttributeLayout {
        std::string name;
        GLuint location = 0;
        GLint components = 1;
        int count = 1;
    };
    // Binds those attributes at their locations and turns the other declared locations off.
    static constexpr GLuint kFirstDeclaredLocation = 6;  // 0-5 are the mesh's own streams
    static constexpr GLuint kLocationCount = 16;         // what GL guarantees
    void bind_attributes(const std::vector<AttributeLayout>& layouts);

private:
    void upload_materials(const Mesh& mesh, bool has_face_materials);
    void upload_mtoon_textures(const Mesh& mesh);
    // Faces sorted by material when materials change what a draw binds, else in file order.
    void upload_indices(const Mesh& mesh, const std::vector<glm::uvec3>& faces, bool has_face_materials);
    void make_vertex_array();

    struct Range {
        size_t first = 0;  // index offset into the index buffer
        GLsizei count = 0;
        uint32_t material = 0;
        glm::vec3 center{0.0f};
    };
    gpu::GlBuffer vbo_, ibo_, hull_normal_vbo_, object_id_vbo_, uv_vbo_;
    struct Attribute {
        gpu::GlBuffer buffer;
        std::vector<float> key;
    };
    std::map<std::string, Attribute> attributes_;  // set_attribute
    gpu::GlVertexArray vao_;
    gpu::GlBuffer face_number_vbo_;  // draw_face_numbers
    gpu::GlVertexArray face_number_vao_;
    GLsizei face_number_count_ = 0;
    std::vector<uint32_t> source_;          // mesh vertex of each stream vertex (set_attribute)
    size_t stream_size_ = 0;                // vertices in the stream
    std::vector<glm::uvec2> object_parts_;  // object_parts()
    GLsizei index_count_ = 0;
    std::vector<Range> ranges_;
    std::vector<Material> materials_;         // names, colours and MToon values; no pixels
    std::vector<gpu::BaseTexture> textures_;  // each distinct image once, then the white texel
    std::vector<size_t> material_texture_;    // per material: index into textures_
    // MToon textures: each distinct image once, then white and black; per material and slot an
    // index into them.
    std::vector<gpu::BaseTexture> mtoon_textures_;
    std::vector<std::array<size_t, kMtoonTextureSlotCount>> material_mtoon_;
    bool has_material_params_ = false;
    bool has_own_colors_ = false;
    bool has_unlit_materials_ = false;
    bool has_material_rules_ = false;
    bool has_alpha_materials_ = false;
    bool has_blend_materials_ = false;
};

}  // namespace inkshade::render
