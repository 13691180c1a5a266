#include "io/vrm_materials.hpp"

#include "io/texture_transform.hpp"

#include <fstream>  // as in gltf_reader.cpp: tiny_gltf.h needs it with TINYGLTF_NO_FS

#include "io/tiny_gltf_config.hpp"
#include "io/gltf_value_member.hpp"

#include <algorithm>
#include <cmath>

namespace inkshade::io {

double json_number(const tinygltf::Value& object, const char* key, double fallback) {
    if (!object.IsObject() || !object.Has(key)) return fallback;
    const tinygltf::Value& v = object.Get(key);
    if (!v.IsNumber()) return fallback;
    double d = v.GetNumberAsDouble();
    return std::isfinite(d) ? d : fallback;
}

std::vector<float> json_numbers(const tinygltf::Value& object, const char* key, std::vector<float> fallback) {
    if (!object.IsObject() || !object.Has(key)) return fallback;
    const tinygltf::Value& v = object.Get(key);
    if (!v.IsArray() || v.ArrayLen() < fallback.size()) return fallback;
    for (size_t i = 0; i < fallback.size(); ++i) {
        const tinygltf::Value& x = v.Get(int(i));
        if (x.IsNumber() && std::isfinite(x.GetNumberAsDouble())) fallback[i] = float(x.GetNumberAsDouble());
    }
    return fallback;
}

int json_texture_index(const tinygltf::Value& object, const char* key) {
    double d = json_number(object, key, -1.0);
    return d >= 0.0 && d < 1e9 ? int(d) : -1;
}

std::vector<float> gamma_decode(std::vector<float> c) {
    for (float& x : c) x = std::pow(std::max(x, 0.0f), 2.2f);
    return c;
}

std::map<std::string, std::vector<float>> mtoon_defaults() {
    return {{"shade-color", {0, 0, 0}},
            {"shading-shift", {0}},
            {"shading-toony", {0.9f}},
            {"shading-shift-texture-scale", {1}},
            {"rim-color", {0, 0, 0}},
            {"rim-fresnel-power", {5}},
            {"rim-lift", {0}},
            {"rim-lighting-mix", {1}},
            {"outline-width-mode", {0}},
            {"outline-width", {0}},
            {"outline-color", {0, 0, 0}},
            {"outline-lighting-mix", {1}},
            {"gi-equalization", {0.9f}},
            {"matcap-color", {1, 1, 1}},
            {"emissive", {0, 0, 0}},
            {"emissive-intensity", {1}},
            {"normal-scale", {1}},
            {"uv-animation-scroll-x-speed", {0}},
            {"uv-animation-scroll-y-speed", {0}},
            {"uv-animation-rotation-speed", {0}}};
}

namespace {

// The MToon textures (Material::mtoon_textures) by their VRM 1.0 and VRM 0.x names.
struct MtoonTextureName {
    const char* key;  // Material::mtoon_textures
    const char* v1;   // VRMC_materials_mtoon textureInfo
    const char* v0;   // VRM 0.x textureProperties
};
constexpr MtoonTextureName kMtoonTextureNames[] = {
    {"matcap-texture", "matcapTexture", "_SphereAdd"},
    {"rim-multiply-texture", "rimMultiplyTexture", "_RimTexture"},
    {"outline-width-multiply-texture", "outlineWidthMultiplyTexture", "_OutlineWidthTexture"},
    {"shade-multiply-texture", "shadeMultiplyTexture", "_ShadeTexture"},
    {"shading-shift-texture", "shadingShiftTexture", nullptr},  // VRM 0.x has none
    {"uv-animation-mask-texture", "uvAnimationMaskTexture", "_UvAnimMaskTexture"},
};

}  // namespace

VrmMaterial vrm1_mtoon(const tinygltf::Material& g, const tinygltf::Value& e) {
    VrmMaterial out;
    auto& m = out.values;
    m = mtoon_defaults();
    m["shade-color"] = json_numbers(e, "shadeColorFactor", m["shade-color"]);
    m["shading-shift"] = {float(json_number(e, "shadingShiftFactor", 0.0))};
    m["shading-toony"] = {float(json_number(e, "shadingToonyFactor", 0.9))};
    m["shading-shift-texture-scale"] = {float(json_number(member(e, "shadingShiftTexture"), "scale", 1.0))};
    m["rim-color"] = json_numbers(e, "parametricRimColorFactor", m["rim-color"]);
    m["rim-fresnel-power"] = {float(json_number(e, "parametricRimFresnelPowerFactor", 5.0))};
    m["rim-lift"] = {float(json_number(e, "parametricRimLiftFactor", 0.0))};
    m["rim-lighting-mix"] = {float(json_number(e, "rimLightingMixFactor", 1.0))};
    const tinygltf::Value& mode = member(e, "outlineWidthMode");
    if (mode.IsString()) {
        const std::string& name = mode.Get<std::string>();
        m["outline-width-mode"] = {name == "worldCoordinates" ? 1.0f : name == "screenCoordinates" ? 2.0f : 0.0f};
    }
    m["outline-width"] = {float(json_number(e, "outlineWidthFactor", 0.0))};
    m["outline-color"] = json_numbers(e, "outlineColorFactor", m["outline-color"]);
    m["outline-lighting-mix"] = {float(json_number(e, "outlineLightingMixFactor", 1.0))};
    m["gi-equalization"] = {float(json_number(e, "giEqualizationFactor", 0.9))};
    m["matcap-color"] = json_numbers(e, "matcapFactor", m["matcap-color"]);
    m["uv-animation-scroll-x-speed"] = {float(json_number(e, "uvAnimationScrollXSpeedFactor", 0.0))};
    m["uv-animation-scroll-y-speed"] = {float(json_number(e, "uvAnimationScrollYSpeedFactor", 0.0))};
    m["uv-animation-rotation-speed"] = {float(json_number(e, "uvAnimationRotationSpeedFactor", 0.0))};
    for (const MtoonTextureName& t : kMtoonTextureNames) {
        const tinygltf::Value& info = member(e, t.v1);
        if (const int index = json_texture_index(info, "index"); index >= 0) {
            out.textures[t.key] = index;
            if (auto m3 = khr_texture_transform(member(member(info, "extensions"), "KHR_texture_transform")))
                out.uv_transforms[t.key] = *m3;
        }
    }

    // The glTF material's own (section 3.9.3 and 3.9.4 of glTF 2.0), as three.js's GLTFLoader
    // gives them to an MToonMaterial: emissiveFactor linear, KHR_materials_emissive_strength as
    // emissiveIntensity, normalTexture.scale as normalScale.
    if (g.emissiveFactor.size() == 3) {
        std::vector<float> emissive(3);
        for (size_t i = 0; i < 3; ++i)
            emissive[i] = std::isfinite(g.emissiveFactor[i]) ? float(std::max(g.emissiveFactor[i], 0.0)) : 0.0f;
        m["emissive"] = emissive;
    }
    if (const auto strength = g.extensions.find("KHR_materials_emissive_strength"); strength != g.extensions.end())
        m["emissive-intensity"] = {float(std::max(json_number(strength->second, "emissiveStrength", 1.0), 0.0))};
    auto transform_of = [&](const tinygltf::ExtensionMap& extensions, const char* key) {
        const auto it = extensions.find("KHR_texture_transform");
        if (it == extensions.end()) return;
        if (auto m3 = khr_texture_transform(it->second)) out.uv_transforms[key] = *m3;
    };
    if (g.emissiveTexture.index >= 0) {
        out.textures["emissive-texture"] = g.emissiveTexture.index;
        transform_of(g.emissiveTexture.extensions, "emissive-texture");
    }
    if (g.normalTexture.index >= 0) {
        out.textures["normal-texture"] = g.normalTexture.index;
        transform_of(g.normalTexture.extensions, "normal-texture");
        if (std::isfinite(g.normalTexture.scale)) m["normal-scale"] = {float(g.normalTexture.scale)};
    }
    return out;
}

VrmMaterial vrm0_mtoon(const tinygltf::Value& props) {
    const tinygltf::Value& f = member(props, "floatProperties");
    const tinygltf::Value& v = member(props, "vectorProperties");
    const tinygltf::Value& tex = member(props, "textureProperties");
    VrmMaterial out;
    auto& m = out.values;
    m = mtoon_defaults();
    m["shade-color"] = gamma_decode(json_numbers(v, "_ShadeColor", {0.97f, 0.81f, 0.86f}));
    // MToon 0.x's shade shift and toony as 1.0's: toony' = lerp(toony, 1, 0.5 + 0.5 shift),
    // shift' = -shift - (1 - toony').
    const double shift0 = json_number(f, "_ShadeShift", 0.0), toony0 = json_number(f, "_ShadeToony", 0.9);
    const double toony = toony0 + (1.0 - toony0) * (0.5 + 0.5 * shift0);
    m["shading-toony"] = {float(toony)};
    m["shading-shift"] = {float(-shift0 - (1.0 - toony))};
    m["rim-color"] = gamma_decode(json_numbers(v, "_RimColor", {0, 0, 0}));
    m["rim-fresnel-power"] = {float(json_number(f, "_RimFresnelPower", 1.0))};
    m["rim-lift"] = {float(json_number(f, "_RimLift", 0.0))};
    m["rim-lighting-mix"] = {float(json_number(f, "_RimLightingMix", 0.0))};
    const double mode = json_number(f, "_OutlineWidthMode", 0.0);
    m["outline-width-mode"] = {mode == 1.0 ? 1.0f : mode == 2.0 ? 2.0f : 0.0f};
    m["outline-width"] = {float(0.01 * json_number(f, "_OutlineWidth", 0.0))};  // v0 widths are centimetres
    m["outline-color"] = gamma_decode(json_numbers(v, "_OutlineColor", {0, 0, 0}));
    m["outline-lighting-mix"] = {
        json_number(f, "_OutlineColorMode", 0.0) == 1.0 ? float(json_number(f, "_OutlineLightingMix", 1.0)) : 0.0f};
    const double gi = json_number(f, "_IndirectLightIntensity", 0.1);
    m["gi-equalization"] = {gi != 0.0 ? float(1.0 - gi) : 0.9f};
    m["emissive"] = gamma_decode(json_numbers(v, "_EmissionColor", {0, 0, 0}));
    m["normal-scale"] = {float(json_number(f, "_BumpScale", 1.0))};
    m["uv-animation-scroll-x-speed"] = {float(json_number(f, "_UvAnimScrollX", 0.0))};
    // MToon 0.x scrolled v up the image (Unity's uvs), 1.0 scrolls it down: the sign flips.
    m["uv-animation-scroll-y-speed"] = {float(-json_number(f, "_UvAnimScrollY", 0.0))};
    m["uv-animation-rotation-speed"] = {float(json_number(f, "_UvAnimRotation", 0.0))};
    for (const MtoonTextureName& t : kMtoonTextureNames)
        if (t.v0)
            if (const int index = json_texture_index(tex, t.v0); index >= 0) out.textures[t.key] = index;
    if (const int index = json_texture_index(tex, "_EmissionMap"); index >= 0) out.textures["emissive-texture"] = index;
    if (const int index = json_texture_index(tex, "_BumpMap"); index >= 0) out.textures["normal-texture"] = index;
    // three-vrm gives the main texture's transform to every texture but the matcap.
    if (const auto main = vrm0_main_texture_transform(v))
        for (const auto& [key, index] : out.textures)
            if (key != "matcap-texture") out.uv_transforms[key] = *main;
    return out;
}

VrmMaterial vrm0_unlit(const glm::vec3& lit, int main_texture, const glm::mat3& main_transform) {
    VrmMaterial out;
    out.values = mtoon_defaults();
    out.values["shade-color"] = {lit.r, lit.g, lit.b};
    if (main_texture >= 0) {
        out.textures["shade-multiply-texture"] = main_texture;
        if (main_transform != glm::mat3(1.0f)) out.uv_transforms["shade-multiply-texture"] = main_transform;
    }
    return out;
}

}  // namespace inkshade::io
