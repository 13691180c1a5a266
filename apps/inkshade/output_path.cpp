#include "output_path.hpp"

#include <unistd.h>

#include <filesystem>

#include "inkshade/error.hpp"

namespace inkshade::cli {

void check_output_path(const std::string& option, const std::string& path) {
    namespace fs = std::filesystem;
    fs::path p(path);
    std::error_code ec;
    if (path.empty()) throw InputError(option + ": empty path");
    if (fs::is_directory(p, ec)) throw InputError(path + ": output is a directory");
    fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
    if (!fs::is_directory(dir, ec)) throw InputError(path + ": directory " + dir.string() + " does not exist");
    if (::access(dir.c_str(), W_OK) != 0) throw InputError(path + ": directory " + dir.string() + " is not writable");
}

}  // namespace inkshade::cli
