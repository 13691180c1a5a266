// GltfMeshBuilder (gltf_mesh_builder.hpp): primitives (glTF 2.0 section 3.7.2.1) into one Mesh.
#include "io/gltf_mesh_builder.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>  // as in gltf_container.cpp: tiny_gltf.h needs it with TINYGLTF_NO_FS

#include "io/tiny_gltf_config.hpp"

#include <glm/gtc/matrix_inverse.hpp>

#include "io/gltf_pose.hpp"

namespace inkshade::io {
namespace {

// The accessor of a primitive's attribute `name`, or -1.
int attribute_index(const tinygltf::Primitive& prim, const std::string& name) {
    auto it = prim.attributes.find(name);
    return it == prim.attributes.end() ? -1 : it->second;
}

}  // namespace

GltfMeshBuilder::GltfMeshBuilder(const tinygltf::Model& model, const std::string& path, Mesh& mesh,
                                 const GltfAccessorReader& reader)
    : model_(model), path_(path), mesh_(mesh), reader_(reader), materials_(model, reader_, path, mesh) {}

void GltfMeshBuilder::add(const GltfInstance& instance, const GltfPose& pose) {
    const tinygltf::Mesh& gm = model_.meshes[size_t(instance.mesh)];
    for (size_t p = 0; p < gm.primitives.size(); ++p)
        add_primitive(gm.primitives[p], instance, pose,
                      "mesh " + std::to_string(instance.mesh) + " primitive " + std::to_string(p));
}

void GltfMeshBuilder::finish() {
    if (!normals_complete_) mesh_.normals.clear();
    if (!mesh_.face_marks.empty()) mesh_.face_marks.resize(mesh_.triangles.size(), 0);  // later primitives: none
    if (skipped_ > 0)
        mesh_.warnings.push_back(path_ + ": " + std::to_string(skipped_) + " point primitive" +
                                 (skipped_ > 1 ? "s" : "") + " skipped (only triangles and lines are drawn)");
}

void GltfMeshBuilder::add_primitive(const tinygltf::Primitive& prim, const GltfInstance& instance, const GltfPose& pose,
                                    const std::string& where) {
    const glm::dmat4& transform = instance.transform;
    const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
    if (mode == TINYGLTF_MODE_LINE || mode == TINYGLTF_MODE_LINE_LOOP || mode == TINYGLTF_MODE_LINE_STRIP) {
        add_lines(prim, instance, mode, where);
        return;
    }
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        ++skipped_;
        return;
    }
    const int position = attribute_index(prim, "POSITION");
    if (position < 0) {  // section 3.7.2.1: such a primitive is not rendered
        mesh_.warnings.push_back(path_ + ": " + where + " has no POSITION attribute; skipped");
        return;
    }
    int comps = 0;
    std::vector<float> pos = reader_.floats(position, "POSITION of " + where, {3}, comps);
    const size_t n = pos.size() / 3;
    if (n == 0) return;
    const size_t base = mesh_.positions.size();
    const std::vector<glm::uvec3> tris = triangles(prim, mode, n, glm::determinant(glm::dmat3(transform)) < 0.0, where);

    // Attributes, read (and checked) before anything is appended.
    Attributes attrs = attributes(prim, n, where);
    pose.deform(size_t(instance.node), prim, pos, attrs.normals, where);

    const uint32_t material = materials_.index(prim.material);
    const glm::vec3 base_colour = mesh_.materials[material].diffuse;
    // three-vrm's MToonMaterial leaves COLOR_0 out (ignoreVertexColor, true by default and never
    // changed by its loaders): an MToon material's vertices take its colour alone.
    if (!mesh_.materials[material].mtoon.empty()) attrs.colours.clear();
    append_positions_and_normals(pos, attrs.normals, n, transform);
    append_uvs_and_colours(attrs, base, n, base_colour);
    const std::vector<uint8_t> marks = face_marks(prim, tris, n, where);
    const uint32_t object = object_of(instance.node);
    if (!marks.empty()) mesh_.face_marks.resize(mesh_.triangles.size(), 0);
    for (const glm::uvec3& t : tris) {
        mesh_.triangles.push_back(glm::uvec3(base) + t);
        mesh_.face_materials.push_back(material);
        mesh_.face_objects.push_back(object);
    }
    mesh_.face_marks.insert(mesh_.face_marks.end(), marks.begin(), marks.end());
}

