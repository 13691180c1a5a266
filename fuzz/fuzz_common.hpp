// Shared by the fuzz targets: the readers take paths, so each input is written to a file in a
// per-process scratch directory in /dev/shm (RAM; $INKSHADE_FUZZ_DIR overrides), and checks of
// the contract every reader promises (one-line InputError naming the file; a loaded mesh is
// indexed, in range, finite and has normals). A broken promise throws ContractBroken, which
// nothing catches: libFuzzer reports the abort as a crash, and the regression tests that replay
// saved inputs through the same functions (tests/io/fuzz_regressions_test.cpp) as a failure.
#pragma once
#include <fcntl.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "inkshade/error.hpp"
#include "inkshade/io.hpp"
#include "inkshade/mesh.hpp"

namespace inkshade::fuzz {

struct ContractBroken : std::logic_error {
    using std::logic_error::logic_error;
};

[[noreturn]] inline void broken(const std::string& what) { throw ContractBroken("fuzz contract broken: " + what); }

// The scratch directory, created on first use and removed at exit.
inline const std::string& scratch_dir() {
    struct Dir {
        std::string path;
        Dir() {
            const char* base = std::getenv("INKSHADE_FUZZ_DIR");
            std::string root = base ? base : (std::filesystem::is_directory("/dev/shm") ? "/dev/shm" : "/tmp");
            path = root + "/inkshade-fuzz-" + std::to_string(::getpid());
            std::filesystem::create_directories(path);
        }
        ~Dir() {
            std::error_code ec;
            std::filesystem::remove_all(path, ec);
        }
    };
    static Dir dir;
    return dir.path;
}

// Writes `bytes` to scratch_dir()/name (replacing it) and returns the path.
inline std::string write_file(const std::string& name, std::string_view bytes) {
    const std::string path = scratch_dir() + "/" + name;
    int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
    if (fd < 0) broken("cannot write " + path);
    for (size_t done = 0; done < bytes.size();) {
        ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n <= 0) broken("cannot write " + path);
        done += size_t(n);
    }
    ::close(fd);
    return path;
}

// Removes scratch_dir()/name if present (a part the input did not provide).
inline void remove_file(const std::string& name) { ::unlink((scratch_dir() + "/" + name).c_str()); }

// The input cut at each `marker` into at most `max_parts` parts (the last keeps any further
// markers). Lets one input carry a model and the files next to it (MTL, textures, buffers).
inline std::vector<std::string_view> split(std::string_view data, std::string_view marker, size_t max_parts) {
    std::vector<std::string_view> parts;
    while (parts.size() + 1 < max_parts) {
        size_t at = data.find(marker);
        if (at == std::string_view::npos) break;
        parts.push_back(data.substr(0, at));
        data.remove_prefix(at + marker.size());
    }
    parts.push_back(data);
    return parts;
}

// What load_mesh promises of a mesh it returns.
inline void check_mesh(const Mesh& mesh) {
    const size_t n = mesh.positions.size();
    if (mesh.triangles.empty()) broken("loaded a mesh without triangles");
    if (mesh.normals.size() != n) broken("normals do not match the vertices");
    if (!mesh.colors.empty() && mesh.colors.size() != n) broken("colours do not match the vertices");
    if (!mesh.uvs.empty() && mesh.uvs.size() != n) broken("uvs do not match the vertices");
    if (!mesh.face_materials.empty() && mesh.face_materials.size() != mesh.triangles.size())
        broken("face materials do not match the triangles");
    for (const glm::uvec3& t : mesh.triangles)
        for (int k = 0; k < 3; ++k)
            if (t[k] >= n) broken("triangle index out of range");
    for (uint32_t m : mesh.face_materials)
        if (m >= mesh.materials.size()) broken("face material out of range");
    for (const glm::vec3& p : mesh.positions)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) broken("non-finite position");
    for (const glm::vec3& v : mesh.normals)
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) broken("non-finite normal");
    for (const Material& m : mesh.materials)
        if (m.texture && m.texture->rgba.size() != size_t(m.texture->width) * size_t(m.texture->height) * 4)
            broken("texture size does not match its pixels");
}

// What every InputError promises: one line, starting with the file it is about.
inline void check_error(const InputError& e, const std::string& path) {
    const std::string what = e.what();
    if (what.find('\n') != std::string::npos || what.find('\r') != std::string::npos)
        broken("multi-line error: " + what);
    if (what.rfind(path + ": ", 0) != 0) broken("error does not start with the file name: " + what);
}

// load_mesh on `path`: true and the mesh (checked), or false after a well-formed InputError.
// Anything else thrown escapes.
inline bool load_checked(const std::string& path, Mesh& mesh) {
    try {
        mesh = load_mesh(path);
    } catch (const InputError& e) {
        check_error(e, path);
        return false;
    }
    check_mesh(mesh);
    return true;
}

}  // namespace inkshade::fuzz
