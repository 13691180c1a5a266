// Formats Inkshade has no reader of its own for (FBX, COLLADA, 3DS, Blender, DirectX .x, ...)
// through the Open Asset Import Library, when built with it (INKSHADE_HAVE_ASSIMP, Debian's
// libassimp-dev; docs/inputs.md). It is a fallback: the native readers keep their extensions,
// since they check their input strictly and are fuzzed; assimp's parsers are Debian's build.
// The node hierarchy is flattened by assimp (aiProcess_PreTransformVertices, mirrored nodes
// keep their winding), polygons are triangulated, and points and lines are dropped.
#include <filesystem>
#include <map>
#include <string>

#include "inkshade/error.hpp"
#include "io/readers.hpp"
#include "io/texture_image.hpp"

#if INKSHADE_HAVE_ASSIMP
#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#endif

namespace inkshade::io {

#if INKSHADE_HAVE_ASSIMP
namespace {

// As the glTF reader: more vertices than this cannot be drawn in one buffer anyway (32-bit
// indices, 12 bytes a position), and a claim beyond it is a corrupt or hostile file.
constexpr size_t kMaxVertices = size_t(1) << 28;

std::string one_line(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) s.pop_back();
    for (char& c : s)
        if (static_cast<unsigned char>(c) < 0x20) c = ' ';
    return s;
}

// An embedded texture ("*0" names, or an FBX's packed file): compressed bytes (mHeight == 0)
// decode like a file; raw texels are BGRA (aiTexel).
std::shared_ptr<const Texture> embedded_texture(const aiTexture& t, const std::string& source, std::string& problem) {
    if (t.mHeight == 0)
        return decode_texture(reinterpret_cast<const unsigned char*>(t.pcData), t.mWidth, source, problem);
    if (t.mWidth > unsigned(kMaxTextureSide) || t.mHeight > unsigned(kMaxTextureSide)) {
        problem = "larger than " + std::to_string(kMaxTextureSide) + " pixels a side";
        return nullptr;
    }
    auto texture = std::make_shared<Texture>();
    texture->source = source;
    texture->width = int(t.mWidth);
    texture->height = int(t.mHeight);
    texture->rgba.resize(size_t(t.mWidth) * t.mHeight * 4);
    for (size_t i = 0; i < size_t(t.mWidth) * t.mHeight; ++i) {
        const aiTexel& p = t.pcData[i];
        texture->rgba[4 * i + 0] = p.r;
        texture->rgba[4 * i + 1] = p.g;
        texture->rgba[4 * i + 2] = p.b;
        texture->rgba[4 * i + 3] = p.a;
    }
    return texture;
}

Material read_material(const aiScene& scene, const aiMaterial& m, const std::string& path,
                       std::map<std::string, std::shared_ptr<const Texture>>& textures,
                       std::vector<std::string>& warnings) {
    Material out;
    aiString name;
    if (m.Get(AI_MATKEY_NAME, name) == AI_SUCCESS) out.name = name.C_Str();
    // PBR base colour where the exporter wrote one, else the classic diffuse colour; linear, as
    // MTL Kd and glTF baseColorFactor are taken.
    aiColor4D color;
    if (m.Get(AI_MATKEY_BASE_COLOR, color) == AI_SUCCESS || m.Get(AI_MATKEY_COLOR_DIFFUSE, color) == AI_SUCCESS)
        out.diffuse = glm::clamp(glm::vec3(color.r, color.g, color.b), 0.0f, 1.0f);

    aiString file;
    if (m.GetTexture(aiTextureType_BASE_COLOR, 0, &file) != AI_SUCCESS &&
        m.GetTexture(aiTextureType_DIFFUSE, 0, &file) != AI_SUCCESS)
        return out;
    const std::string texname = file.C_Str();
    auto [it, fresh] = textures.try_emplace(texname);
    if (fresh) {
        if (const aiTexture* embedded = scene.GetEmbeddedTexture(file.C_Str())) {
            std::string problem;
            it->second = embedded_texture(*embedded, path + "#" + texname, problem);
            if (!it->second) warnings.push_back(texture_warning(path, texname, problem));
        } else {
            const std::filesystem::path dir = std::filesystem::path(path).parent_path();
            it->second =
                load_texture_or_warn(path, texname, {dir.empty() ? std::filesystem::path(".") : dir}, warnings);
        }
    }
    out.texture = it->second;
    // A texture with a black or missing diffuse colour means the texture as is (as for MTL).
    if (out.texture && out.diffuse == glm::vec3(0.0f)) out.diffuse = glm::vec3(1.0f);
    return out;
}

}  // namespace