// The object a node's faces belong to for line sets: its name, else its mesh's, else "node N";
// nodes of one name are one object.
uint32_t GltfMeshBuilder::object_of(int node) {
    const tinygltf::Node& gn = model_.nodes[size_t(node)];
    std::string name = gn.name;
    if (name.empty() && gn.mesh >= 0) name = model_.meshes[size_t(gn.mesh)].name;
    if (name.empty()) name = "node " + std::to_string(node);
    std::vector<std::string>& names = mesh_.object_names;
    for (size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return uint32_t(i);
    names.push_back(std::move(name));
    return uint32_t(names.size() - 1);
}

// Per triangle of `tris`, its face mark from the primitive's _FACEMARK attribute (an
// application-specific attribute, glTF 2.0 section 3.7.2.1): its corners' smallest value,
// rounded, a value in (0, 1) (a normalized integer) counting as 1, at most 255. Empty without one.
std::vector<uint8_t> GltfMeshBuilder::face_marks(const tinygltf::Primitive& prim, const std::vector<glm::uvec3>& tris,
                                                 size_t n, const std::string& where) {
    const int index = attribute_index(prim, "_FACEMARK");
    if (index < 0) return {};
    int comps = 0;
    const std::vector<float> v = reader_.floats(index, "_FACEMARK of " + where, {1}, comps);
    if (v.size() != n)
        reader_.fail("_FACEMARK of " + where + " has " + std::to_string(v.size()) + " values for " + std::to_string(n) +
                     " vertices");
    const auto mark = [](float x) {
        if (!(x > 0.0f)) return uint8_t(0);
        return uint8_t(x < 1.0f ? 1.0f : std::min(std::round(x), 255.0f));
    };
    std::vector<uint8_t> out;
    out.reserve(tris.size());
    for (const glm::uvec3& t : tris) out.push_back(std::min({mark(v[t.x]), mark(v[t.y]), mark(v[t.z])}));
    return out;
}

// A LINES, LINE_LOOP or LINE_STRIP primitive (section 3.7.2.1 gives the orders): its vertices
// placed by the instance's transform and its segments kept as Mesh::line_segments. Vertices
// that only lines use get a placeholder unit normal (faces never read it) so that the file's
// normals stay complete.
void GltfMeshBuilder::add_lines(const tinygltf::Primitive& prim, const GltfInstance& instance, int mode,
                                const std::string& where) {
    const int position = attribute_index(prim, "POSITION");
    if (position < 0) {
        mesh_.warnings.push_back(path_ + ": " + where + " has no POSITION attribute; skipped");
        return;
    }
    int comps = 0;
    const std::vector<float> pos = reader_.floats(position, "POSITION of " + where, {3}, comps);
    const size_t n = pos.size() / 3;
    if (n == 0) return;
    if (n > kMaxGltfVertices - mesh_.positions.size())
        reader_.fail("more than " + std::to_string(kMaxGltfVertices) + " vertices in the scene");
    const std::vector<uint32_t> corners = vertex_indices(prim, n, where);
    const size_t base = mesh_.positions.size();
    append_positions_and_normals(pos, std::vector<float>(normals_complete_ ? 3 * n : 0, 0.0f), n, instance.transform);
    if (normals_complete_)
        for (size_t i = base; i < base + n; ++i) mesh_.normals[i] = glm::vec3(0.0f, 0.0f, 1.0f);
    append_uvs_and_colours(Attributes{}, base, n, glm::vec3(0.8f));
    const auto emit = [&](uint32_t a, uint32_t b) {
        if (a != b) mesh_.line_segments.emplace_back(uint32_t(base) + a, uint32_t(base) + b);
    };
    const size_t m = corners.size();
    if (mode == TINYGLTF_MODE_LINE) {
        for (size_t i = 0; i + 1 < m; i += 2) emit(corners[i], corners[i + 1]);
    } else {
        for (size_t i = 0; i + 1 < m; ++i) emit(corners[i], corners[i + 1]);
        if (mode == TINYGLTF_MODE_LINE_LOOP && m > 2) emit(corners[m - 1], corners[0]);
    }
}

std::vector<uint32_t> GltfMeshBuilder::vertex_indices(const tinygltf::Primitive& prim, size_t n,
                                                      const std::string& where) {
    if (prim.indices >= 0) return reader_.indices(prim.indices, "indices of " + where, n);
    std::vector<uint32_t> all(n);
    for (size_t i = 0; i < n; ++i) all[i] = uint32_t(i);
    return all;
}

// The primitive's triangles over its `n` vertices (section 3.7.2.1 gives the strip and fan
// orders), its indices read and the scene's vertex and triangle limits checked; `mirror` (a
// mirroring transform) swaps two corners so the front face stays counter-clockwise.
std::vector<glm::uvec3> GltfMeshBuilder::triangles(const tinygltf::Primitive& prim, int mode, size_t n, bool mirror,
                                                   const std::string& where) {
    const std::vector<uint32_t> corners = vertex_indices(prim, n, where);
    if (n > kMaxGltfVertices - mesh_.positions.size())
        reader_.fail("more than " + std::to_string(kMaxGltfVertices) + " vertices in the scene");

    std::vector<glm::uvec3> tris;
    auto emit = [&](uint32_t a, uint32_t b, uint32_t c) {
        tris.push_back(mirror ? glm::uvec3(a, c, b) : glm::uvec3(a, b, c));
    };
    const size_t m = corners.size();
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        if (m % 3 != 0)
            mesh_.warnings.push_back(path_ + ": " + where + " has " + std::to_string(m) +
                                     " indices, not a multiple of 3; the rest is ignored");
        for (size_t i = 0; i + 2 < m; i += 3) emit(corners[i], corners[i + 1], corners[i + 2]);
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        for (size_t i = 0; i + 2 < m; ++i) emit(corners[i], corners[i + 1 + i % 2], corners[i + 2 - i % 2]);
    } else {
        for (size_t i = 1; i + 1 < m; ++i) emit(corners[i], corners[i + 1], corners[0]);
    }
    if (tris.size() > kMaxGltfTriangles - mesh_.triangles.size())
        reader_.fail("more than " + std::to_string(kMaxGltfTriangles) + " triangles in the scene");
    return tris;
}

