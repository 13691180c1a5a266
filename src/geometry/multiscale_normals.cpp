// Smoothed normals: the sources (one per occupied cell of side σ/2), sorted into a hash grid of
// cells of side 3σ, then each vertex sums the sources in the 27 grid cells around it (in
// parallel, the vertices of one grid cell together).
#include "geometry/multiscale_normals.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace inkshade::geometry {
namespace {

constexpr size_t kGrain = 4096;  // vertices per TBB task

struct Cell {
    int64_t x = 0, y = 0, z = 0;
    bool operator==(const Cell&) const = default;
};

struct CellHash {
    size_t operator()(const Cell& c) const {
        uint64_t h = uint64_t(c.x) * 0x9e3779b97f4a7c15ull;
        h ^= uint64_t(c.y) * 0xc2b2ae3d27d4eb4full + (h << 6) + (h >> 2);
        h ^= uint64_t(c.z) * 0x165667b19e3779f9ull + (h << 6) + (h >> 2);
        return size_t(h);
    }
};

// The cell of side `size` holding p; false when p is too far out for 64-bit cell numbers.
bool cell_of(const glm::dvec3& p, double size, Cell& cell) {
    const glm::dvec3 c = glm::floor(p / size);
    if (!(std::abs(c.x) < 1e15 && std::abs(c.y) < 1e15 && std::abs(c.z) < 1e15)) return false;
    cell = {int64_t(c.x), int64_t(c.y), int64_t(c.z)};
    return true;
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

struct Source {
    glm::dvec3 weighted_position{0.0};  // Σ A p, then the centroid
    glm::dvec3 normal{0.0};             // Σ A n
    double area = 0.0;
};

// Items 0 .. n − 1 grouped by their cell (`cell_of_item(i, cell)` false: left out), by a
// counting sort: items in index order within a cell, cells in the order they first appear.
struct CellBuckets {
    template <class CellOfItem>
    CellBuckets(size_t n, const CellOfItem& cell_of_item) {
        std::vector<uint32_t> bucket(n, kNone), count;
        for (size_t i = 0; i < n; ++i) {
            Cell cell;
            if (!cell_of_item(i, cell)) continue;
            auto [it, inserted] = index.try_emplace(cell, uint32_t(cells.size()));
            if (inserted) {
                cells.push_back(cell);
                count.push_back(0);
            }
            bucket[i] = it->second;
            ++count[it->second];
        }
        first.assign(cells.size() + 1, 0);
        for (size_t b = 0; b < cells.size(); ++b) first[b + 1] = first[b] + count[b];
        items.resize(first.back());
        std::vector<uint32_t> next(first.begin(), first.end() - 1);
        for (size_t i = 0; i < n; ++i)
            if (bucket[i] != kNone) items[next[bucket[i]]++] = uint32_t(i);
    }
    static constexpr uint32_t kNone = ~0u;
    std::vector<Cell> cells;
    std::vector<uint32_t> first;  // bucket b's items: items[first[b] .. first[b + 1])
    std::vector<uint32_t> items;
    std::unordered_map<Cell, uint32_t, CellHash> index;  // cell → bucket
};

// The sources sorted by their cell of side `reach` (in source order within a cell, so each
// vertex sums them in the order it did when each cell held a list).
struct Grid {
    Grid(const std::vector<Source>& sources, double reach)
        : buckets(sources.size(),
                  [&](size_t k, Cell& cell) { return cell_of(sources[k].weighted_position, reach, cell); }) {
        for (const uint32_t k : buckets.items) {
            position.push_back(sources[k].weighted_position);
            normal.push_back(sources[k].normal);
        }
    }
    // The ranges of the 27 cells around `home` that hold sources, in z, y, x order.
    void around(const Cell& home, std::vector<std::pair<uint32_t, uint32_t>>& out) const {
        out.clear();
        for (int64_t dz = -1; dz <= 1; ++dz)
            for (int64_t dy = -1; dy <= 1; ++dy)
                for (int64_t dx = -1; dx <= 1; ++dx)
                    if (const auto it = buckets.index.find({home.x + dx, home.y + dy, home.z + dz});
                        it != buckets.index.end())
                        out.emplace_back(buckets.first[it->second], buckets.first[it->second + 1]);
    }
    CellBuckets buckets;
    std::vector<glm::dvec3> position, normal;  // in buckets.items order
};

}  // namespace

std::vector<glm::vec3> smoothed_normals(const Mesh& mesh, const std::vector<glm::vec3>& normals, float sigma) {
    const size_t n = mesh.positions.size();
    if (!(sigma > 0.0f) || !std::isfinite(sigma) || normals.size() != n) return normals;
    std::vector<double> area(n, 0.0);
    for (const glm::uvec3& t : mesh.triangles) {
        if (t.x >= n || t.y >= n || t.z >= n) continue;
        const glm::dvec3 a(mesh.positions[t.x]), b(mesh.positions[t.y]), c(mesh.positions[t.z]);
        const double third = glm::length(glm::cross(b - a, c - a)) / 6.0;
        if (!std::isfinite(third)) continue;
        for (int k = 0; k < 3; ++k) area[t[k]] += third;
    }

    const double s = sigma, reach = 3.0 * s;
    std::vector<Source> sources;
    std::unordered_map<Cell, uint32_t, CellHash> source_of;
    for (size_t i = 0; i < n; ++i) {
        Cell cell;
        if (!(area[i] > 0.0) || !finite(mesh.positions[i]) || !finite(normals[i]) ||
            !cell_of(glm::dvec3(mesh.positions[i]), 0.5 * s, cell))
            continue;
        auto [it, inserted] = source_of.try_emplace(cell, uint32_t(sources.size()));
        if (inserted) sources.emplace_back();
        Source& src = sources[it->second];
        src.weighted_position += area[i] * glm::dvec3(mesh.positions[i]);
        src.normal += area[i] * glm::dvec3(normals[i]);
        src.area += area[i];
    }
    for (Source& src : sources) src.weighted_position /= src.area;
    const Grid grid(sources, reach);
    // The vertices grouped by their cell of side `reach`: the vertices of a group read the same
    // 27 cells, looked up once for all of them (at the coarse scales a cell holds hundreds).
    const CellBuckets groups(n, [&](size_t i, Cell& cell) {
        return finite(mesh.positions[i]) && cell_of(glm::dvec3(mesh.positions[i]), reach, cell);
    });

    std::vector<glm::vec3> out(normals);
    const double inv_two_s2 = 1.0 / (2.0 * s * s);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, groups.cells.size(), kGrain / 16), [&](const auto& range) {
        std::vector<std::pair<uint32_t, uint32_t>> near;  // the source ranges of the 27 cells
        for (size_t g = range.begin(); g != range.end(); ++g) {
            grid.around(groups.cells[g], near);
            for (uint32_t k = groups.first[g]; k != groups.first[g + 1]; ++k) {
                const uint32_t i = groups.items[k];
                const glm::dvec3 p(mesh.positions[i]);
                glm::dvec3 sum(0.0);
                for (const auto& [begin, end] : near)
                    for (uint32_t q = begin; q != end; ++q) {
                        const glm::dvec3 d = grid.position[q] - p;
                        const double d2 = glm::dot(d, d);
                        // The weight in float: std::exp in double took most of the time, and
                        // float's rounding (6e-8) is far below what the unit normal keeps.
                        if (d2 < reach * reach) sum += double(std::exp(float(-d2 * inv_two_s2))) * grid.normal[q];
                    }
                const double len = glm::length(sum);
                if (len > 0.0 && std::isfinite(len)) out[i] = glm::vec3(sum / len);
            }
        }
    });
    return out;
}

std::vector<std::vector<glm::vec3>> multiscale_normals(const Mesh& mesh, const std::vector<glm::vec3>& normals,
                                                       const std::vector<float>& sigmas) {
    std::vector<std::vector<glm::vec3>> out;
    out.reserve(sigmas.size());
    for (const float sigma : sigmas) out.push_back(smoothed_normals(mesh, normals, sigma));
    return out;
}

}  // namespace inkshade::geometry
