// glTF / GLB files built by hand for the reader tests: a JSON document plus one binary buffer,
// written as GLB, as .gltf + .bin, or as .gltf with data: URIs. Also a tiny PNG encoder.
#pragma once
#include <stb_image_write.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace inkshade::test {

// glTF 2.0 enumerations used below (section 3.6.2.2 and 3.7.2.1).
constexpr int kByte = 5120, kUByte = 5121, kShort = 5122, kUShort = 5123, kUInt = 5125, kFloat = 5126;
constexpr int kPoints = 0, kLines = 1, kTriangles = 4, kStrip = 5, kFan = 6;

inline std::string base64(const std::string& in) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    size_t i = 0;
    for (; i + 2 < in.size(); i += 3) {
        uint32_t v = uint32_t(uint8_t(in[i])) << 16 | uint32_t(uint8_t(in[i + 1])) << 8 | uint8_t(in[i + 2]);
        for (int k = 3; k >= 0; --k) out += table[(v >> (6 * k)) & 63];
    }
    if (i + 1 == in.size()) {
        uint32_t v = uint32_t(uint8_t(in[i])) << 16;
        out += table[(v >> 18) & 63];
        out += table[(v >> 12) & 63];
        out += "==";
    } else if (i + 2 == in.size()) {
        uint32_t v = uint32_t(uint8_t(in[i])) << 16 | uint32_t(uint8_t(in[i + 1])) << 8;
        out += table[(v >> 18) & 63];
        out += table[(v >> 12) & 63];
        out += table[(v >> 6) & 63];
        out += '=';
    }
    return out;
}

// An RGBA8 PNG (rows top first) through stb_image_write, as the texture tests' input.
inline std::string png_bytes(int w, int h, const std::vector<uint8_t>& rgba) {
    std::string out;
    stbi_write_png_to_func(
        [](void* ctx, void* data, int size) {
        static_cast<std::string*>(ctx)->append(static_cast<char*>(data), size_t(size));
        },
        &out, w, h, 4, rgba.data(), w * 4);
    return out;
}

// 2 x 2 texture: red, green (top row), blue, white (bottom row).
inline const std::vector<uint8_t> kTexturePixels = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};

class GltfBuilder {
public:
    nlohmann::json doc = {{"asset", {{"version", "2.0"}}}};
    std::string bin;

    // Appends bytes (4-byte aligned) as a new bufferView; returns its index.
    int view(const void* data, size_t size, size_t stride = 0) {
        while (bin.size() % 4) bin.push_back('\0');
        nlohmann::json v = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", size}};
        if (stride) v["byteStride"] = stride;
        bin.append(static_cast<const char*>(data), size);
        doc["bufferViews"].push_back(v);
        return int(doc["bufferViews"].size()) - 1;
    }
    int accessor(int view, int component_type, size_t count, const std::string& type, bool normalized = false,
                 size_t offset = 0) {
        nlohmann::json a = {{"componentType", component_type}, {"count", count}, {"type", type}};
        if (view >= 0) a["bufferView"] = view;
        if (offset) a["byteOffset"] = offset;
        if (normalized) a["normalized"] = true;
        doc["accessors"].push_back(a);
        return int(doc["accessors"].size()) - 1;
    }
    template <class T>
    int data(const std::vector<T>& values, int component_type, size_t components, const std::string& type,
             bool normalized = false) {
        int v = view(values.data(), values.size() * sizeof(T));
        return accessor(v, component_type, values.size() / components, type, normalized);
    }
    int floats(const std::vector<float>& values, const std::string& type, size_t components) {
        return data(values, kFloat, components, type);
    }
    // A mesh with one primitive; returns the mesh index.
    int mesh(const nlohmann::json& attributes, int indices = -1, int material = -1, int mode = kTriangles) {
        nlohmann::json p = {{"attributes", attributes}};
        if (indices >= 0) p["indices"] = indices;
        if (material >= 0) p["material"] = material;
        if (mode != kTriangles) p["mode"] = mode;
        doc["meshes"].push_back({{"primitives", nlohmann::json::array({p})}});
        return int(doc["meshes"].size()) - 1;
    }
    int node(nlohmann::json n) {
        doc["nodes"].push_back(std::move(n));
        return int(doc["nodes"].size()) - 1;
    }
    void scene(const std::vector<int>& roots) {
        doc["scenes"] = nlohmann::json::array({{{"nodes", roots}}});
        doc["scene"] = 0;
    }
    // An image stored in a bufferView (GLB style) used as texture; returns the texture index.
    int texture_in_buffer(const std::string& png) {
        int v = view(png.data(), png.size());
        doc["images"].push_back({{"bufferView", v}, {"mimeType", "image/png"}});
        return add_texture();
    }
    int texture_at_uri(const std::string& uri) {
        doc["images"].push_back({{"uri", uri}});
        return add_texture();
    }
    int material(std::vector<float> base_colour, int texture = -1) {
        nlohmann::json pbr = {{"baseColorFactor", base_colour}};
        if (texture >= 0) pbr["baseColorTexture"] = {{"index", texture}};
        doc["materials"].push_back({{"pbrMetallicRoughness", pbr}});
        return int(doc["materials"].size()) - 1;
    }

    std::string json_with_buffer(const std::string& uri) const {
        nlohmann::json d = doc;
        d["buffers"] = nlohmann::json::array({{{"byteLength", padded_bin().size()}, {"uri", uri}}});
        return d.dump();
    }
    std::string gltf_embedded() const {
        return json_with_buffer("data:application/octet-stream;base64," + base64(padded_bin()));
    }
    std::string padded_bin() const {
        std::string b = bin;
        while (b.size() % 4) b.push_back('\0');
        return b;
    }
    std::string glb() const {
        nlohmann::json d = doc;
        std::string b = padded_bin();
        if (!b.empty()) d["buffers"] = nlohmann::json::array({{{"byteLength", b.size()}}});
        std::string json = d.dump();
        while (json.size() % 4) json.push_back(' ');
        std::string out = "glTF";
        put32(out, 2);
        put32(out, uint32_t(12 + 8 + json.size() + (b.empty() ? 0 : 8 + b.size())));
        put32(out, uint32_t(json.size()));
        put32(out, 0x4E4F534A);
        out += json;
        if (!b.empty()) {
            put32(out, uint32_t(b.size()));
            put32(out, 0x004E4942);
            out += b;
        }
        return out;
    }

private:
    int add_texture() {
        doc["textures"].push_back({{"source", int(doc["images"].size()) - 1}});
        return int(doc["textures"].size()) - 1;
    }
    static void put32(std::string& s, uint32_t v) {
        char b[4];
        std::memcpy(b, &v, 4);
        s.append(b, 4);
    }
};

// A unit quad in the z = 0 plane facing +z, with glTF uvs (origin top-left), u16 indices.
inline GltfBuilder textured_quad(bool texture_in_buffer = true) {
    GltfBuilder g;
    int pos = g.floats({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, "VEC3", 3);
    int uv = g.floats({0, 1, 1, 1, 1, 0, 0, 0}, "VEC2", 2);
    int idx = g.data(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}, kUShort, 1, "SCALAR");
    int tex = texture_in_buffer ? g.texture_in_buffer(png_bytes(2, 2, kTexturePixels)) : g.texture_at_uri("quad.png");
    int mat = g.material({0.5f, 0.25f, 1.0f, 1.0f}, tex);
    int mesh = g.mesh({{"POSITION", pos}, {"TEXCOORD_0", uv}}, idx, mat);
    g.scene({g.node({{"mesh", mesh}})});
    return g;
}

}  // namespace inkshade::test
