// glTF's KHR_texture_transform as three.js r187 applies it, in the extension's order T · R · S
// (scale, then rotate, then offset) on the uvs in glTF's convention (t down the image):
//   s' =  cos r · sx · s + sin r · sy · t + ox
//   t' = −sin r · sx · s + cos r · sy · t + oy
// GLTFLoader's extendTexture writes this matrix into the texture when the extension has a
// rotation (three.js's own setUvTransform would rotate before it scales), and three-vrm's
// MToonMaterial copies the texture's matrix into its *UvTransform uniforms. Without a rotation
// both orders give the same matrix.
#pragma once
#include <optional>

#include <glm/glm.hpp>

namespace tinygltf {
class Value;
}

namespace inkshade::io {

// The matrix (column-major: m[2] is the translation) above.
glm::mat3 uv_transform(double offset_s, double offset_t, double rotation, double scale_s, double scale_t);

// The KHR_texture_transform object `transform` (offset [0, 0], rotation 0, scale [1, 1] where
// absent or not finite) as a matrix; nullopt when it is not an object. Its texCoord is not
// read: a mesh has one set of uvs here.
std::optional<glm::mat3> khr_texture_transform(const tinygltf::Value& transform);

// VRM 0.x: a material's vectorProperties._MainTex, [offset s, offset t, scale s, scale t] as
// three-vrm reads it, ported to KHR_texture_transform as its VRMMaterialsV0CompatPlugin does
// (offset t becomes 1 − scale t − offset t); nullopt without one.
std::optional<glm::mat3> vrm0_main_texture_transform(const tinygltf::Value& vector_properties);

}  // namespace inkshade::io
