// GltfAccessorReader (gltf_accessors.hpp): accessor bytes as floats or vertex indices, every
// range checked first (glTF 2.0 section 3.6; KHR_mesh_quantization's component types).
#include "io/gltf_accessors.hpp"

#include <fstream>  // as in gltf_container.cpp: tiny_gltf.h needs it with TINYGLTF_NO_FS

#include "io/tiny_gltf_config.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "inkshade/error.hpp"

namespace inkshade::io {
namespace {

// Accessors without a bufferView are zeros (plus sparse values): no bytes back their count.
constexpr size_t kMaxDatalessElements = size_t(1) << 22;

int component_size(int type) {
    switch (type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
        default: return 0;
    }
}

int component_count(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return 1;
        case TINYGLTF_TYPE_VEC2: return 2;
        case TINYGLTF_TYPE_VEC3: return 3;
        case TINYGLTF_TYPE_VEC4: return 4;
        case TINYGLTF_TYPE_MAT4: return 16;  // a skin's inverseBindMatrices (no padding: 4-byte components)
        default: return 0;
    }
}

// One component as float. Normalized integers map to [0,1] or [-1,1] (section 3.11, the
// formulas KHR_mesh_quantization uses too).
float component(const unsigned char* p, int type, bool normalized) {
    switch (type) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: {
            float f;
            std::memcpy(&f, p, 4);
            return f;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? float(p[0]) / 255.0f : float(p[0]);
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            int8_t v;
            std::memcpy(&v, p, 1);
            return normalized ? std::max(float(v) / 127.0f, -1.0f) : float(v);
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            uint16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? float(v) / 65535.0f : float(v);
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            int16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? std::max(float(v) / 32767.0f, -1.0f) : float(v);
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            uint32_t v;
            std::memcpy(&v, p, 4);
            return float(v);
        }
        default: return 0.0f;
    }
}

uint32_t index_value(const unsigned char* p, int type) {
    switch (type) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return p[0];
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            uint16_t v;
            std::memcpy(&v, p, 2);
            return v;
        }
        default: {
            uint32_t v;
            std::memcpy(&v, p, 4);
            return v;
        }
    }
}

std::string accessor_name(int index, const std::string& role) {
    return "accessor " + std::to_string(index) + " (" + role + ")";
}

}  // namespace

GltfAccessorReader::Span GltfAccessorReader::span(int view, size_t offset, size_t count, size_t element_bytes,
                                                  size_t component_bytes, bool strided, const std::string& what) const {
    if (view < 0 || size_t(view) >= model_.bufferViews.size())
        fail(what + " refers to bufferView " + std::to_string(view) + " but the file has " +
             std::to_string(model_.bufferViews.size()));
    const tinygltf::BufferView& bv = model_.bufferViews[size_t(view)];
    const unsigned char* base = buffer_view_bytes(view, what);
    size_t stride = element_bytes;
    if (strided && bv.byteStride != 0) {
        // Section 3.6.2.4: 4..252, a multiple of the component size, at least one element.
        if (bv.byteStride < element_bytes || bv.byteStride > 252 || bv.byteStride % component_bytes != 0)
            fail(what + ": bufferView " + std::to_string(view) + " has byteStride " + std::to_string(bv.byteStride) +
                 " (elements are " + std::to_string(element_bytes) + " bytes)");
        stride = bv.byteStride;
    }
    if (count == 0) return {base, stride};
    {
        // offset + stride * (count - 1) + element_bytes <= byteLength, without overflow.
        const size_t length = bv.byteLength;
        bool fits = offset <= length && element_bytes <= length - offset &&
                    (count - 1) <= (length - offset - element_bytes) / stride;
        if (!fits)
            fail(what + ": " + std::to_string(count) + " elements of " + std::to_string(element_bytes) +
                 " bytes from offset " + std::to_string(offset) + " do not fit in bufferView " + std::to_string(view) +
                 " (" + std::to_string(length) + " bytes)");
    }
    return {base + offset, stride};
}

const unsigned char* GltfAccessorReader::buffer_view_bytes(int view, const std::string& what) const {
    const tinygltf::BufferView& bv = model_.bufferViews[size_t(view)];
    if (bv.buffer < 0 || size_t(bv.buffer) >= model_.buffers.size())
        fail(what + ": bufferView " + std::to_string(view) + " refers to buffer " + std::to_string(bv.buffer) +
             " but the file has " + std::to_string(model_.buffers.size()));
    const std::vector<unsigned char>& data = model_.buffers[size_t(bv.buffer)].data;
    if (bv.byteOffset > data.size() || bv.byteLength > data.size() - bv.byteOffset)
        fail(what + ": bufferView " + std::to_string(view) + " (bytes " + std::to_string(bv.byteOffset) + ".." +
             std::to_string(bv.byteOffset + bv.byteLength) + ") is past the end of buffer " +
             std::to_string(bv.buffer) + " (" + std::to_string(data.size()) + " bytes)");
    return data.data() + bv.byteOffset;
}

const tinygltf::Accessor& GltfAccessorReader::accessor(int index, const std::string& role) const {
    if (index < 0 || size_t(index) >= model_.accessors.size())
        fail(role + " refers to accessor " + std::to_string(index) + " but the file has " +
             std::to_string(model_.accessors.size()));
    return model_.accessors[size_t(index)];
}

