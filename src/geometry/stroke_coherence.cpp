#include "geometry/stroke_coherence.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

#include "geometry/path_arc_length.hpp"
#include "geometry/path_attributes.hpp"

namespace inkshade::geometry {

namespace {

// A polyline resampled every `spacing` px along its arc length: positions, unit directions, the
// arc length and (when given) the interpolated u of each sample.
struct Resampled {
    std::vector<glm::vec2> p, dir;
    std::vector<double> s;
    std::vector<double> u;
};

Resampled resample(const std::vector<glm::vec2>& pts, const std::vector<float>* u, double spacing) {
    Resampled r;
    if (pts.size() < 2) return r;
    double along = 0.0, next = 0.0;
    for (size_t i = 0; i + 1 < pts.size(); ++i) {
        const glm::dvec2 a(pts[i]), b(pts[i + 1]);
        const double len = glm::length(b - a);
        if (!(len > 0.0)) continue;
        const glm::vec2 dir((b - a) / len);
        for (; next <= along + len; next += spacing) {
            const double t = (next - along) / len;
            r.p.emplace_back(a + (b - a) * t);
            r.dir.push_back(dir);
            r.s.push_back(next);
            if (u) r.u.push_back(double((*u)[i]) + (double((*u)[i + 1]) - double((*u)[i])) * t);
        }
        along += len;
    }
    return r;
}

// The previous frame's samples in a uniform grid over their bounding box, cells at least
// `radius` wide (so the 3 x 3 cells around a point hold every sample within `radius`), stored
// flat: each cell's samples contiguous (a counting sort), no allocation per cell.
class SampleGrid {
public:
    struct Sample {
        glm::vec2 p, dir;
        double u;
        uint32_t path, index;  // the previous path and the sample's place along it
    };

    void add(const Sample& s) { samples_.push_back(s); }

    // Sorts the samples into their cells; call once, after the last add.
    void build(float radius) {
        if (samples_.empty()) return;
        glm::vec2 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
        for (const Sample& s : samples_) {
            lo = glm::min(lo, s.p);
            hi = glm::max(hi, s.p);
        }
        origin_ = lo;
        // At most about 4096 cells a side, however far off the image a projected point fell.
        const float extent = std::max(hi.x - lo.x, hi.y - lo.y);
        cell_ = std::max({radius, extent / 4096.0f, 1e-3f});
        nx_ = int64_t((hi.x - lo.x) / cell_) + 1;
        ny_ = int64_t((hi.y - lo.y) / cell_) + 1;
        std::vector<uint32_t> count(size_t(nx_ * ny_) + 1, 0);
        for (const Sample& s : samples_) ++count[cell_index(s.p) + 1];
        for (size_t c = 1; c < count.size(); ++c) count[c] += count[c - 1];
        start_ = count;
        order_.resize(samples_.size());
        for (size_t i = 0; i < samples_.size(); ++i) order_[count[cell_index(samples_[i].p)]++] = uint32_t(i);
    }

    const Sample& operator[](size_t i) const { return samples_[i]; }
    size_t size() const { return samples_.size(); }

    // The nearest sample within `radius` whose direction is along `dir` (|cos| >= min_cos), or -1.
    int64_t nearest(glm::vec2 p, glm::vec2 dir, float radius, float min_cos) const {
        if (samples_.empty()) return -1;
        const auto cx = int64_t(std::floor((p.x - origin_.x) / cell_)),
                   cy = int64_t(std::floor((p.y - origin_.y) / cell_));
        int64_t best = -1;
        float best_d2 = radius * radius;
        for (int64_t y = std::max<int64_t>(cy - 1, 0); y <= std::min(cy + 1, ny_ - 1); ++y)
            for (int64_t x = std::max<int64_t>(cx - 1, 0); x <= std::min(cx + 1, nx_ - 1); ++x) {
                const size_t c = size_t(y * nx_ + x);
                for (uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
                    const uint32_t i = order_[k];
                    const Sample& s = samples_[i];
                    const glm::vec2 d = s.p - p;
                    const float d2 = glm::dot(d, d);
                    if (d2 <= best_d2 && std::abs(glm::dot(s.dir, dir)) >= min_cos) {
                        best_d2 = d2;
                        best = int64_t(i);
                    }
                }
            }
        return best;
    }

private:
    size_t cell_index(glm::vec2 p) const {
        const int64_t x = std::clamp(int64_t((p.x - origin_.x) / cell_), int64_t(0), nx_ - 1);
        const int64_t y = std::clamp(int64_t((p.y - origin_.y) / cell_), int64_t(0), ny_ - 1);
        return size_t(y * nx_ + x);
    }

