#include "render/gpu_mesh.hpp"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <map>
#include <numeric>
#include <unordered_map>

#include "render/welded_attributes.hpp"

namespace inkshade::render {

bool build_vertex_stream(const Mesh& mesh, std::vector<GpuVertex>& vertices, std::vector<glm::uvec3>& triangles,
                         std::vector<uint32_t>& source) {
    const size_t n = mesh.positions.size();
    auto normal_of = [&](size_t i) { return i < mesh.normals.size() ? mesh.normals[i] : glm::vec3(0, 0, 1); };
    const bool per_face =
        mesh.colors.empty() && !mesh.materials.empty() && mesh.face_materials.size() == mesh.triangles.size();
    const bool hard_edges = mesh.has_hard_edges();
    if (!per_face && !hard_edges) {
        vertices.resize(n);
        for (size_t i = 0; i < n; ++i)
            vertices[i] = {mesh.positions[i], normal_of(i), mesh.colors.size() == n ? mesh.colors[i] : glm::vec3(1.0f)};
        triangles.clear();
        source.clear();
        return false;
    }
    // Split vertices by (vertex, material) so each face gets its material's colour, and by
    // shading normal at hard edges (a shading normal id belongs to one vertex, so it stands for
    // the vertex in the key).
    vertices.clear();
    vertices.reserve(n);
    source.clear();
    triangles.resize(mesh.triangles.size());
    std::unordered_map<uint64_t, uint32_t> remap;
    remap.reserve(n * 2);
    for (size_t f = 0; f < mesh.triangles.size(); ++f) {
        const uint32_t mat = per_face ? mesh.face_materials[f] : 0;
        glm::vec3 color(1.0f);
        if (per_face) color = mat < mesh.materials.size() ? mesh.materials[mat].diffuse : glm::vec3(1.0f);
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = mesh.triangles[f][k];
            const uint32_t shading = hard_edges ? mesh.shading_normal_id(f, k) : v;
            const uint64_t key = (uint64_t(mat) << 32) | shading;
            auto [it, inserted] = remap.try_emplace(key, uint32_t(vertices.size()));
            if (inserted) {
                if (!per_face && mesh.colors.size() == n) color = mesh.colors[v];
                vertices.push_back({mesh.positions[v], hard_edges ? mesh.shading_normal(f, k) : normal_of(v), color});
                source.push_back(v);
            }
            triangles[f][k] = it->second;
        }
    }
    return true;
}

namespace {

// An immutable buffer holding `size` bytes from `data`.
gpu::GlBuffer upload_buffer(GLsizeiptr size, const void* data) {
    gpu::GlBuffer buffer = gpu::GlBuffer::create();
    glNamedBufferStorage(buffer.id(), size, data, 0);
    return buffer;
}

}  // namespace

