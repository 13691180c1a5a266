// KHR_texture_transform as three.js reads it (io/texture_transform.hpp).
#include "io/texture_transform.hpp"

#include <cmath>
#include <fstream>  // as in gltf_reader.cpp: tiny_gltf.h needs it with TINYGLTF_NO_FS

#include "io/tiny_gltf_config.hpp"

namespace inkshade::io {

namespace {

double finite_or(const tinygltf::Value& v, double fallback) {
    if (!v.IsNumber()) return fallback;
    const double d = v.GetNumberAsDouble();
    return std::isfinite(d) ? d : fallback;
}

// Element i of an array of numbers, or `fallback`.
double element(const tinygltf::Value& object, const char* key, int i, double fallback) {
    if (!object.IsObject() || !object.Has(key)) return fallback;
    const tinygltf::Value& a = object.Get(key);
    if (!a.IsArray() || a.ArrayLen() <= size_t(i)) return fallback;
    return finite_or(a.Get(i), fallback);
}

}  // namespace

glm::mat3 uv_transform(double offset_s, double offset_t, double rotation, double scale_s, double scale_t) {
    const double c = std::cos(rotation), s = std::sin(rotation);
    glm::mat3 m(1.0f);  // m[column][row]
    m[0][0] = float(scale_s * c);
    m[1][0] = float(scale_t * s);
    m[2][0] = float(offset_s);
    m[0][1] = float(-scale_s * s);
    m[1][1] = float(scale_t * c);
    m[2][1] = float(offset_t);
    return m;
}

std::optional<glm::mat3> khr_texture_transform(const tinygltf::Value& transform) {
    if (!transform.IsObject()) return std::nullopt;
    const double rotation = transform.Has("rotation") ? finite_or(transform.Get("rotation"), 0.0) : 0.0;
    return uv_transform(element(transform, "offset", 0, 0.0), element(transform, "offset", 1, 0.0), rotation,
                        element(transform, "scale", 0, 1.0), element(transform, "scale", 1, 1.0));
}

std::optional<glm::mat3> vrm0_main_texture_transform(const tinygltf::Value& vector_properties) {
    if (!vector_properties.IsObject() || !vector_properties.Has("_MainTex") ||
        !vector_properties.Get("_MainTex").IsArray())
        return std::nullopt;
    const double offset_s = element(vector_properties, "_MainTex", 0, 0.0);
    const double offset_t = element(vector_properties, "_MainTex", 1, 0.0);
    const double scale_s = element(vector_properties, "_MainTex", 2, 1.0);
    const double scale_t = element(vector_properties, "_MainTex", 3, 1.0);
    // three-vrm 3.5.5 VRMMaterialsV0CompatPlugin._portTextureTransform: offset[1] = 1 - scale[1]
    // - offset[1] (Unity's t runs up the image, glTF's down it).
    return uv_transform(offset_s, 1.0 - scale_t - offset_t, 0.0, scale_s, scale_t);
}

}  // namespace inkshade::io