    std::vector<Sample> samples_;
    glm::vec2 origin_{0.0f};
    float cell_ = 1.0f;
    int64_t nx_ = 0, ny_ = 0;
    std::vector<uint32_t> start_, order_;  // cell c's samples: order_[start_[c] .. start_[c + 1])
};

// The u at p on the previous path near sample i: p projected onto the sample's segment to the
// previous or the next sample of its path, whichever is nearer (so a vote is exact on a straight
// piece, not rounded to the sample spacing).
double u_near(const SampleGrid& grid, size_t i, glm::vec2 p) {
    const SampleGrid::Sample& s = grid[i];
    double best_d2 = 1e300, best_u = s.u;
    for (const int step : {-1, 1}) {
        const size_t j = i + size_t(step);
        if (j >= grid.size() || grid[j].path != s.path || grid[j].index != s.index + uint32_t(step)) continue;
        const glm::dvec2 a(s.p), b(grid[j].p);
        const glm::dvec2 ab = b - a;
        const double l2 = glm::dot(ab, ab);
        if (!(l2 > 0.0)) continue;
        const double t = std::clamp(glm::dot(glm::dvec2(p) - a, ab) / l2, 0.0, 1.0);
        const glm::dvec2 q = a + ab * t;
        const double d2 = glm::dot(glm::dvec2(p) - q, glm::dvec2(p) - q);
        if (d2 < best_d2) {
            best_d2 = d2;
            best_u = s.u + (grid[j].u - s.u) * t;
        }
    }
    return best_u;
}

// The largest group of votes within ±window of one another: its size and mean. A group, so the
// votes across a previous loop's seam (a loop's length apart) do not count; its mean, not its
// median, because the surface carries a contour's points along it unevenly: on a sphere seen
// from an orbit, the top of the outline one way and the bottom the other, and the mean of the
// two is the outline that did not move.
std::pair<size_t, double> consensus(std::vector<double>& votes, double window) {
    std::sort(votes.begin(), votes.end());
    size_t best_begin = 0, best_end = 0;
    for (size_t a = 0, b = 0; a < votes.size(); ++a) {
        while (b < votes.size() && votes[b] - votes[a] <= 2.0 * window) ++b;
        if (b - a > best_end - best_begin) best_begin = a, best_end = b;
    }
    if (best_end == best_begin) return {0, 0.0};
    double sum = 0.0;
    for (size_t i = best_begin; i < best_end; ++i) sum += votes[i] - votes[best_begin];
    return {best_end - best_begin, votes[best_begin] + sum / double(best_end - best_begin)};
}

}  // namespace

LinePath reversed(const LinePath& path) {
    LinePath out = path;
    for_each_point_attribute([&](auto& v) { reverse_attribute(v, path.closed); }, out);
    out.u.clear();  // it would decrease along the path: the caller sets it anew
    return out;
}

LinePath rotated_at(const LinePath& path, double at) {
    if (!path.closed || path.points.size() < 2) return path;
    const LinePath open = opened(path);
    const std::vector<double> s = arc_lengths(open);
    const double total = s.back();
    if (!(at > 1e-9 && at < total - 1e-9)) return path;
    // From `at` round to the start, then on to `at`; each piece's last point is the other's first.
    const LinePath a = sub_path(open, s, at, total), b = sub_path(open, s, 0.0, at);
    LinePath out;
    out.closed = true;
    out.level = path.level;
    auto join = [](auto& to, const auto& x, const auto& y) {
        if (x.empty()) return;
        to.assign(x.begin(), x.end() - 1);
        to.insert(to.end(), y.begin(), y.end() - 1);
    };
    for_each_point_attribute(join, out, a, b);
    // u stays increasing, as rotated() keeps it: b's points come after the loop's end.
    if (!out.u.empty()) {
        const float lap = open.u.back() - open.u.front();
        for (size_t i = a.u.size() - 1; i < out.u.size(); ++i) out.u[i] += lap;
    }
    return out;
}

void parameterise_paths(std::vector<LinePath>& paths, const std::vector<LinePath>& previous,
                        const ProjectPoint& project, const CoherenceOptions& o) {
    const double spacing = std::max(double(o.spacing_px), 0.05);
    SampleGrid grid;
    for (size_t k = 0; k < previous.size(); ++k) {
        const LinePath open = opened(previous[k]);
        if (open.points.size() < 2 || open.u.size() != open.points.size()) continue;
        // Carried by the surface: where the previous frame's points are in this frame.
        std::vector<glm::vec2> at = open.points;
        if (project && open.world.size() == open.points.size())
            for (size_t i = 0; i < at.size(); ++i) at[i] = project(open.world[i]);
        const Resampled r = resample(at, &open.u, spacing);
        for (size_t j = 0; j < r.p.size(); ++j) grid.add({r.p[j], r.dir[j], r.u[j], uint32_t(k), uint32_t(j)});
    }
    grid.build(o.radius_px);

    for (LinePath& path : paths) {
        path.u.clear();
        if (path.points.empty() || !attributes_consistent(path)) continue;
        const LinePath open = opened(path);
        const Resampled r = resample(open.points, nullptr, spacing);
        // Votes per previous path and direction: the offset u − s (along) or u + s (against).
        std::unordered_map<uint64_t, std::vector<double>> votes;
        for (size_t j = 0; j < r.p.size(); ++j) {
            const int64_t i = grid.nearest(r.p[j], r.dir[j], o.radius_px, o.min_direction_cos);
            if (i < 0 || previous[grid[size_t(i)].path].level != path.level) continue;
            const bool along = glm::dot(grid[size_t(i)].dir, r.dir[j]) >= 0.0f;
            const double u = u_near(grid, size_t(i), r.p[j]);
            votes[uint64_t(grid[size_t(i)].path) * 2 + (along ? 0 : 1)].push_back(along ? u - r.s[j] : u + r.s[j]);
        }
        size_t best_count = 0;
        uint64_t best_key = 0;
        double offset = 0.0;
        for (auto& [key, v] : votes) {
            const auto [count, median] = consensus(v, o.window_px);
            if (count > best_count || (count == best_count && key < best_key)) {
                best_count = count;
                best_key = key;
                offset = median;
            }
        }
        std::vector<double> s = arc_lengths(path);
        const double total = s.back();
        const size_t needed = std::max<size_t>(3, size_t(std::ceil(double(o.min_fraction) * double(r.p.size()))));
        if (best_count < needed) {
            offset = 0.0;  // a new stroke: u from its start
        } else {
            const LinePath& source = previous[best_key / 2];
            if (best_key % 2 == 1) {
                // Against the previous stroke: turned round, u = offset − s becomes (offset − L) + s'.
                path = reversed(path);
                offset -= total;
                s = arc_lengths(path);
            }
            if (path.closed && source.closed) {
                // Start where the previous loop started (u = its u at its start), so the seam,
                // where the pattern restarts, stays on the surface too.
                const double u0 = double(source.u.front());
                const double start = u0 - offset - total * std::floor((u0 - offset) / total);
                path = rotated_at(path, start);
                offset = u0;
                s = arc_lengths(path);
            }
        }
        path.u.resize(path.points.size());
        for (size_t i = 0; i < path.points.size(); ++i) path.u[i] = float(offset + s[i]);
    }
}

}  // namespace inkshade::geometry