std::vector<float> GltfAccessorReader::floats(int index, const std::string& role,
                                              std::initializer_list<int> allowed_counts, int& components) const {
    const tinygltf::Accessor& a = accessor(index, role);
    const std::string what = accessor_name(index, role);
    components = component_count(a.type);
    if (std::find(allowed_counts.begin(), allowed_counts.end(), components) == allowed_counts.end())
        fail(what + " has an unsupported element type");
    const int csize = component_size(a.componentType);
    if (csize == 0) fail(what + " has unknown componentType " + std::to_string(a.componentType));
    check_count(a, what);
    const size_t nc = size_t(components), esize = nc * size_t(csize);
    // The range is checked before the allocation: a count is only trusted once bytes back it.
    Span s = a.bufferView >= 0 ? span(a.bufferView, a.byteOffset, a.count, esize, size_t(csize), true, what) : Span{};
    std::vector<float> out(a.count * nc, 0.0f);  // no bufferView: zeros (section 3.6.2.1)
    if (s.data) {
        for (size_t i = 0; i < a.count; ++i)
            for (size_t k = 0; k < nc; ++k)
                out[i * nc + k] = component(s.data + i * s.stride + k * size_t(csize), a.componentType, a.normalized);
    }
    if (a.sparse.isSparse) {
        std::vector<uint32_t> at = sparse_indices(a, what);
        Span values = span(a.sparse.values.bufferView, size_t(std::max(0, a.sparse.values.byteOffset)), at.size(),
                           esize, size_t(csize), false, what + " sparse values");
        for (size_t j = 0; j < at.size(); ++j)
            for (size_t k = 0; k < nc; ++k)
                out[size_t(at[j]) * nc + k] =
                    component(values.data + j * esize + k * size_t(csize), a.componentType, a.normalized);
    }
    for (size_t i = 0; i < out.size(); ++i)
        if (!std::isfinite(out[i])) fail(what + ": element " + std::to_string(i / nc) + " is not a finite number");
    return out;
}

std::vector<uint32_t> GltfAccessorReader::indices(int index, const std::string& role, size_t vertex_count) const {
    const tinygltf::Accessor& a = accessor(index, role);
    const std::string what = accessor_name(index, role);
    if (a.type != TINYGLTF_TYPE_SCALAR) fail(what + " is not SCALAR");
    if (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        fail(what + " has componentType " + std::to_string(a.componentType) +
             " (indices must be unsigned byte, short or int)");
    check_count(a, what);
    const size_t csize = size_t(component_size(a.componentType));
    // Index bufferViews are tightly packed (section 3.6.2.4: byteStride only for vertex attributes).
    Span s = a.bufferView >= 0 ? span(a.bufferView, a.byteOffset, a.count, csize, csize, false, what) : Span{};
    std::vector<uint32_t> out(a.count, 0);
    if (s.data)
        for (size_t i = 0; i < a.count; ++i) out[i] = index_value(s.data + i * csize, a.componentType);
    if (a.sparse.isSparse) {
        std::vector<uint32_t> at = sparse_indices(a, what);
        Span values = span(a.sparse.values.bufferView, size_t(std::max(0, a.sparse.values.byteOffset)), at.size(),
                           csize, csize, false, what + " sparse values");
        for (size_t j = 0; j < at.size(); ++j) out[at[j]] = index_value(values.data + j * csize, a.componentType);
    }
    for (size_t i = 0; i < out.size(); ++i)
        if (out[i] >= vertex_count)
            fail(what + ": index " + std::to_string(i) + " is " + std::to_string(out[i]) + " but the primitive has " +
                 std::to_string(vertex_count) + " vertices");
    return out;
}

void GltfAccessorReader::fail(const std::string& problem) const { throw InputError(path_, problem); }

void GltfAccessorReader::check_count(const tinygltf::Accessor& a, const std::string& what) const {
    if (a.count > kMaxGltfVertices * 3)
        fail(what + " claims " + std::to_string(a.count) + " elements (limit " + std::to_string(kMaxGltfVertices * 3) +
             ")");
    if (a.bufferView < 0 && a.count > kMaxDatalessElements)
        fail(what + " claims " + std::to_string(a.count) + " elements without a bufferView (limit " +
             std::to_string(kMaxDatalessElements) + ")");
}

std::vector<uint32_t> GltfAccessorReader::sparse_indices(const tinygltf::Accessor& a, const std::string& what) const {
    if (a.sparse.count < 0 || size_t(a.sparse.count) > a.count)
        fail(what + ": sparse count " + std::to_string(a.sparse.count) + " exceeds the accessor's " +
             std::to_string(a.count));
    const int type = a.sparse.indices.componentType;
    if (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        fail(what + ": sparse indices have componentType " + std::to_string(type));
    const size_t csize = size_t(component_size(type)), n = size_t(a.sparse.count);
    Span s = span(a.sparse.indices.bufferView, size_t(std::max(0, a.sparse.indices.byteOffset)), n, csize, csize, false,
                  what + " sparse indices");
    std::vector<uint32_t> at(n);
    for (size_t j = 0; j < n; ++j) {
        at[j] = index_value(s.data + j * csize, type);
        if (at[j] >= a.count) fail(what + ": sparse index " + std::to_string(at[j]) + " is out of range");
    }
    return at;
}

}  // namespace inkshade::io
