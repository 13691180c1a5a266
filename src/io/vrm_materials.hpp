// The MToon values of a VRM avatar's materials, as three-vrm 3.x reads them: VRM 1.0's
// VRMC_materials_mtoon with the glTF material's own emissive and normal map, and VRM 0.x's
// extensions.VRM.materialProperties ported to MToon 1.0 the way three-vrm's
// VRMMaterialsV0CompatPlugin does. Values only: textures come back as glTF texture indices,
// which the glTF reader decodes (gltf_materials.cpp's GltfMaterialTable).
#pragma once
#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace tinygltf {
class Value;
struct Material;
}  // namespace tinygltf

namespace inkshade::io {

// A material's MToon values (Material::mtoon, keyed by the mtoon model's parameter names) and
// textures (Material::mtoon_textures' keys, each a glTF texture index).
struct VrmMaterial {
    std::map<std::string, std::vector<float>> values;
    std::map<std::string, int> textures;
    std::map<std::string, glm::mat3> uv_transforms;  // Material::uv_transforms, for `textures`
};

// The number at `key` of a JSON object, or `fallback` when it is absent, not a number or not finite.
double json_number(const tinygltf::Value& object, const char* key, double fallback);
// The first fallback.size() numbers of the array at `key`, each one not given keeping its fallback.
std::vector<float> json_numbers(const tinygltf::Value& object, const char* key, std::vector<float> fallback);
// The texture index at `key` of an object (a textureInfo's "index", a VRM 0.x textureProperties
// entry), or -1.
int json_texture_index(const tinygltf::Value& object, const char* key);
// VRM 0.x colours are gamma-encoded; three-vrm decodes them with x^2.2 (its gammaEOTF).
std::vector<float> gamma_decode(std::vector<float> c);

// The VRM MToon 1.0 specification's defaults (VRMC_materials_mtoon) for every value a VRM
// material carries.
std::map<std::string, std::vector<float>> mtoon_defaults();

// VRM 1.0: materials[i].extensions.VRMC_materials_mtoon (factors linear as written) with the
// material's emissiveFactor, KHR_materials_emissive_strength, emissiveTexture and normalTexture.
VrmMaterial vrm1_mtoon(const tinygltf::Material& material, const tinygltf::Value& extension);

// VRM 0.x: a "VRM/MToon" entry of materialProperties.
VrmMaterial vrm0_mtoon(const tinygltf::Value& properties);

// VRM 0.x: a "VRM/Unlit*" entry, which three-vrm draws as an MToon material whose shade colour
// and shade multiply texture are its lit colour `lit` and main texture (`main_texture`, -1: none).
// `main_transform`: the main texture's (vrm0_main_texture_transform), identity without one.
VrmMaterial vrm0_unlit(const glm::vec3& lit, int main_texture, const glm::mat3& main_transform = glm::mat3(1.0f));

}  // namespace inkshade::io