GpuMesh::GpuMesh(const Mesh& mesh) {
    // Materials first, so that a texture that fails leaves no buffers behind.
    const bool has_face_materials = !mesh.materials.empty() && mesh.face_materials.size() == mesh.triangles.size();
    upload_materials(mesh, has_face_materials);

    // Each CPU-side array is uploaded and freed before the next one is built: at 10 M
    // triangles they add up to about 500 MB beside the GL driver's own copies (docs/benchmarks.md).
    std::vector<GpuVertex> vertices;
    std::vector<glm::uvec3> triangles;
    std::vector<uint32_t> source;
    const bool split = build_vertex_stream(mesh, vertices, triangles, source);
    const std::vector<glm::uvec3>& faces = split ? triangles : mesh.triangles;
    auto source_of = [&](size_t i) { return split ? source[i] : uint32_t(i); };
    index_count_ = GLsizei(faces.size() * 3);
    const size_t stream_size = vertices.size();
    stream_size_ = stream_size;
    has_own_colors_ = textured() || std::any_of(vertices.begin(), vertices.end(),
                                                [](const GpuVertex& v) { return v.color != glm::vec3(1.0f); });
    vbo_ = upload_buffer(GLsizeiptr(vertices.size() * sizeof(GpuVertex)), vertices.data());
    std::vector<GpuVertex>().swap(vertices);

    {
        const std::vector<glm::vec3> welded = welded_vertex_normals(mesh);
        std::vector<glm::vec3> hull_normals(stream_size);
        for (size_t i = 0; i < stream_size; ++i) hull_normals[i] = welded[source_of(i)];
        hull_normal_vbo_ = upload_buffer(GLsizeiptr(hull_normals.size() * sizeof(glm::vec3)), hull_normals.data());
    }
    // Object id per stream vertex: every face using a vertex has the same id (components are
    // unions over shared positions; the stream splits vertices by material when faces have
    // materials), except for meshes with both vertex colours and several materials, where
    // the last face wins.
    {
        const std::vector<uint32_t> face_ids = face_object_ids(mesh, &object_parts_);
        std::vector<uint32_t> vertex_ids(stream_size, 0);
        for (size_t f = 0; f < faces.size(); ++f)
            for (int k = 0; k < 3; ++k)
                if (faces[f][k] < vertex_ids.size()) vertex_ids[faces[f][k]] = face_ids[f];
        object_id_vbo_ = upload_buffer(GLsizeiptr(vertex_ids.size() * sizeof(uint32_t)), vertex_ids.data());
    }
    if ((textured() || has_mtoon_textures()) && mesh.uvs.size() == mesh.positions.size()) {
        std::vector<glm::vec2> uvs(stream_size);
        for (size_t i = 0; i < stream_size; ++i) uvs[i] = mesh.uvs[source_of(i)];
        uv_vbo_ = upload_buffer(GLsizeiptr(uvs.size() * sizeof(glm::vec2)), uvs.data());
    }
    // Kept for set_attribute only when the stream is not the mesh's own vertex order.
    if (split) source_ = std::move(source);
    std::vector<uint32_t>().swap(source);

    upload_indices(mesh, faces, has_face_materials);
    std::vector<glm::uvec3>().swap(triangles);

    make_vertex_array();
}

// What the per-material draws need (no pixels), and each distinct image once as a GL texture.
void GpuMesh::upload_materials(const Mesh& mesh, bool has_face_materials) {
    materials_ = mesh.materials;
    for (Material& m : materials_) {
        m.texture.reset();
        m.mtoon_textures.clear();
        has_material_params_ |= !m.mtoon.empty();
        has_unlit_materials_ |= m.unlit;
        has_material_rules_ |= m.alpha_mode != AlphaMode::Opaque || m.sides != FaceSides::Seen;
        has_alpha_materials_ |= m.alpha_mode != AlphaMode::Opaque;
        has_blend_materials_ |= m.alpha_mode == AlphaMode::Blend;
    }
    if (has_face_materials && mesh.uvs.size() == mesh.positions.size()) {
        constexpr size_t kWhite = std::numeric_limits<size_t>::max();
        std::map<const Texture*, size_t> index;
        material_texture_.assign(mesh.materials.size(), kWhite);
        for (size_t m = 0; m < mesh.materials.size(); ++m) {
            const Texture* t = mesh.materials[m].texture.get();
            if (!t) continue;
            auto [it, inserted] = index.try_emplace(t, textures_.size());
            if (inserted) textures_.emplace_back(*t);
            material_texture_[m] = it->second;
        }
        if (!textures_.empty()) {
            textures_.push_back(gpu::BaseTexture::white());
            for (size_t& t : material_texture_) t = std::min(t, textures_.size() - 1);
        }
    }
    // MToon textures without uvs too: the matcap is read at the normal; the others read the
    // uv attribute's default (0, 0), as WebGL reads an absent attribute in three-vrm's shader.
    if (has_face_materials) upload_mtoon_textures(mesh);
}

