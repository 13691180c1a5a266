#include "gpu/shader_source.hpp"

#include <algorithm>
#include <set>
#include <sstream>
#include <vector>

#include "gpu/embedded_shaders.hpp"
#include "inkshade/error.hpp"

namespace inkshade::gpu {

namespace {

constexpr std::string_view kInclude = "#include \"";

struct Expansion {
    const ShaderLookup& lookup;
    std::vector<std::string> open;  // the include chain being expanded
    std::set<std::string> done;     // files expanded already
    std::string out;

    void expand(const std::string& path, const std::string& included_from) {
        const char* contents = lookup(path);
        if (!contents) throw RuntimeError(included_from + "shader " + path + " is not embedded in this build");
        open.push_back(path);
        std::istringstream in(contents);
        std::string line;
        for (int number = 1; std::getline(in, line); ++number) {
            if (line.rfind(kInclude, 0) != 0) {
                out += line;
                out += '\n';
                continue;
            }
            const std::string where = "shader " + path + " line " + std::to_string(number) + ": ";
            const size_t end = line.find('"', kInclude.size());
            if (end == std::string::npos || end == kInclude.size())
                throw RuntimeError(where + "malformed #include (want #include \"file\")");
            const std::string target = line.substr(kInclude.size(), end - kInclude.size());
            if (std::find(open.begin(), open.end(), target) != open.end())
                throw RuntimeError(where + "#include \"" + target + "\" includes itself");
            if (done.insert(target).second) expand(target, where);
        }
        open.pop_back();
    }
};

}  // namespace

std::string expand_includes(const std::string& path, const ShaderLookup& lookup) {
    Expansion e{lookup, {}, {path}, {}};
    e.expand(path, "");
    return std::move(e.out);
}

std::string shader_source(const std::string& path) {
    return expand_includes(path, [](const std::string& p) -> const char* {
        for (const auto& s : embedded_shaders())
            if (p == s.path) return s.contents;
        return nullptr;
    });
}

}  // namespace inkshade::gpu
