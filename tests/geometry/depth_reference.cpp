#include "geometry/depth_reference.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <ostream>

namespace inkshade::test {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr size_t kExamples = 5;

struct ScreenVertex {
    glm::dvec2 p{0.0};  // high-resolution pixels
    double z = 0.0;     // view depth
    bool clipped = false;
};

// Twice the signed area of (a, b, p), evaluated with the edge's end points in one fixed order
// so that the two triangles sharing the edge get exactly opposite values.
double edge_function(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& p) {
    const bool swap = b.x < a.x || (b.x == a.x && b.y < a.y);
    const glm::dvec2& u = swap ? b : a;
    const glm::dvec2& v = swap ? a : b;
    const double e = (v.x - u.x) * (p.y - u.y) - (v.y - u.y) * (p.x - u.x);
    return swap ? -e : e;
}

}  // namespace

DepthReference::DepthReference(const Mesh& mesh, const Camera& camera, int width, int height, int scale)
    : view_(camera, width, height),
      width_(width),
      height_(height),
      scale_(scale),
      hi_width_(width * scale),
      hi_height_(height * scale),
      depth_(size_t(width) * scale * size_t(height) * scale, std::numeric_limits<float>::infinity()),
      eps_(1e-4 * double(mesh.bounds().diagonal())) {
    std::vector<ScreenVertex> vertices(mesh.positions.size());
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        ScreenVertex& v = vertices[i];
        v.clipped = view_.clipped(mesh.positions[i]);
        if (v.clipped) continue;
        const glm::dvec3 q = view_.project(mesh.positions[i]);
        v.p = glm::dvec2(q.x, q.y) * double(scale);
        v.z = view_.view_depth(mesh.positions[i]);
    }
    const bool orthographic = camera.orthographic;
    const size_t n = vertices.size();
    for (const glm::uvec3& t : mesh.triangles) {
        if (t.x >= n || t.y >= n || t.z >= n) continue;
        const ScreenVertex &a = vertices[t.x], &b = vertices[t.y], &c = vertices[t.z];
        if (a.clipped || b.clipped || c.clipped) {
            ++clipped_;
            continue;
        }
        const double area = edge_function(a.p, b.p, c.p);
        if (!(std::abs(area) > 0.0) || !std::isfinite(area)) continue;  // zero area: covers no centre
        const double sign = area > 0.0 ? 1.0 : -1.0;
        const double min_x = std::min({a.p.x, b.p.x, c.p.x}), max_x = std::max({a.p.x, b.p.x, c.p.x});
        const double min_y = std::min({a.p.y, b.p.y, c.p.y}), max_y = std::max({a.p.y, b.p.y, c.p.y});
        const int j0 = std::max(0, int(std::ceil(min_y - 0.5)));
        const int j1 = std::min(hi_height_ - 1, int(std::floor(max_y - 0.5)));
        const glm::dvec2* corners[3] = {&a.p, &b.p, &c.p};
        for (int j = j0; j <= j1; ++j) {
            const double y = j + 0.5;
            // The row's span from the three half-planes (a pixel of margin on each side; the
            // exact test below decides).
            double lo = min_x, hi = max_x;
            for (int k = 0; k < 3; ++k) {
                const glm::dvec2& u = *corners[k];
                const glm::dvec2& v = *corners[(k + 1) % 3];
                const double dy = v.y - u.y;
                if (dy == 0.0) continue;
                // sign · ((v.x − u.x)(y − u.y) − dy (x − u.x)) ≥ 0
                const double x0 = u.x + (v.x - u.x) * (y - u.y) / dy;
                if (sign * dy > 0.0)
                    hi = std::min(hi, x0);
                else
                    lo = std::max(lo, x0);
            }
            const int i0 = std::max(0, int(std::ceil(lo - 0.5)) - 1);
            const int i1 = std::min(hi_width_ - 1, int(std::floor(hi - 0.5)) + 1);
            for (int i = i0; i <= i1; ++i) {
                const glm::dvec2 p(i + 0.5, y);
                const double ea = edge_function(b.p, c.p, p), eb = edge_function(c.p, a.p, p),
                             ec = edge_function(a.p, b.p, p);
                if (sign * ea < 0.0 || sign * eb < 0.0 || sign * ec < 0.0) continue;
                const double sum = ea + eb + ec;
                if (sum == 0.0) continue;
                const double la = ea / sum, lb = eb / sum, lc = ec / sum;
                const double z = orthographic ? la * a.z + lb * b.z + lc * c.z : 1.0 / (la / a.z + lb / b.z + lc / c.z);
                float& d = depth_[size_t(j) * size_t(hi_width_) + size_t(i)];
                d = std::min(d, float(z));
            }
        }
    }
}

