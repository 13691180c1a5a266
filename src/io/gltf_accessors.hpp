// The glTF reader's accessors (glTF 2.0 section 3.6). GltfFloatReader is what the parts of the
// reader that read animation-like data (skins, morph targets, animations) see; GltfAccessorReader
// implements it and also reads vertex indices and bufferView bytes (images), checking every byte
// range against the real buffer sizes before it reads and bounding every count before it
// allocates.
#pragma once
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
struct Accessor;
}  // namespace tinygltf

namespace inkshade::io {

// Bounds on what a file can make us allocate. Data-backed counts are also bounded by the
// buffer sizes; these catch instancing (one mesh under a million nodes) and accessors without
// a bufferView (zeros of any claimed count).
constexpr size_t kMaxGltfVertices = size_t(1) << 28;
constexpr size_t kMaxGltfTriangles = size_t(1) << 28;

class GltfFloatReader {
public:
    // Float components of accessor `index` (count x components, interleaving removed; normalized
    // integers mapped to [0, 1] or [-1, 1]), each finite. `allowed_counts` lists the accepted
    // components per element (1..4 for SCALAR..VEC4, 16 for MAT4); `role` names the accessor in
    // errors. Throws InputError("FILE: problem").
    virtual std::vector<float> floats(int index, const std::string& role, std::initializer_list<int> allowed_counts,
                                      int& components) const = 0;
    // Throws InputError("FILE: problem").
    [[noreturn]] virtual void fail(const std::string& problem) const = 0;

protected:
    ~GltfFloatReader() = default;
};

// Reads accessors of a loaded model, checking every range against the real buffer sizes.
class GltfAccessorReader final : public GltfFloatReader {
public:
    GltfAccessorReader(const tinygltf::Model& model, const std::string& path) : model_(model), path_(path) {}

    // A strided view of `count` elements of `element_bytes` starting `offset` bytes into
    // bufferView `view`; `what` names the accessor in errors.
    struct Span {
        const unsigned char* data = nullptr;
        size_t stride = 0;
    };
    Span span(int view, size_t offset, size_t count, size_t element_bytes, size_t component_bytes, bool strided,
              const std::string& what) const;

    // The bytes of a bufferView, after checking it lies inside its buffer.
    const unsigned char* buffer_view_bytes(int view, const std::string& what) const;

    const tinygltf::Accessor& accessor(int index, const std::string& role) const;

    // Float components of accessor `index` (count x components, interleaving removed).
    // `allowed_counts` lists the accepted component counts (e.g. {3} for POSITION).
    std::vector<float> floats(int index, const std::string& role, std::initializer_list<int> allowed_counts,
                              int& components) const override;

    // Vertex indices (section 3.7.2.1: SCALAR, unsigned byte/short/int), each checked against
    // `vertex_count`.
    std::vector<uint32_t> indices(int index, const std::string& role, size_t vertex_count) const;

    [[noreturn]] void fail(const std::string& problem) const override;

private:
    void check_count(const tinygltf::Accessor& a, const std::string& what) const;
    // Section 3.6.2.3: strictly increasing element indices, each below the accessor's count.
    std::vector<uint32_t> sparse_indices(const tinygltf::Accessor& a, const std::string& what) const;

    const tinygltf::Model& model_;
    const std::string& path_;
};

}  // namespace inkshade::io