void GpuMesh::upload_mtoon_textures(const Mesh& mesh) {
    constexpr size_t kWhite = std::numeric_limits<size_t>::max(), kBlack = kWhite - 1;
    std::map<const Texture*, size_t> index;
    material_mtoon_.assign(mesh.materials.size(), {});
    for (size_t m = 0; m < mesh.materials.size(); ++m)
        for (int slot = 0; slot < kMtoonTextureSlotCount; ++slot) {
            const MtoonTextureSlot& s = kMtoonTextureSlots[slot];
            const auto& textures = mesh.materials[m].mtoon_textures;
            const auto it = textures.find(s.name);
            size_t& at = material_mtoon_[m][size_t(slot)];
            at = s.black_when_absent ? kBlack : kWhite;
            if (it == textures.end() || !it->second) continue;
            auto [known, inserted] = index.try_emplace(it->second.get(), mtoon_textures_.size());
            if (inserted) mtoon_textures_.emplace_back(*it->second);
            at = known->second;
        }
    if (mtoon_textures_.empty()) {
        material_mtoon_.clear();
        return;
    }
    mtoon_textures_.push_back(gpu::BaseTexture::white());
    mtoon_textures_.push_back(gpu::BaseTexture::black());
    for (auto& slots : material_mtoon_)
        for (size_t& at : slots)
            if (at == kWhite || at == kBlack) at = mtoon_textures_.size() - (at == kWhite ? 2 : 1);
}

void GpuMesh::upload_indices(const Mesh& mesh, const std::vector<glm::uvec3>& faces, bool has_face_materials) {
    // Faces sorted by material (stable) when materials change what a draw binds; otherwise the
    // file's order, so untextured meshes draw exactly as they always did.
    constexpr uint32_t kNoMaterial = std::numeric_limits<uint32_t>::max();
    if (has_face_materials &&
        (textured() || has_mtoon_textures() || has_material_params_ || has_unlit_materials_ || has_material_rules_)) {
        std::vector<uint32_t> order(faces.size());
        std::iota(order.begin(), order.end(), 0u);
        auto key = [&](uint32_t f) {
            uint32_t m = mesh.face_materials[f];
            return m < mesh.materials.size() ? m : kNoMaterial;
        };
        std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return key(a) < key(b); });
        std::vector<glm::uvec3> sorted(faces.size());
        std::vector<BoundingBox> boxes;
        for (size_t i = 0; i < order.size(); ++i) {
            sorted[i] = faces[order[i]];
            if (ranges_.empty() || ranges_.back().material != key(order[i])) {
                ranges_.push_back({i * 3, 0, key(order[i])});
                const glm::vec3 p = mesh.positions[mesh.triangles[order[i]][0]];
                boxes.push_back({p, p});
            }
            ranges_.back().count += 3;
            for (int k = 0; k < 3; ++k) {
                const glm::vec3& p = mesh.positions[mesh.triangles[order[i]][k]];
                boxes.back().min = glm::min(boxes.back().min, p);
                boxes.back().max = glm::max(boxes.back().max, p);
            }
        }
        for (size_t r = 0; r < ranges_.size(); ++r) ranges_[r].center = boxes[r].center();
        ibo_ = upload_buffer(GLsizeiptr(sorted.size() * sizeof(glm::uvec3)), sorted.data());
    } else {
        ranges_.push_back({0, index_count_, kNoMaterial, mesh.bounds().center()});
        ibo_ = upload_buffer(GLsizeiptr(faces.size() * sizeof(glm::uvec3)), faces.data());
    }
}