double DepthReference::depth(int i, int j) const {
    if (i < 0 || j < 0 || i >= hi_width_ || j >= hi_height_) return kInfinity;
    return double(depth_[size_t(j) * size_t(hi_width_) + size_t(i)]);
}

double DepthReference::view_depth_of_window(double window_depth) const {
    const Camera& camera = view_.camera();
    const double n = camera.near_plane, f = camera.far_plane;
    if (camera.orthographic) return n + window_depth * (f - n);
    const double z_ndc = 2.0 * window_depth - 1.0;
    return 2.0 * n * f / ((f + n) - z_ndc * (f - n));
}

double VisibilityErrors::wrongly_visible_fraction() const {
    return visible_length > 0.0 ? wrongly_visible_length / visible_length : 0.0;
}

double VisibilityErrors::wrongly_hidden_fraction() const {
    return hidden_length > 0.0 ? wrongly_hidden_length / hidden_length : 0.0;
}

double VisibilityErrors::shallow_hidden_fraction() const {
    return hidden_length > 0.0 ? hidden_shallow_length / hidden_length : 0.0;
}

double VisibilityErrors::deep_visible_fraction() const {
    return visible_length > 0.0 ? visible_deep_length / visible_length : 0.0;
}

double DepthReference::pixel_depth(double z) const {
    const Camera& camera = view_.camera();
    if (camera.orthographic) return double(camera.ortho_height) / height_;
    return z * 2.0 * std::tan(0.5 * glm::radians(double(camera.fov_degrees))) / height_;
}

VisibilityErrors& VisibilityErrors::operator+=(const VisibilityErrors& other) {
    visible_length += other.visible_length;
    hidden_length += other.hidden_length;
    wrongly_visible_length += other.wrongly_visible_length;
    wrongly_hidden_length += other.wrongly_hidden_length;
    hidden_near_outline_length += other.hidden_near_outline_length;
    hidden_shallow_length += other.hidden_shallow_length;
    visible_deep_length += other.visible_deep_length;
    outside_length += other.outside_length;
    level_mismatch_length += other.level_mismatch_length;
    for (const glm::vec2& p : other.wrongly_visible_at)
        if (wrongly_visible_at.size() < kExamples) wrongly_visible_at.push_back(p);
    for (const glm::vec2& p : other.wrongly_hidden_at)
        if (wrongly_hidden_at.size() < kExamples) wrongly_hidden_at.push_back(p);
    return *this;
}

std::ostream& operator<<(std::ostream& out, const VisibilityErrors& e) {
    const auto points = [&](const std::vector<glm::vec2>& at) {
        for (const glm::vec2& p : at) out << " (" << p.x << ", " << p.y << ")";
    };
    const std::ios::fmtflags flags = out.flags();
    const std::streamsize precision = out.precision();
    out << std::fixed << std::setprecision(2) << "wrongly visible " << 100.0 * e.wrongly_visible_fraction() << " % ("
        << e.wrongly_visible_length << " of " << e.visible_length << " px";
    if (!e.wrongly_visible_at.empty()) {
        out << "; at";
        points(e.wrongly_visible_at);
    }
    out << "), wrongly hidden " << 100.0 * e.wrongly_hidden_fraction() << " % (" << e.wrongly_hidden_length << " of "
        << e.hidden_length << " px; " << e.hidden_near_outline_length << " px hidden along an outline";
    if (!e.wrongly_hidden_at.empty()) {
        out << "; at";
        points(e.wrongly_hidden_at);
    }
    out << "), false hidden " << 100.0 * e.shallow_hidden_fraction() << " % (" << e.hidden_shallow_length
        << " px), visible a pixel deep " << 100.0 * e.deep_visible_fraction() << " % (" << e.visible_deep_length
        << " px), level mismatch " << e.level_mismatch_length << " px";
    if (e.outside_length > 0.0) out << ", outside the image " << e.outside_length << " px";
    out.flags(flags);
    out.precision(precision);
    return out;
}

