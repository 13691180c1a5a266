// GltfMaterialTable (gltf_materials.hpp): glTF materials (section 3.9) and VRM MToon as Mesh
// materials, their images decoded on first use.
#include "io/gltf_materials.hpp"

#include <fstream>  // as in gltf_container.cpp: tiny_gltf.h needs it with TINYGLTF_NO_FS

#include "io/tiny_gltf_config.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <optional>
#include <set>

#include "inkshade/error.hpp"
#include "io/gltf_container.hpp"
#include "io/texture_image.hpp"
#include "io/texture_transform.hpp"
#include "io/vrm_materials.hpp"

namespace inkshade::io {
namespace {

std::string percent_decode(const std::string& uri) {
    std::string out;
    for (size_t i = 0; i < uri.size(); ++i) {
        auto hex = [](char c) {
            return std::isxdigit(static_cast<unsigned char>(c))
                       ? (std::isdigit(static_cast<unsigned char>(c)) ? c - '0' : (std::tolower(c) - 'a' + 10))
                       : -1;
        };
        if (uri[i] == '%' && i + 2 < uri.size() && hex(uri[i + 1]) >= 0 && hex(uri[i + 2]) >= 0) {
            out += char(hex(uri[i + 1]) * 16 + hex(uri[i + 2]));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

// glTF alphaMode, alphaCutoff, doubleSided and baseColorFactor's alpha (sections 3.9.4, 3.9.5),
// as three.js's GLTFLoader reads them; the default material is opaque and single-sided.
void read_alpha_and_sides(const tinygltf::Material& g, Material& m) {
    const std::vector<double>& f = g.pbrMetallicRoughness.baseColorFactor;
    m.alpha = f.size() >= 4 && std::isfinite(f[3]) ? std::clamp(float(f[3]), 0.0f, 1.0f) : 1.0f;
    m.alpha_mode = g.alphaMode == "MASK"    ? AlphaMode::Mask
                   : g.alphaMode == "BLEND" ? AlphaMode::Blend
                                            : AlphaMode::Opaque;
    m.alpha_cutoff = std::isfinite(g.alphaCutoff) ? float(std::max(g.alphaCutoff, 0.0)) : 0.5f;
    m.sides = g.doubleSided ? FaceSides::Double : FaceSides::Front;
}

// three-vrm's MToonMaterialLoaderPlugin: an MToon material's mesh gets renderOrder
// renderQueueOffsetNumber + (transparentWithZWrite ? 0 : 19), and the z-write flag sets depthWrite.
void mtoon_render_order(Material& m, bool z_write, double queue_offset) {
    m.blend_depth_write = z_write;
    m.render_order = (z_write ? 0 : 19) + int(std::clamp(queue_offset, -1e6, 1e6));
}

bool keyword_on(const tinygltf::Value& props, const char* key) {
    if (!props.IsObject() || !props.Has("keywordMap")) return false;
    const tinygltf::Value& k = props.Get("keywordMap");
    return k.IsObject() && k.Has(key) && k.Get(key).IsBool() && k.Get(key).Get<bool>();
}

// Is a VRM 0.x material transparent (and does it write depth, `z_write`)?
bool v0_transparent(const tinygltf::Value& props, const std::string& shader, bool* z_write) {
    const tinygltf::Value& f = props.Has("floatProperties") ? props.Get("floatProperties") : props;
    const bool unlit_z = shader == "VRM/UnlitTransparentZWrite";
    const bool has_blend =
        props.Has("keywordMap") && props.Get("keywordMap").IsObject() && props.Get("keywordMap").Has("_ALPHABLEND_ON");
    *z_write = json_number(f, "_ZWrite", 0.0) == 1.0 || unlit_z;
    return has_blend || shader == "VRM/UnlitTransparent" || unlit_z;
}

std::string shader_of(const tinygltf::Value& props) {
    return props.IsObject() && props.Has("shader") && props.Get("shader").IsString()
               ? props.Get("shader").Get<std::string>()
               : std::string();
}

// A glTF sampler as three.js's GLTFLoader reads it (WEBGL_FILTERS, WEBGL_WRAPPINGS): absent or
// unknown values are magnify LINEAR, minify LINEAR_MIPMAP_LINEAR, wrap REPEAT; texture.anisotropy
// stays three.js's 1. Null: a texture without a sampler.
TextureSampler gltf_sampler(const tinygltf::Sampler* s) {
    TextureSampler out;
    out.anisotropic = false;
    if (!s) return out;
    auto wrap = [](int mode) {
        if (mode == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE) return TextureWrap::ClampToEdge;
        if (mode == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT) return TextureWrap::MirroredRepeat;
        return TextureWrap::Repeat;
    };
    out.wrap_s = wrap(s->wrapS);
    out.wrap_t = wrap(s->wrapT);
    if (s->magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST) out.mag = TextureFilter::Nearest;
    switch (s->minFilter) {
        case TINYGLTF_TEXTURE_FILTER_NEAREST: out.min = TextureFilter::Nearest; out.mipmap.reset(); break;
        case TINYGLTF_TEXTURE_FILTER_LINEAR: out.mipmap.reset(); break;
        case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST:
            out.min = TextureFilter::Nearest;
            out.mipmap = TextureFilter::Nearest;
            break;
        case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST: out.mipmap = TextureFilter::Nearest; break;
        case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR: out.min = TextureFilter::Nearest; break;
        default: break;  // LINEAR_MIPMAP_LINEAR, absent, unknown
    }
    return out;
}

}  // namespace

GltfMaterialTable::GltfMaterialTable(const tinygltf::Model& model, const GltfAccessorReader& reader,
                                     const std::string& path, Mesh& mesh)
    : model_(model),
      reader_(reader),
      path_(path),
      mesh_(mesh),
      images_(model.images.size()),
      tried_(model.images.size(), 0),
      index_(model.materials.size() + 1, kNone) {
    const auto vrm = model.extensions.find("VRM");
    if (vrm != model.extensions.end() && vrm->second.IsObject() && vrm->second.Has("materialProperties")) {
        const tinygltf::Value& list = vrm->second.Get("materialProperties");
        if (list.IsArray()) v0_ = &list;
    }
    if (v0_) v0_queue_maps();
}

uint32_t GltfMaterialTable::index(int gltf) {
    const size_t slot = gltf >= 0 && size_t(gltf) < model_.materials.size() ? size_t(gltf) : model_.materials.size();
    if (index_[slot] == kNone) {
        index_[slot] = uint32_t(mesh_.materials.size());
        Material fallback{"default", glm::vec3(1.0f)};
        fallback.sides = FaceSides::Front;  // section 3.9.6: single-sided, opaque
        mesh_.materials.push_back(slot == model_.materials.size() ? fallback : build(slot));
    }
    return index_[slot];
}

int GltfMaterialTable::uv_set(int gltf) const {
    if (gltf < 0 || size_t(gltf) >= model_.materials.size()) return 0;
    return std::clamp(model_.materials[size_t(gltf)].pbrMetallicRoughness.baseColorTexture.texCoord, 0, 7);
}

void GltfMaterialTable::v0_alpha_and_sides(const tinygltf::Value& props, const std::string& shader, Material& m) const {
    const tinygltf::Value& f = props.Has("floatProperties") ? props.Get("floatProperties") : props;
    const tinygltf::Value& v = props.Has("vectorProperties") ? props.Get("vectorProperties") : props;
    const float alpha = json_numbers(v, "_Color", {1, 1, 1, 1})[3];
    bool blend = false, z_write = false, cutout = false;
    if (shader == "VRM/MToon") {
        blend = keyword_on(props, "_ALPHABLEND_ON");
        z_write = blend && json_number(f, "_ZWrite", 0.0) == 1.0;
        cutout = keyword_on(props, "_ALPHATEST_ON");
        m.alpha = std::clamp(alpha, 0.0f, 1.0f);
        m.sides = json_number(f, "_CullMode", 2.0) == 0.0 ? FaceSides::Double : FaceSides::Front;
    } else {
        z_write = shader == "VRM/UnlitTransparentZWrite";
        blend = z_write || shader == "VRM/UnlitTransparent";
        cutout = shader == "VRM/UnlitCutout";
        m.alpha = std::clamp(std::pow(std::max(alpha, 0.0f), 2.2f), 0.0f, 1.0f);
    }
    m.alpha_mode = blend ? AlphaMode::Blend : cutout ? AlphaMode::Mask : AlphaMode::Opaque;
    m.alpha_cutoff = cutout ? float(std::max(json_number(f, "_Cutoff", 0.5), 0.0)) : 0.5f;
    mtoon_render_order(m, z_write, v0_queue_offset(props, shader));
}

void GltfMaterialTable::v0_queue_maps() {
    std::set<double> plain, z;
    for (size_t i = 0; i < v0_->ArrayLen(); ++i) {
        const tinygltf::Value& props = v0_->Get(int(i));
        bool z_write = false;
        if (!props.IsObject() || !v0_transparent(props, shader_of(props), &z_write)) continue;
        if (props.Has("renderQueue") && props.Get("renderQueue").IsNumber())
            (z_write ? z : plain).insert(props.Get("renderQueue").GetNumberAsDouble());
    }
    int i = 0;
    for (double q : plain) queue_plain_[q] = std::clamp(i++ - int(plain.size()) + 1, -9, 0);
    i = 0;
    for (double q : z) queue_z_[q] = std::clamp(i++, 0, 9);
}

double GltfMaterialTable::v0_queue_offset(const tinygltf::Value& props, const std::string& shader) const {
    bool z_write = false;
    if (!v0_transparent(props, shader, &z_write) || !props.Has("renderQueue") || !props.Get("renderQueue").IsNumber())
        return 0.0;
    const auto& map = z_write ? queue_z_ : queue_plain_;
    const auto it = map.find(props.Get("renderQueue").GetNumberAsDouble());
    return it == map.end() ? 0.0 : it->second;
}

Material GltfMaterialTable::build(size_t i) {
    const tinygltf::Material& g = model_.materials[i];
    Material m;
    m.name = g.name.empty() ? "material " + std::to_string(i) : g.name;
    const std::vector<double>& f = g.pbrMetallicRoughness.baseColorFactor;  // linear RGBA
    for (size_t k = 0; k < 3 && k < f.size(); ++k)
        m.diffuse[int(k)] = std::isfinite(f[k]) ? std::clamp(float(f[k]), 0.0f, 1.0f) : 1.0f;
    if (f.size() < 3) m.diffuse = glm::vec3(1.0f);
    int texture = g.pbrMetallicRoughness.baseColorTexture.index;
    std::optional<glm::mat3> base_transform;
    if (texture >= 0) {
        const auto& extensions = g.pbrMetallicRoughness.baseColorTexture.extensions;
        if (const auto it = extensions.find("KHR_texture_transform"); it != extensions.end())
            base_transform = khr_texture_transform(it->second);
    }

    read_alpha_and_sides(g, m);
    const auto v1 = g.extensions.find("VRMC_materials_mtoon");
    if (v1 != g.extensions.end()) {
        const tinygltf::Value& e = v1->second;
        add_mtoon(vrm1_mtoon(g, e), m);
        const bool z_write = e.IsObject() && e.Has("transparentWithZWrite") &&
                             e.Get("transparentWithZWrite").IsBool() && e.Get("transparentWithZWrite").Get<bool>();
        mtoon_render_order(m, z_write, json_number(e, "renderQueueOffsetNumber", 0.0));
    } else if (v0_ != nullptr && i < v0_->ArrayLen()) {
        const tinygltf::Value& props = v0_->Get(int(i));
        const std::string shader = props.IsObject() && props.Has("shader") && props.Get("shader").IsString()
                                       ? props.Get("shader").Get<std::string>()
                                       : std::string();
        if (shader == "VRM/MToon" || shader.rfind("VRM/Unlit", 0) == 0) {
            // Like three-vrm: the v0 properties replace the glTF material's colour and texture.
            const tinygltf::Value& v = props.Has("vectorProperties") ? props.Get("vectorProperties") : props;
            std::vector<float> c = gamma_decode(json_numbers(v, "_Color", {1, 1, 1}));
            m.diffuse = glm::clamp(glm::vec3(c[0], c[1], c[2]), 0.0f, 1.0f);
            v0_alpha_and_sides(props, shader, m);
            const int main =
                json_texture_index(props.Has("textureProperties") ? props.Get("textureProperties") : props, "_MainTex");
            if (main >= 0) texture = main;
            const std::optional<glm::mat3> main_transform = vrm0_main_texture_transform(v);
            if (main >= 0) base_transform = main_transform;
            // unlit: an MToon whose shade colour and shade multiply texture are the lit ones
            add_mtoon(shader == "VRM/MToon" ? vrm0_mtoon(props)
                                            : vrm0_unlit(m.diffuse, main, main_transform.value_or(glm::mat3(1.0f))),
                      m);
        }
    }
    if (texture >= 0) m.texture = texture_of(texture, m.name);
    if (m.texture && base_transform && *base_transform != glm::mat3(1.0f))
        m.uv_transforms["base-color-texture"] = *base_transform;
    // three-vrm removes KHR_materials_unlit from a material that has MToon.
    m.unlit = m.mtoon.empty() && g.extensions.count("KHR_materials_unlit") > 0;
    return m;
}

void GltfMaterialTable::add_mtoon(const VrmMaterial& vrm, Material& m) {
    m.mtoon = vrm.values;
    for (const auto& [key, index] : vrm.textures)
        if (auto t = texture_of(index, m.name)) {
            m.mtoon_textures[key] = std::move(t);
            const auto transform = vrm.uv_transforms.find(key);
            if (transform != vrm.uv_transforms.end() && transform->second != glm::mat3(1.0f))
                m.uv_transforms[key] = transform->second;
        }
}

std::shared_ptr<const Texture> GltfMaterialTable::texture_of(int texture, const std::string& material) {
    if (size_t(texture) >= model_.textures.size()) {
        mesh_.warnings.push_back(path_ + ": material '" + printable_first_line(material) + "' refers to texture " +
                                 std::to_string(texture) + ", which does not exist; using the base colour");
        return nullptr;
    }
    const int image = model_.textures[size_t(texture)].source;
    if (image < 0 || size_t(image) >= model_.images.size()) {  // e.g. KHR_texture_basisu / EXT_texture_webp only
        mesh_.warnings.push_back(path_ + ": texture " + std::to_string(texture) +
                                 " has no image Inkshade can decode (PNG or JPEG); using the base colour");
        return nullptr;
    }
    if (!tried_[size_t(image)]) {
        tried_[size_t(image)] = 1;
        images_[size_t(image)] = decode_image(size_t(image));
        if (images_[size_t(image)]) {  // glTF's sampling without a sampler (section 5.26, three.js's defaults)
            auto t = std::make_shared<Texture>(*images_[size_t(image)]);
            t->sampler = gltf_sampler(nullptr);
            images_[size_t(image)] = std::move(t);
        }
    }
    const std::shared_ptr<const Texture>& decoded = images_[size_t(image)];
    const int s = model_.textures[size_t(texture)].sampler;
    if (!decoded || s < 0 || size_t(s) >= model_.samplers.size()) return decoded;
    const TextureSampler sampler = gltf_sampler(&model_.samplers[size_t(s)]);
    if (sampler == decoded->sampler) return decoded;
    std::shared_ptr<const Texture>& copy = sampled_[{size_t(image), s}];
    if (!copy) {
        auto t = std::make_shared<Texture>(*decoded);
        t->sampler = sampler;
        copy = std::move(t);
    }
    return copy;
}

std::shared_ptr<const Texture> GltfMaterialTable::decode_image(size_t i) {
    const tinygltf::Image& image = model_.images[i];
    const std::string label = image.uri.empty() ? "image " + std::to_string(i) : image.uri;
    const std::string source = path_ + "#image " + std::to_string(i);
    std::string problem;
    std::shared_ptr<const Texture> texture;
    if (image.bufferView >= 0) {
        if (size_t(image.bufferView) >= model_.bufferViews.size()) {
            problem = "bufferView " + std::to_string(image.bufferView) + " does not exist";
        } else {
            try {
                const unsigned char* bytes = reader_.buffer_view_bytes(image.bufferView, "image " + std::to_string(i));
                texture =
                    decode_texture(bytes, model_.bufferViews[size_t(image.bufferView)].byteLength, source, problem);
            } catch (const InputError& e) {  // a bad image range costs the texture, not the mesh
                problem = std::string(e.what()).substr(path_.size() + 2);
            }
        }
    } else if (!image.image.empty()) {  // data: URI, kept by keep_encoded_image
        texture = decode_texture(image.image.data(), image.image.size(), source, problem);
    } else if (!image.uri.empty()) {
        std::filesystem::path dir = std::filesystem::path(path_).parent_path();
        return load_texture_or_warn(path_, percent_decode(image.uri), {dir.empty() ? std::filesystem::path(".") : dir},
                                    mesh_.warnings);
    } else {
        problem = "no image data";
    }
    if (!texture) mesh_.warnings.push_back(texture_warning(path_, label, problem));
    return texture;
}

}  // namespace inkshade::io