bool assimp_reads(const std::string& extension) {
    Assimp::Importer importer;
    return !extension.empty() && importer.IsExtensionSupported(extension.c_str());
}

std::string assimp_extensions() {
    Assimp::Importer importer;
    std::string list;
    importer.GetExtensionList(list);  // "*.3ds;*.obj;..."
    std::string out;
    for (size_t b = 0; b < list.size();) {
        size_t e = list.find(';', b);
        if (e == std::string::npos) e = list.size();
        std::string ext = list.substr(b, e - b);
        if (ext.starts_with("*")) ext.erase(0, 1);
        if (!ext.empty()) out += (out.empty() ? "" : " ") + ext;
        b = e + 1;
    }
    return out;
}

Mesh read_with_assimp(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw InputError(path, std::filesystem::exists(path, ec) ? "not a regular file" : "no such file");

    Assimp::Importer importer;
    // Points and lines are removed by SortByPType; the rest is triangles after Triangulate.
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    const unsigned flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_PreTransformVertices |
                           aiProcess_SortByPType | aiProcess_ValidateDataStructure;
    const aiScene* scene = importer.ReadFile(path, flags);
    if (!scene) throw InputError(path, "assimp: " + one_line(importer.GetErrorString()));
    if (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) throw InputError(path, "assimp: the file holds no complete scene");

    Mesh mesh;
    std::map<std::string, std::shared_ptr<const Texture>> textures;
    for (unsigned i = 0; i < scene->mNumMaterials; ++i)
        mesh.materials.push_back(read_material(*scene, *scene->mMaterials[i], path, textures, mesh.warnings));

    // Attributes are kept only when every mesh has them (one vertex layout for the whole model).
    bool normals = true, uvs = true, colors = true;
    size_t vertices = 0;
    for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
        const aiMesh& m = *scene->mMeshes[i];
        if (!(m.mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
        normals &= m.HasNormals();
        uvs &= m.HasTextureCoords(0);
        colors &= m.HasVertexColors(0);
        vertices += m.mNumVertices;
    }
    if (vertices > kMaxVertices)
        throw InputError(path, std::to_string(vertices) + " vertices (more than " + std::to_string(kMaxVertices) + ")");

    for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
        const aiMesh& m = *scene->mMeshes[i];
        if (!(m.mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
        const uint32_t base = uint32_t(mesh.positions.size());
        for (unsigned v = 0; v < m.mNumVertices; ++v) {
            mesh.positions.emplace_back(m.mVertices[v].x, m.mVertices[v].y, m.mVertices[v].z);
            if (normals) mesh.normals.emplace_back(m.mNormals[v].x, m.mNormals[v].y, m.mNormals[v].z);
            if (uvs) mesh.uvs.emplace_back(m.mTextureCoords[0][v].x, m.mTextureCoords[0][v].y);
            if (colors) mesh.colors.emplace_back(m.mColors[0][v].r, m.mColors[0][v].g, m.mColors[0][v].b);
        }
        for (unsigned f = 0; f < m.mNumFaces; ++f) {
            const aiFace& face = m.mFaces[f];
            if (face.mNumIndices != 3) continue;
            mesh.triangles.emplace_back(base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]);
            if (!mesh.materials.empty())
                mesh.face_materials.push_back(std::min(m.mMaterialIndex, scene->mNumMaterials - 1));
        }
    }
    return mesh;
}

#else  // built without assimp

bool assimp_reads(const std::string&) { return false; }
std::string assimp_extensions() { return {}; }
Mesh read_with_assimp(const std::string& path) {
    throw InputError(path, "this inkshade was built without assimp (-DINKSHADE_WITH_ASSIMP=OFF)");
}

#endif

}  // namespace inkshade::io
