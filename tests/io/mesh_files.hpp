// Small meshes written in every supported format, and a check for one-line load errors.
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "inkshade/error.hpp"
#include "inkshade/io.hpp"

namespace inkshade::test {

// Unit cube, quads counter-clockwise seen from outside.
inline const std::vector<std::array<float, 3>> kCubeVertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                                                {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
inline const std::vector<std::array<uint32_t, 4>> kCubeQuads = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                                                {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}};

inline std::vector<std::array<uint32_t, 3>> cube_triangles() {
    std::vector<std::array<uint32_t, 3>> t;
    for (auto q : kCubeQuads) {
        t.push_back({q[0], q[1], q[2]});
        t.push_back({q[0], q[2], q[3]});
    }
    return t;
}

// Sorted positions, to compare meshes whose vertex order a weld may change.
inline std::vector<std::array<float, 3>> sorted_positions(const Mesh& m) {
    std::vector<std::array<float, 3>> p;
    for (auto v : m.positions) p.push_back({v.x, v.y, v.z});
    std::sort(p.begin(), p.end());
    return p;
}
inline std::vector<std::array<float, 3>> sorted_cube() {
    auto p = kCubeVertices;
    std::sort(p.begin(), p.end());
    return p;
}

template <class T>
void put(std::string& out, T value, bool big_endian = false) {
    char b[sizeof(T)];
    std::memcpy(b, &value, sizeof(T));
    if (big_endian) std::reverse(b, b + sizeof(T));
    out.append(b, sizeof(T));
}

inline std::string cube_ascii_stl() {
    std::ostringstream s;
    s << "solid cube\n";
    for (auto t : cube_triangles()) {
        s << "  facet normal 0 0 0\n    outer loop\n";
        for (uint32_t i : t)
            s << "      vertex " << kCubeVertices[i][0] << " " << kCubeVertices[i][1] << " " << kCubeVertices[i][2]
              << "\n";
        s << "    endloop\n  endfacet\n";
    }
    s << "endsolid cube\n";
    return s.str();
}

inline std::string binary_stl(const std::vector<std::array<std::array<float, 3>, 3>>& tris,
                              std::string header = "binary cube", int64_t claimed = -1) {
    header.resize(80, ' ');
    std::string s = header;
    put<uint32_t>(s, uint32_t(claimed < 0 ? int64_t(tris.size()) : claimed));
    for (auto& t : tris) {
        for (int k = 0; k < 3; ++k) put<float>(s, 0.0f);
        for (auto& v : t)
            for (float x : v) put<float>(s, x);
        put<uint16_t>(s, 0);
    }
    return s;
}
inline std::vector<std::array<std::array<float, 3>, 3>> cube_soup() {
    std::vector<std::array<std::array<float, 3>, 3>> soup;
    for (auto t : cube_triangles()) soup.push_back({kCubeVertices[t[0]], kCubeVertices[t[1]], kCubeVertices[t[2]]});
    return soup;
}
inline std::string cube_binary_stl(std::string header = "binary cube") { return binary_stl(cube_soup(), header); }

inline std::string cube_ascii_ply() {
    std::ostringstream s;
    s << "ply\nformat ascii 1.0\ncomment unit cube\nelement vertex 8\nproperty float x\nproperty float y\n"
         "property float z\nelement face 6\nproperty list uchar int vertex_indices\nend_header\n";
    for (auto v : kCubeVertices) s << v[0] << " " << v[1] << " " << v[2] << "\n";
    for (auto q : kCubeQuads) s << "4 " << q[0] << " " << q[1] << " " << q[2] << " " << q[3] << "\n";
    return s.str();
}

inline std::string cube_binary_ply(bool big_endian) {
    std::string s = std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
                    " 1.0\nelement vertex 8\nproperty float x\nproperty float y\nproperty float z\n"
                    "element face 6\nproperty list uchar int vertex_indices\nend_header\n";
    for (auto v : kCubeVertices)
        for (float x : v) put<float>(s, x, big_endian);
    for (auto q : kCubeQuads) {
        put<uint8_t>(s, 4);
        for (uint32_t i : q) put<int32_t>(s, int32_t(i), big_endian);
    }
    return s;
}

inline std::string cube_off() {
    std::ostringstream s;
    s << "OFF\n# unit cube\n8 6 12\n";
    for (auto v : kCubeVertices) s << v[0] << " " << v[1] << " " << v[2] << "\n";
    for (auto q : kCubeQuads) s << "4 " << q[0] << " " << q[1] << " " << q[2] << " " << q[3] << "\n";
    return s.str();
}

inline std::string cube_obj() {
    std::ostringstream s;
    s << "# unit cube\no cube\n";
    for (auto v : kCubeVertices) s << "v " << v[0] << " " << v[1] << " " << v[2] << "\n";
    for (auto q : kCubeQuads) s << "f " << q[0] + 1 << " " << q[1] + 1 << " " << q[2] + 1 << " " << q[3] + 1 << "\n";
    return s.str();
}

// load_mesh must throw InputError whose message names the file, contains `phrase` and is one line.
inline ::testing::AssertionResult LoadFailsWith(const std::string& path, const std::string& phrase,
                                                const LoadOptions& options = {}) {
    try {
        Mesh m = load_mesh(path, options);
        return ::testing::AssertionFailure()
               << "loaded " << m.triangle_count() << " triangles, expected an error with '" << phrase << "'";
    } catch (const InputError& e) {
        std::string what = e.what();
        if (what.find(path) == std::string::npos) return ::testing::AssertionFailure() << "path missing in: " << what;
        if (what.find(phrase) == std::string::npos)
            return ::testing::AssertionFailure() << "'" << phrase << "' missing in: " << what;
        if (what.find('\n') != std::string::npos || what.find('\r') != std::string::npos)
            return ::testing::AssertionFailure() << "not one line: " << what;
        return ::testing::AssertionSuccess() << what;
    } catch (const std::exception& e) {
        return ::testing::AssertionFailure() << "wrong exception type: " << e.what();
    }
}

}  // namespace inkshade::test
