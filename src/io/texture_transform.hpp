// glTF's KHR_texture_transform as three.js applies it: GLTFLoader puts the extension's offset,
// rotation and scale on the texture (offset, rotation, repeat), and the texture's matrix is
// Matrix3.setUvTransform(offset, repeat, rotation, centre 0):
//   s' = sx ( cos r · s + sin r · t) + ox
//   t' = sy (−sin r · s + cos r · t) + oy
// on the uvs in glTF's convention (t down the image). That rotates before it scales, where the
// extension's specification scales first (T · R · S); the two differ only for a rotated,
// unevenly scaled texture, and three.js's order is the one three-vrm renders.
#pragma once
#include <optional>

#include <glm/glm.hpp>

namespace tinygltf {
class Value;
}

namespace inkshade::io {

// The matrix (column-major: m[2] is the translation) of three.js's setUvTransform with centre 0.
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
