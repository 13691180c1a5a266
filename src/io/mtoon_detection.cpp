#include "io/mtoon_detection.hpp"

#include <array>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>

#include <nlohmann/json.hpp>

namespace inkshade::io {

namespace {

constexpr uint32_t kGlbMagic = 0x46546C67;      // "glTF"
constexpr uint32_t kJsonChunk = 0x4E4F534A;     // "JSON"
constexpr uint64_t kMaxJsonBytes = 256u << 20;  // as the container's guard: larger is not read

uint32_t le32(const unsigned char* p) { return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24; }

// The glTF JSON of the file: a GLB's first chunk, or the whole text file. Empty when neither.
std::string gltf_json(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return {};
    std::array<unsigned char, 20> head{};
    in.read(reinterpret_cast<char*>(head.data()), head.size());
    const std::streamsize got = in.gcount();
    if (got == std::streamsize(head.size()) && le32(head.data()) == kGlbMagic) {
        const uint32_t length = le32(head.data() + 12);
        if (le32(head.data() + 16) != kJsonChunk || length > kMaxJsonBytes) return {};
        std::string json(length, '\0');
        in.read(json.data(), length);
        return in.gcount() == std::streamsize(length) ? json : std::string();
    }
    size_t start = 0;
    while (start < size_t(got) && std::isspace(head[start])) ++start;
    if (start == size_t(got) || head[start] != '{') return {};
    in.clear();
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (size <= 0 || uint64_t(size) > kMaxJsonBytes) return {};
    std::string json(size_t(size), '\0');
    in.seekg(0);
    in.read(json.data(), size);
    return json;
}

}  // namespace

bool uses_mtoon_materials(const std::string& path) {
    const std::string ext = path.size() >= 4 ? path.substr(path.size() - 4) : "";
    std::string lower;
    for (char c : ext) lower += char(std::tolower(static_cast<unsigned char>(c)));
    if (lower != ".vrm" && lower != ".glb" && lower != "gltf") return false;
    const nlohmann::json doc = nlohmann::json::parse(gltf_json(path), nullptr, /*allow_exceptions=*/false);
    if (!doc.is_object()) return false;
    const auto names_mtoon = [](const std::string& name) {
        return name == "VRMC_vrm" || name == "VRM" || name == "VRMC_materials_mtoon";
    };
    if (const auto used = doc.find("extensionsUsed"); used != doc.end() && used->is_array())
        for (const nlohmann::json& name : *used)
            if (name.is_string() && names_mtoon(name.get<std::string>())) return true;
    if (const auto extensions = doc.find("extensions"); extensions != doc.end() && extensions->is_object())
        for (const auto& item : extensions->items())
            if (names_mtoon(item.key())) return true;
    return false;
}

}  // namespace inkshade::io