// NORMAL, the TEXCOORD set the material's base colour texture uses, and COLOR_0, each checked
// to have `n` elements.
GltfMeshBuilder::Attributes GltfMeshBuilder::attributes(const tinygltf::Primitive& prim, size_t n,
                                                        const std::string& where) {
    Attributes a;
    int comps = 0;
    const int normal = attribute_index(prim, "NORMAL");
    if (normal >= 0) a.normals = reader_.floats(normal, "NORMAL of " + where, {3}, comps);
    const int uv_set = materials_.uv_set(prim.material);
    const int texcoord = attribute_index(prim, "TEXCOORD_" + std::to_string(uv_set));
    if (texcoord >= 0)
        a.uvs = reader_.floats(texcoord, "TEXCOORD_" + std::to_string(uv_set) + " of " + where, {2}, comps);
    const int color = attribute_index(prim, "COLOR_0");
    if (color >= 0) a.colours = reader_.floats(color, "COLOR_0 of " + where, {3, 4}, a.colour_components);
    auto same_count = [&](const std::vector<float>& v, size_t c, const char* name) {
        if (!v.empty() && v.size() / c != n)
            reader_.fail(std::string(name) + " of " + where + " has " + std::to_string(v.size() / c) +
                         " elements but POSITION has " + std::to_string(n));
    };
    same_count(a.normals, 3, "NORMAL");
    same_count(a.uvs, 2, "TEXCOORD");
    if (a.colour_components > 0) same_count(a.colours, size_t(a.colour_components), "COLOR_0");
    return a;
}

void GltfMeshBuilder::append_positions_and_normals(const std::vector<float>& pos, const std::vector<float>& nrm,
                                                   size_t n, const glm::dmat4& transform) {
    const glm::mat3 normal_matrix = glm::mat3(glm::inverseTranspose(glm::dmat3(transform)));
    for (size_t i = 0; i < n; ++i) {
        glm::dvec4 p = transform * glm::dvec4(pos[3 * i], pos[3 * i + 1], pos[3 * i + 2], 1.0);
        mesh_.positions.emplace_back(float(p.x), float(p.y), float(p.z));
    }
    if (normals_complete_ && nrm.empty()) {
        normals_complete_ = false;
        mesh_.normals.clear();
    } else if (normals_complete_) {
        for (size_t i = 0; i < n; ++i) {
            glm::vec3 v = normal_matrix * glm::vec3(nrm[3 * i], nrm[3 * i + 1], nrm[3 * i + 2]);
            float len = glm::length(v);
            mesh_.normals.push_back(len > 0.0f ? v / len : v);  // zero stays zero: load_mesh repairs it
        }
    }
}

void GltfMeshBuilder::append_uvs_and_colours(const Attributes& a, size_t base, size_t n, const glm::vec3& base_colour) {
    // glTF texture coordinates start at the image's top-left (section 3.7.2.1); Mesh::uvs
    // use OBJ's bottom-left origin.
    const std::vector<float>& uv = a.uvs;
    if (!uv.empty() && mesh_.uvs.size() < base) mesh_.uvs.resize(base, glm::vec2(0.0f));
    if (!uv.empty()) {
        for (size_t i = 0; i < n; ++i) mesh_.uvs.emplace_back(uv[2 * i], 1.0f - uv[2 * i + 1]);
    } else if (!mesh_.uvs.empty()) {
        mesh_.uvs.resize(base + n, glm::vec2(0.0f));
    }
    // COLOR_0 multiplies the base colour factor (section 3.9.2); Mesh::colors replace the
    // material colour, so they carry the product, and other primitives their own colour.
    const std::vector<float>& col = a.colours;
    if (!col.empty() && mesh_.colors.empty() && base > 0) {
        mesh_.colors.reserve(base + n);
        for (const Range& r : ranges_) mesh_.colors.resize(r.end, r.colour);
    }
    if (!col.empty()) {
        const size_t c = size_t(a.colour_components);
        for (size_t i = 0; i < n; ++i)
            mesh_.colors.push_back(glm::clamp(glm::vec3(col[c * i], col[c * i + 1], col[c * i + 2]), 0.0f, 1.0f) *
                                   base_colour);
    } else if (!mesh_.colors.empty()) {
        mesh_.colors.resize(base + n, base_colour);
    }
    ranges_.push_back({base + n, base_colour});
}

}  // namespace inkshade::io
