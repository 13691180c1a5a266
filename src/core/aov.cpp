// AOV names and file names (inkshade/aov.hpp); the buffers are drawn by render/aov_pass.cpp and
// the line masks by scene/aov.cpp, the files written by io/aov_files.cpp.
#include "inkshade/aov.hpp"

#include <filesystem>
#include <stdexcept>
#include <utility>

#include "core/name_suggestion.hpp"

namespace inkshade {

const std::vector<std::string>& aov_names() {
    static const std::vector<std::string> names = {
        "depth", "normal", "id", "material", "mask",  "lines", "lineset-ids",    "ndotv",
        "kr",    "dwkr",   "k1", "k2",       "pdir1", "pdir2", "shading-scales", "camera"};
    return names;
}

const char* aov_name(Aov aov) { return aov_names()[size_t(aov)].c_str(); }

std::optional<Aov> aov_named(std::string_view name) {
    const std::vector<std::string>& names = aov_names();
    for (size_t i = 0; i < names.size(); ++i)
        if (equal_ignoring_case(name, names[i])) return Aov(i);
    return std::nullopt;
}

std::string format_aov_set(AovSet set) {
    std::string out;
    for (size_t i = 0; i < aov_names().size(); ++i)
        if (set.contains(Aov(i))) out += (out.empty() ? "" : ",") + aov_names()[i];
    return out;
}

std::vector<float>& field_buffer(AovImages& images, Aov aov) {
    return const_cast<std::vector<float>&>(field_buffer(std::as_const(images), aov));
}

const std::vector<float>& field_buffer(const AovImages& images, Aov aov) {
    switch (aov) {
        case Aov::Ndotv: return images.ndotv;
        case Aov::Kr: return images.kr;
        case Aov::Dwkr: return images.dwkr;
        case Aov::K1: return images.k1;
        case Aov::K2: return images.k2;
        case Aov::Pdir1: return images.pdir1;
        case Aov::Pdir2: return images.pdir2;
        default: throw std::invalid_argument(std::string("not a field AOV: ") + aov_name(aov));
    }
}

int field_channels(Aov aov) { return aov == Aov::Pdir1 || aov == Aov::Pdir2 ? 2 : 1; }

std::string line_mask_name(const std::string& lineset, const std::string& type) {
    return lineset.empty() ? "lines-" + type : "lines-" + lineset + "-" + type;
}

std::string aov_path(const std::string& image_path, const std::string& aov, const std::string& extension) {
    std::filesystem::path p(image_path);
    p.replace_extension();
    return p.string() + "." + aov + extension;
}

}  // namespace inkshade
