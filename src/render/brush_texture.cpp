#include "render/brush_texture.hpp"

#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>

#include <stb_image.h>

#include "core/embedded_file.hpp"

namespace inkshade::render {

const std::vector<EmbeddedBinary>& embedded_brushes();  // generated (cmake/embed_binary_files.cmake)

const BrushImage* shipped_brush(const std::string& name) {
    static std::mutex mutex;
    static std::map<std::string, std::unique_ptr<BrushImage>> decoded;
    const std::lock_guard lock(mutex);
    if (auto it = decoded.find(name); it != decoded.end()) return it->second.get();
    for (const EmbeddedBinary& f : embedded_brushes()) {
        if (f.path != name + ".png") continue;
        int w = 0, h = 0, channels = 0;
        unsigned char* grey = stbi_load_from_memory(f.bytes, int(f.size), &w, &h, &channels, 1);
        // The images are part of the build: one that does not decode is a build defect.
        if (!grey) throw std::logic_error("embedded brush " + name + ": " + stbi_failure_reason());
        auto brush = std::make_unique<BrushImage>();
        brush->width = w;
        brush->height = h;
        brush->grey.assign(grey, grey + size_t(w) * h);
        stbi_image_free(grey);
        return (decoded[name] = std::move(brush)).get();
    }
    return nullptr;
}

}  // namespace inkshade::render