void GpuMesh::make_vertex_array() {
    vao_ = gpu::GlVertexArray::create();
    const GLuint vao = vao_.id();
    glVertexArrayVertexBuffer(vao, 0, vbo_.id(), 0, sizeof(GpuVertex));
    glVertexArrayElementBuffer(vao, ibo_.id());
    const GLuint offsets[3] = {offsetof(GpuVertex, position), offsetof(GpuVertex, normal), offsetof(GpuVertex, color)};
    for (GLuint a = 0; a < 3; ++a) {
        glEnableVertexArrayAttrib(vao, a);
        glVertexArrayAttribFormat(vao, a, 3, GL_FLOAT, GL_FALSE, offsets[a]);
        glVertexArrayAttribBinding(vao, a, 0);
    }
    glVertexArrayVertexBuffer(vao, 1, hull_normal_vbo_.id(), 0, sizeof(glm::vec3));
    glEnableVertexArrayAttrib(vao, 3);
    glVertexArrayAttribFormat(vao, 3, 3, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(vao, 3, 1);

    glVertexArrayVertexBuffer(vao, 2, object_id_vbo_.id(), 0, sizeof(uint32_t));
    glEnableVertexArrayAttrib(vao, 4);
    glVertexArrayAttribIFormat(vao, 4, 1, GL_UNSIGNED_INT, 0);
    glVertexArrayAttribBinding(vao, 4, 2);

    if (uv_vbo_) {
        glVertexArrayVertexBuffer(vao, 3, uv_vbo_.id(), 0, sizeof(glm::vec2));
        glEnableVertexArrayAttrib(vao, 5);
        glVertexArrayAttribFormat(vao, 5, 2, GL_FLOAT, GL_FALSE, 0);
        glVertexArrayAttribBinding(vao, 5, 3);
    }
}

void GpuMesh::set_attribute(const std::string& name, const std::vector<float>& per_mesh_vertex, size_t floats,
                            std::vector<float> key) {
    std::vector<float> stream;
    const std::vector<float>* data = &per_mesh_vertex;
    if (!source_.empty() || per_mesh_vertex.size() != stream_size_ * floats) {
        // Each stream vertex its source vertex's values (0 past the end).
        stream.assign(stream_size_ * floats, 0.0f);
        for (size_t i = 0; i < stream_size_; ++i) {
            const size_t v = source_.empty() ? i : source_[i];
            if ((v + 1) * floats <= per_mesh_vertex.size())
                std::copy_n(per_mesh_vertex.begin() + std::ptrdiff_t(v * floats), floats,
                            stream.begin() + std::ptrdiff_t(i * floats));
        }
        data = &stream;
    }
    Attribute& attribute = attributes_[name];
    if (!attribute.buffer) attribute.buffer = gpu::GlBuffer::create();
    glNamedBufferData(attribute.buffer.id(), GLsizeiptr(data->size() * sizeof(float)), data->data(), GL_DYNAMIC_DRAW);
    attribute.key = std::move(key);
}

const std::vector<float>* GpuMesh::attribute_key(const std::string& name) const {
    const auto it = attributes_.find(name);
    return it == attributes_.end() ? nullptr : &it->second.key;
}

void GpuMesh::bind_attributes(const std::vector<AttributeLayout>& layouts) {
    const GLuint vao = vao_.id();
    for (GLuint a = kFirstDeclaredLocation; a < kLocationCount; ++a) glDisableVertexArrayAttrib(vao, a);
    // Binding points from 4 (0-3 hold the other streams), one a buffer; its elements side by side.
    GLuint binding = 4;
    for (const AttributeLayout& l : layouts) {
        const GLsizei element = GLsizei(l.components * sizeof(float));
        glVertexArrayVertexBuffer(vao, binding, attributes_.at(l.name).buffer.id(), 0, element * GLsizei(l.count));
        for (GLuint e = 0; e < GLuint(l.count); ++e) {
            glEnableVertexArrayAttrib(vao, l.location + e);
            glVertexArrayAttribFormat(vao, l.location + e, l.components, GL_FLOAT, GL_FALSE, e * GLuint(element));
            glVertexArrayAttribBinding(vao, l.location + e, binding);
        }
        ++binding;
    }
}

namespace {

// llvmpipe bins a whole draw call before it rasterises any of it: one draw of 10 M triangles
// held about 700 MB of binned triangle data at once. Draws of at most kChunk triangles with a
// flush after each keep that to one chunk's worth; the triangles are drawn in the same order,
// so the image is the same. Meshes below the size draw in one call, as before.
constexpr GLsizei kChunkIndices = 3 * (GLsizei(1) << 20);

void draw_indices(size_t first, GLsizei count) {
    while (count > 0) {
        const GLsizei n = std::min(count, kChunkIndices);
        glDrawElements(GL_TRIANGLES, n, GL_UNSIGNED_INT, reinterpret_cast<const void*>(first * sizeof(uint32_t)));
        first += size_t(n);
        count -= n;
        if (count > 0) glFinish();
    }
}

}  // namespace

void GpuMesh::draw() const {
    glBindVertexArray(vao_.id());
    draw_indices(0, index_count_);
}

void GpuMesh::draw_face_numbers(const Mesh& mesh) {
    if (!face_number_vao_) {
        struct Corner {
            glm::vec3 position;
            uint32_t face;  // number + 1
        };
        std::vector<Corner> corners;
        corners.reserve(mesh.triangles.size() * 3);
        for (size_t f = 0; f < mesh.triangles.size(); ++f)
            for (int k = 0; k < 3; ++k) corners.push_back({mesh.positions[mesh.triangles[f][k]], uint32_t(f + 1)});
        face_number_vbo_ = upload_buffer(GLsizeiptr(corners.size() * sizeof(Corner)), corners.data());
        face_number_count_ = GLsizei(corners.size());
        face_number_vao_ = gpu::GlVertexArray::create();
        const GLuint vao = face_number_vao_.id();
        glVertexArrayVertexBuffer(vao, 0, face_number_vbo_.id(), 0, sizeof(Corner));
        glEnableVertexArrayAttrib(vao, 0);
        glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, offsetof(Corner, position));
        glVertexArrayAttribBinding(vao, 0, 0);
        glEnableVertexArrayAttrib(vao, 4);
        glVertexArrayAttribIFormat(vao, 4, 1, GL_UNSIGNED_INT, offsetof(Corner, face));
        glVertexArrayAttribBinding(vao, 4, 0);
    }
    glBindVertexArray(face_number_vao_.id());
    for (GLsizei first = 0; first < face_number_count_; first += kChunkIndices) {  // as draw_indices
        if (first > 0) glFinish();
        glDrawArrays(GL_TRIANGLES, first, std::min(kChunkIndices, face_number_count_ - first));
    }
}