namespace {

// Calls f(point, length, path, wrong, nearer) for each sample of `paths` inside the image:
// the verdict of check_paths and how many of the 9 depths around it are nearer by > eps.
template <class F>
void judge_samples(const DepthReference& reference, const std::vector<LinePath>& paths, bool hidden, double spacing_px,
                   double* outside_length, F&& f) {
    const double k = reference.scale(), eps = reference.eps();
    for_each_sample(paths, spacing_px,
                    [&](const glm::dvec2& p, double window_depth, double length, const LinePath& path) {
        if (length <= 0.0) return;
        if (!(p.x >= 0.0 && p.y >= 0.0 && p.x <= reference.width() && p.y <= reference.height())) {
            if (outside_length) *outside_length += length;
            return;
        }
        const double z = reference.view_depth_of_window(window_depth);
        const int ci = int(std::floor(p.x * k)), cj = int(std::floor(p.y * k));
        int nearer = 0, pixel_nearer = 0;
        const double pixel = reference.pixel_depth(z);
        for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di) {
                const double d = reference.depth(ci + di, cj + dj);
                nearer += d < z - eps;
                pixel_nearer += d < z - pixel;
            }
        f(p, length, path, hidden ? nearer == 0 : nearer == 9, nearer, pixel_nearer);
    });
}

}  // namespace

VisibilityErrors check_paths(const DepthReference& reference, const std::vector<LinePath>& paths, bool hidden,
                             double spacing_px) {
    VisibilityErrors e;
    judge_samples(
        reference, paths, hidden, spacing_px, &e.outside_length,
        [&](const glm::dvec2& p, double length, const LinePath& path, bool wrong, int nearer, int pixel_nearer) {
        (hidden ? e.hidden_length : e.visible_length) += length;
        if (hidden && pixel_nearer == 0) e.hidden_shallow_length += length;
        if (!hidden && pixel_nearer == 9) e.visible_deep_length += length;
        if (hidden ? path.level < 1 : path.level != 0) e.level_mismatch_length += length;
        if (hidden && nearer > 0 && nearer < 9) e.hidden_near_outline_length += length;
        if (!wrong) return;
        (hidden ? e.wrongly_hidden_length : e.wrongly_visible_length) += length;

        std::vector<glm::vec2>& at = hidden ? e.wrongly_hidden_at : e.wrongly_visible_at;
        if (at.size() < kExamples) at.emplace_back(p);
        });
    return e;
}

Image picture(const DepthReference& reference, const LineLayer& layer, glm::dvec2 origin, double size_px, int zoom) {
    const int side = int(std::lround(size_px * zoom));
    Image image(side, side);
    const double k = reference.scale();
    double lo = kInfinity, hi = -kInfinity;
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            const double d = reference.depth(int(std::floor((origin.x + (x + 0.5) / zoom) * k)),
                                             int(std::floor((origin.y + (y + 0.5) / zoom) * k)));
            if (std::isinf(d)) continue;
            lo = std::min(lo, d);
            hi = std::max(hi, d);
        }
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            const double d = reference.depth(int(std::floor((origin.x + (x + 0.5) / zoom) * k)),
                                             int(std::floor((origin.y + (y + 0.5) / zoom) * k)));
            uint8_t* px = image.pixel(x, y);
            const uint8_t g = std::isinf(d) ? 255 : uint8_t(200.0 - 150.0 * (d - lo) / std::max(hi - lo, 1e-12));
            px[0] = std::isinf(d) ? 255 : g;
            px[1] = std::isinf(d) ? 250 : g;
            px[2] = std::isinf(d) ? 235 : g;
            px[3] = 255;
        }
    const auto dot = [&](const glm::dvec2& p, std::array<uint8_t, 3> color) {
        const int cx = int(std::floor((p.x - origin.x) * zoom)), cy = int(std::floor((p.y - origin.y) * zoom));
        const int r = std::max(0, zoom / 8);
        for (int y = cy - r; y <= cy + r; ++y)
            for (int x = cx - r; x <= cx + r; ++x) {
                if (x < 0 || y < 0 || x >= side || y >= side) continue;
                uint8_t* px = image.pixel(x, y);
                px[0] = color[0];
                px[1] = color[1];
                px[2] = color[2];
            }
    };
    for (bool hidden : {false, true})
        judge_samples(reference, hidden ? layer.hidden : layer.visible, hidden, 0.25, nullptr,
                      [&](const glm::dvec2& p, double, const LinePath&, bool wrong, int, int pixel_nearer) {
            if (wrong)
                dot(p, hidden ? std::array<uint8_t, 3>{230, 0, 230} : std::array<uint8_t, 3>{230, 0, 0});
            else if (hidden && pixel_nearer == 0)
                dot(p, {255, 140, 0});
            else
                dot(p, hidden ? std::array<uint8_t, 3>{0, 90, 255} : std::array<uint8_t, 3>{0, 170, 0});
        });
    return image;
}

VisibilityErrors check_layer(const DepthReference& reference, const LineLayer& layer, double spacing_px) {
    VisibilityErrors e = check_paths(reference, layer.visible, false, spacing_px);
    e += check_paths(reference, layer.hidden, true, spacing_px);
    return e;
}

}  // namespace inkshade::test
