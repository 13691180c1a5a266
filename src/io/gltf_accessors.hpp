// What the parts of the glTF reader outside gltf_reader.cpp (skins, morph targets, animations)
// read accessors through: gltf_reader.cpp's reader, which checks every byte range against the
// real buffer sizes before it reads and bounds every count before it allocates.
#pragma once
#include <initializer_list>
#include <string>
#include <vector>

namespace inkshade::io {

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

}  // namespace inkshade::io