const Material* GpuMesh::range_material(size_t range) const {
    const uint32_t m = ranges_[range].material;
    return m < materials_.size() ? &materials_[m] : nullptr;
}

void GpuMesh::draw_by_material(GLuint texture_unit, gpu::Texels texels,
                               const std::function<bool(const Material*)>& before) const {
    for (size_t r = 0; r < ranges_.size(); ++r) {
        if (before && !before(range_material(r))) continue;
        draw_range(r, texture_unit, texels);
    }
}

bool GpuMesh::range_has_mtoon_texture(size_t range, int slot) const {
    const uint32_t m = ranges_[range].material;
    return has_mtoon_textures() && m < material_mtoon_.size() && slot >= 0 && slot < kMtoonTextureSlotCount &&
           material_mtoon_[m][size_t(slot)] + 2 < mtoon_textures_.size();
}

void GpuMesh::draw_range(size_t range, GLuint texture_unit, gpu::Texels texels) const {
    glBindVertexArray(vao_.id());
    const Range& r = ranges_[range];
    const bool known = r.material < materials_.size();
    if (textured()) textures_[known ? material_texture_[r.material] : textures_.size() - 1].bind(texture_unit, texels);
    for (int slot = 0; has_mtoon_textures() && slot < kMtoonTextureSlotCount; ++slot) {
        const MtoonTextureSlot& s = kMtoonTextureSlots[slot];
        const size_t fallback = mtoon_textures_.size() - (s.black_when_absent ? 1 : 2);
        mtoon_textures_[known ? material_mtoon_[r.material][size_t(slot)] : fallback].bind(
            texture_unit + 1 + GLuint(slot), s.color ? texels : gpu::Texels::AsStored);
    }
    draw_indices(r.first, r.count);
}

}  // namespace inkshade::render
