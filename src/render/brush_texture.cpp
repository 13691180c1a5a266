#include "render/brush_texture.hpp"

#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>

#include "core/embedded_file.hpp"
#include "io/texture_image.hpp"

namespace inkshade::render {

const std::vector<EmbeddedBinary>& embedded_brushes();  // generated (cmake/embed_binary_files.cmake)

const BrushImage* shipped_brush(const std::string& name) {
    static std::mutex mutex;
    static std::map<std::string, std::unique_ptr<BrushImage>> decoded;
    const std::lock_guard lock(mutex);
    if (auto it = decoded.find(name); it != decoded.end()) return it->second.get();
    for (const EmbeddedBinary& f : embedded_brushes()) {
        if (f.path != name + ".png") continue;
        std::string problem;
        const auto texture = io::decode_texture(f.bytes, f.size, f.path, problem);
        // The images are part of the build: one that does not decode is a build defect.
        if (!texture) throw std::logic_error("embedded brush " + name + ": " + problem);
        auto brush = std::make_unique<BrushImage>();
        brush->width = texture->width;
        brush->height = texture->height;
        brush->grey.resize(size_t(texture->width) * texture->height);
        for (size_t i = 0; i < brush->grey.size(); ++i) brush->grey[i] = texture->rgba[4 * i];
        return (decoded[name] = std::move(brush)).get();
    }
    return nullptr;
}

}  // namespace inkshade::render
