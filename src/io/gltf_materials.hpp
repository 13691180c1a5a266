// The materials of a glTF file as Mesh materials (glTF 2.0 section 3.9): pbrMetallicRoughness
// baseColorFactor and baseColorTexture with its KHR_texture_transform, alphaMode, alphaCutoff,
// doubleSided, KHR_materials_unlit, and a VRM avatar's MToon values and textures (VRM 1.0's
// VRMC_materials_mtoon, VRM 0.x's materialProperties; the values from vrm_materials.hpp), with
// the render order and blending three-vrm gives them. Images are decoded here, each once; a bad
// one is a warning and the material keeps its base colour.
#pragma once
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "inkshade/mesh.hpp"
#include "io/gltf_accessors.hpp"

namespace tinygltf {
class Model;
class Value;
}  // namespace tinygltf

namespace inkshade::io {

struct VrmMaterial;

// Builds Mesh materials from glTF materials on first use, decoding each image once.
class GltfMaterialTable {
public:
    // Materials are appended to mesh.materials and warnings to mesh.warnings as they are built.
    GltfMaterialTable(const tinygltf::Model& model, const GltfAccessorReader& reader, const std::string& path,
                      Mesh& mesh);

    // Mesh material index for glTF material `gltf` (-1 or out of range: the default material,
    // base colour 1 as section 3.9.6 defines).
    uint32_t index(int gltf);

    // TEXCOORD set the material's base colour texture uses (section 3.9.2 texCoord).
    int uv_set(int gltf) const;

private:
    static constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();

    // VRM 0.x blending as three-vrm's VRMMaterialsV0CompatPlugin turns it into glTF and MToon 1.0:
    // MToon's keywords _ALPHABLEND_ON / _ALPHATEST_ON (cutoff _Cutoff), _ZWrite, _CullMode 0 for
    // double-sided, _Color's alpha as written; the VRM/Unlit* shaders by name (their whole _Color
    // gamma-decoded, alpha too, and sides as the glTF material says).
    void v0_alpha_and_sides(const tinygltf::Value& props, const std::string& shader, Material& m) const;
    // VRM 0.x renderQueue of a transparent material as a 1.0 renderQueueOffsetNumber: the
    // queues in use, in order, mapped to -n+1..0 (transparent, clamped at -9) or 0..n-1 (with
    // z-write, clamped at 9), as three-vrm's _populateRenderQueueMap does.
    void v0_queue_maps();
    double v0_queue_offset(const tinygltf::Value& props, const std::string& shader) const;

    Material build(size_t i);
    // A VRM material's MToon values, and its textures decoded.
    void add_mtoon(const VrmMaterial& vrm, Material& m);
    // The glTF texture's image with its sampler (three.js's GLTFLoader values), decoded once per
    // image and copied only for a sampler other than glTF's default.
    std::shared_ptr<const Texture> texture_of(int texture, const std::string& material);
    std::shared_ptr<const Texture> decode_image(size_t i);

    const tinygltf::Model& model_;
    const GltfAccessorReader& reader_;
    const std::string& path_;
    Mesh& mesh_;
    std::vector<std::shared_ptr<const Texture>> images_;
    std::vector<char> tried_;
    std::map<std::pair<size_t, int>, std::shared_ptr<const Texture>> sampled_;  // (image, sampler)
    std::vector<uint32_t> index_;  // glTF material (last slot: default) -> Mesh material
    const tinygltf::Value* v0_ = nullptr;
    std::map<double, int> queue_plain_, queue_z_;  // v0_queue_maps
};

}  // namespace inkshade::io
