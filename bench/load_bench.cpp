// Loading and soup processing at 100 k, 1 M and 10 M triangles. Input files are generated once
// per size (a torus grid: closed, every vertex shared by six triangles, like a scan) into /tmp
// and removed at exit. 10 M runs once per benchmark so the whole suite stays within minutes.
//   inkshade_bench --benchmark_filter='Load|Read|Weld|Normals'
#include <benchmark/benchmark.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "geometry/normals.hpp"
#include "geometry/weld.hpp"
#include "inkshade/io.hpp"
#include "io/readers.hpp"

namespace {

using inkshade::Mesh;

// Torus with u x v quads, about `triangles` triangles (2uv), v ~ u/2.
Mesh torus_grid(int64_t triangles) {
    int v = std::max(3, int(std::sqrt(double(triangles) / 4.0)));
    int u = std::max(3, int(triangles / (2 * int64_t(v))));
    Mesh m;
    m.positions.reserve(size_t(u) * v);
    for (int i = 0; i < u; ++i)
        for (int j = 0; j < v; ++j) {
            float a = 6.2831853f * float(i) / float(u), b = 6.2831853f * float(j) / float(v);
            float r = 1.0f + 0.4f * std::cos(b);
            m.positions.emplace_back(r * std::cos(a), r * std::sin(a), 0.4f * std::sin(b));
        }
    m.triangles.reserve(2 * size_t(u) * v);
    for (int i = 0; i < u; ++i)
        for (int j = 0; j < v; ++j) {
            uint32_t a = uint32_t(i * v + j), b = uint32_t(((i + 1) % u) * v + j);
            uint32_t c = uint32_t(((i + 1) % u) * v + (j + 1) % v), d = uint32_t(i * v + (j + 1) % v);
            m.triangles.emplace_back(a, b, c);
            m.triangles.emplace_back(a, c, d);
        }
    return m;
}

Mesh to_soup(const Mesh& m) {
    Mesh s;
    s.positions.reserve(3 * m.triangles.size());
    for (const glm::uvec3& t : m.triangles) {
        uint32_t base = uint32_t(s.positions.size());
        for (int k = 0; k < 3; ++k) s.positions.push_back(m.positions[t[k]]);
        s.triangles.emplace_back(base, base + 1, base + 2);
    }
    return s;
}

template <class T>
void put(std::string& out, T v) {
    out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

std::string ply_bytes(const Mesh& m) {
    std::string s = "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(m.vertex_count()) +
                    "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
                    std::to_string(m.triangle_count()) + "\nproperty list uchar int vertex_indices\nend_header\n";
    s.reserve(s.size() + 12 * m.vertex_count() + 13 * m.triangle_count());
    for (const glm::vec3& p : m.positions) s.append(reinterpret_cast<const char*>(&p), 12);
    for (const glm::uvec3& t : m.triangles) {
        put<uint8_t>(s, 3);
        s.append(reinterpret_cast<const char*>(&t), 12);
    }
    return s;
}

std::string stl_bytes(const Mesh& m) {
    std::string s(80, ' ');
    put<uint32_t>(s, uint32_t(m.triangle_count()));
    s.reserve(84 + 50 * m.triangle_count());
    for (const glm::uvec3& t : m.triangles) {
        s.append(12, '\0');
        for (int k = 0; k < 3; ++k) s.append(reinterpret_cast<const char*>(&m.positions[t[k]]), 12);
        s.append(2, '\0');
    }
    return s;
}

std::string obj_bytes(const Mesh& m) {
    std::string s;
    char buf[32];
    auto num = [&](auto x) {
        auto r = std::to_chars(buf, buf + sizeof buf, x);
        s.append(buf, r.ptr);
    };
    for (const glm::vec3& p : m.positions) {
        s += "v ";
        num(p.x), s += ' ', num(p.y), s += ' ', num(p.z), s += '\n';
    }
    for (const glm::uvec3& t : m.triangles) {
        s += "f ";
        num(t.x + 1), s += ' ', num(t.y + 1), s += ' ', num(t.z + 1), s += '\n';
    }
    return s;
}

// One generated file per (format, size), deleted when the process ends.
class BenchFiles {
public:
    ~BenchFiles() {
        for (auto& [key, path] : paths_) std::filesystem::remove(path);
    }
    const std::string& get(const std::string& ext, int64_t triangles) {
        std::string& path = paths_[ext + std::to_string(triangles)];
        if (path.empty()) {
            path = "/tmp/inkshade-bench-" + std::to_string(triangles) + ext;
            Mesh m = torus_grid(triangles);
            std::string bytes = ext == ".ply" ? ply_bytes(m) : ext == ".stl" ? stl_bytes(m) : obj_bytes(m);
            std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
        }
        return path;
    }

private:
    std::map<std::string, std::string> paths_;
};

BenchFiles& files() {
    static BenchFiles f;
    return f;
}

template <class Load>
void run_load(benchmark::State& state, const char* ext, Load load) {
    const std::string& path = files().get(ext, state.range(0));
    size_t triangles = 0;
    for (auto _ : state) {
        Mesh m = load(path);
        triangles = m.triangle_count();
        benchmark::DoNotOptimize(m.positions.data());
    }
    state.counters["triangles"] = double(triangles);
    state.counters["MB/s"] = benchmark::Counter(double(std::filesystem::file_size(path)) / 1e6,
                                                benchmark::Counter::kIsIterationInvariantRate);
}

void BM_LoadPly(benchmark::State& s) {
    run_load(s, ".ply", [](auto& p) { return inkshade::load_mesh(p); });
}
void BM_LoadStl(benchmark::State& s) {
    run_load(s, ".stl", [](auto& p) { return inkshade::load_mesh(p); });
}
void BM_LoadObj(benchmark::State& s) {
    run_load(s, ".obj", [](auto& p) { return inkshade::load_mesh(p); });
}
// Parsing alone, without validation, welding and normals.
void BM_ReadPly(benchmark::State& s) {
    run_load(s, ".ply", [](auto& p) { return inkshade::io::read_ply(p); });
}
void BM_ReadStl(benchmark::State& s) {
    run_load(s, ".stl", [](auto& p) { return inkshade::io::read_stl(p); });
}

// The last generated mesh, reused across the iterations of one size.
const Mesh& cached(int64_t triangles, bool soup) {
    static int64_t key = -1;
    static Mesh mesh;
    if (key != triangles * 2 + soup) {
        mesh = Mesh();
        mesh = soup ? to_soup(torus_grid(triangles)) : torus_grid(triangles);
        key = triangles * 2 + soup;
    }
    return mesh;
}

void BM_WeldSoup(benchmark::State& state) {
    const Mesh& soup = cached(state.range(0), true);
    for (auto _ : state) {
        state.PauseTiming();
        Mesh m = soup;
        state.ResumeTiming();
        inkshade::geometry::weld(m);
        benchmark::DoNotOptimize(m.positions.data());
    }
    state.counters["triangles"] = double(soup.triangle_count());
}

void BM_AngleWeightedNormals(benchmark::State& state) {
    const Mesh& mesh = cached(state.range(0), false);
    for (auto _ : state) benchmark::DoNotOptimize(inkshade::geometry::angle_weighted_vertex_normals(mesh).data());
    state.counters["triangles"] = double(mesh.triangle_count());
}

}  // namespace

BENCHMARK(BM_ReadPly)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadPly)->Arg(10'000'000)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LoadPly)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LoadPly)->Arg(10'000'000)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadStl)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadStl)->Arg(10'000'000)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LoadStl)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LoadStl)->Arg(10'000'000)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LoadObj)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WeldSoup)->Arg(1'000'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WeldSoup)->Arg(10'000'000)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_AngleWeightedNormals)->Arg(1'000'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_AngleWeightedNormals)->Arg(10'000'000)->Iterations(1)->Unit(benchmark::kMillisecond);
