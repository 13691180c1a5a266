// visible_fills (visible_fills.hpp): hidden-surface removal in the image by polygon clipping
// (Clipper 6, Angus Johnson; Vatti 1992, "A generic solution to polygon clipping"), in the
// spirit of Weiler & Atherton 1977, "Hidden surface removal using polygon area sorting":
// each face keeps what no face in front of it covers.
#include "geometry/visible_fills.hpp"

#include <clipper.hpp>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>

#include "geometry/orientation.hpp"
#include "geometry/visibility.hpp"

namespace inkshade::geometry {

namespace {

namespace cl = ClipperLib;

constexpr double kUnits = 1024.0;     // Clipper's integer coordinates: 1/1024 px
constexpr double kMinOverlap = 1e-6;  // px²: faces meeting along an edge do not overlap
constexpr int kCell = 16;             // px: the grid that finds faces whose images overlap

// A face (or the piece of it a plane leaves) in the image: counter-clockwise points in pixels
// (y down) and their depth-buffer values, which are affine over the image of a plane.
struct Flat {
    std::array<glm::dvec2, 3> p;
    std::array<double, 3> z;
    glm::dvec2 lo, hi;
    uint32_t material = 0;
    uint32_t order = 0;  // ties between coplanar overlapping faces go to the lower
};

double cross(glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; }

double area(const std::vector<glm::dvec2>& poly) {
    double a = 0.0;
    for (size_t i = 0; i < poly.size(); ++i) a += cross(poly[i], poly[(i + 1) % poly.size()]);
    return 0.5 * a;
}

// Sutherland–Hodgman: the part of a convex polygon where side(v) <= 0, `side` affine.
template <class P, class Side>
std::vector<P> clip(const std::vector<P>& poly, Side side) {
    std::vector<P> out;
    for (size_t i = 0; i < poly.size(); ++i) {
        const P& a = poly[i];
        const P& b = poly[(i + 1) % poly.size()];
        const double sa = side(a), sb = side(b);
        if (sa <= 0.0) out.push_back(a);
        if ((sa < 0.0 && sb > 0.0) || (sa > 0.0 && sb < 0.0)) out.push_back(a + (b - a) * (sa / (sa - sb)));
    }
    return out;
}

// Depth of a flat at image point q (barycentric in the image).
double depth_at(const Flat& f, glm::dvec2 q) {
    const double d = cross(f.p[1] - f.p[0], f.p[2] - f.p[0]);
    const double b1 = cross(q - f.p[0], f.p[2] - f.p[0]) / d;
    const double b2 = cross(f.p[1] - f.p[0], q - f.p[0]) / d;
    return f.z[0] + b1 * (f.z[1] - f.z[0]) + b2 * (f.z[2] - f.z[0]);
}

// The faces' visible pieces projected: clipped by the section and near planes, fanned into
// triangles, counter-clockwise in the image; back faces left out on a closed mesh.
std::vector<Flat> project_faces(const Mesh& mesh, const ImageProjection& proj, const Camera& camera,
                                const std::optional<SectionPlane>& section) {
    // A section opens a closed mesh: its inside, back faces, shows through the cut.
    const bool cull = !section && is_closed_outward(mesh);
    const bool materials = mesh.face_materials.size() == mesh.triangles.size();
    std::vector<Flat> flats;
    for (size_t f = 0; f < mesh.triangles.size(); ++f) {
        const glm::uvec3 t = mesh.triangles[f];
        std::vector<glm::dvec3> poly = {glm::dvec3(mesh.positions[t.x]), glm::dvec3(mesh.positions[t.y]),
                                        glm::dvec3(mesh.positions[t.z])};
        if (section) poly = clip(poly, [&](const glm::dvec3& p) { return section->distance(glm::vec3(p)); });
        poly =
            clip(poly, [&](const glm::dvec3& p) { return double(camera.near_plane) - proj.view_depth(glm::vec3(p)); });
        if (poly.size() < 3) continue;
        std::vector<glm::dvec3> image(poly.size());
        for (size_t i = 0; i < poly.size(); ++i) image[i] = proj.project(glm::vec3(poly[i]));
        // Kept within a guard frame far outside the image, so Clipper's integers never overflow;
        // depth is affine in the image, so the cut points keep exact depths.
        const double guard = 64.0 * std::max(proj.width(), proj.height());
        for (int axis = 0; axis < 2; ++axis) {
            image = clip(image, [&](const glm::dvec3& q) { return q[axis] - guard; });
            image = clip(image, [&](const glm::dvec3& q) { return -guard - q[axis]; });
        }
        if (image.size() < 3) continue;
        std::vector<glm::dvec2> outline(image.size());
        for (size_t i = 0; i < image.size(); ++i) outline[i] = glm::dvec2(image[i]);
        const double a = area(outline);
        // Image y points down: a face counter-clockwise from the front is clockwise here.
        if (std::abs(a) < kMinOverlap || (cull && a > 0.0)) continue;
        for (size_t i = 1; i + 1 < image.size(); ++i) {
            Flat flat;
            const size_t k[3] = {0, i, i + 1};
            for (int j = 0; j < 3; ++j) {
                flat.p[j] = glm::dvec2(image[k[j]]);
                flat.z[j] = image[k[j]].z;
            }
            if (cross(flat.p[1] - flat.p[0], flat.p[2] - flat.p[0]) < 0.0) {
                std::swap(flat.p[1], flat.p[2]);
                std::swap(flat.z[1], flat.z[2]);
            }
            flat.lo = glm::min(flat.p[0], glm::min(flat.p[1], flat.p[2]));
            flat.hi = glm::max(flat.p[0], glm::max(flat.p[1], flat.p[2]));
            flat.material = materials ? mesh.face_materials[f] : 0;
            flat.order = uint32_t(flats.size());
            flats.push_back(flat);
        }
    }
    return flats;
}

cl::Path to_path(const std::vector<glm::dvec2>& poly) {
    cl::Path path;
    path.reserve(poly.size());
    for (const glm::dvec2& q : poly)
        path.emplace_back(cl::cInt(std::llround(q.x * kUnits)), cl::cInt(std::llround(q.y * kUnits)));
    return path;
}

// The faces whose bounding boxes meet each cell of a kCell-pixel grid over the image.
struct FaceGrid {
    int columns = 0, rows = 0;
    std::vector<std::vector<uint32_t>> cells;

    FaceGrid(const std::vector<Flat>& flats, int width, int height)
        : columns(width / kCell + 1), rows(height / kCell + 1), cells(size_t(columns) * size_t(rows)) {
        for (uint32_t i = 0; i < flats.size(); ++i) {
            const auto [c0, r0, c1, r1] = range(flats[i]);
            for (int r = r0; r <= r1; ++r)
                for (int c = c0; c <= c1; ++c) cells[size_t(r) * columns + c].push_back(i);
        }
    }
    std::array<int, 4> range(const Flat& f) const {
        auto cell = [](double v, int n) { return std::clamp(int(std::floor(v / kCell)), 0, n - 1); };
        return {cell(f.lo.x, columns), cell(f.lo.y, rows), cell(f.hi.x, columns), cell(f.hi.y, rows)};
    }
};

// What of flat `t` no flat in front of it covers.
cl::Paths visible_part(const std::vector<Flat>& flats, const FaceGrid& grid, uint32_t t) {
    const Flat& T = flats[t];
    const std::vector<glm::dvec2> own(T.p.begin(), T.p.end());
    std::vector<uint32_t> near;
    const auto [c0, r0, c1, r1] = grid.range(T);
    for (int r = r0; r <= r1; ++r)
        for (int c = c0; c <= c1; ++c) {
            const auto& cell = grid.cells[size_t(r) * grid.columns + c];
            near.insert(near.end(), cell.begin(), cell.end());
        }
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    cl::Paths covered;
    const double own_area = area(own);
    for (uint32_t u : near) {
        const Flat& U = flats[u];
        if (u == t || U.lo.x >= T.hi.x || U.hi.x <= T.lo.x || U.lo.y >= T.hi.y || U.hi.y <= T.lo.y) continue;
        std::vector<glm::dvec2> overlap = own;
        for (int e = 0; e < 3 && overlap.size() >= 3; ++e) {
            const glm::dvec2 a = U.p[e], b = U.p[(e + 1) % 3];
            overlap = clip(overlap, [&](const glm::dvec2& q) { return -cross(b - a, q - a); });
        }
        if (overlap.size() < 3) continue;
        const double overlap_area = area(overlap);
        if (overlap_area < kMinOverlap) continue;
        glm::dvec2 centre(0.0);
        for (const glm::dvec2& q : overlap) centre += q;
        centre /= double(overlap.size());
        const double zt = depth_at(T, centre), zu = depth_at(U, centre);
        const bool in_front = zu < zt || (zu == zt && U.order < T.order);
        if (!in_front) continue;
        if (overlap_area >= own_area * (1.0 - 1e-9)) return {};  // covered whole
        covered.push_back(to_path(overlap));
    }
    if (covered.empty()) return {to_path(own)};
    cl::Clipper clipper;
    clipper.AddPath(to_path(own), cl::ptSubject, true);
    clipper.AddPaths(covered, cl::ptClip, true);
    cl::Paths out;
    clipper.Execute(cl::ctDifference, out, cl::pftNonZero, cl::pftNonZero);
    return out;
}

// Interleaved bits of a cell's column and row: pieces near in this order are near in the image.
uint64_t morton(uint32_t x, uint32_t y) {
    uint64_t m = 0;
    for (int b = 0; b < 16; ++b) m |= (uint64_t(x >> b & 1) << (2 * b)) | (uint64_t(y >> b & 1) << (2 * b + 1));
    return m;
}

cl::Paths unite(const cl::Paths& a, const cl::Paths& b) {
    cl::Clipper clipper;
    clipper.AddPaths(a, cl::ptSubject, true);
    clipper.AddPaths(b, cl::ptSubject, true);
    cl::Paths out;
    clipper.Execute(cl::ctUnion, out, cl::pftNonZero, cl::pftNonZero);
    return out;
}

// The union of many small pieces, joined pairwise up a tree in image order: one sweep over
// them all would carry every piece's edges across each scanline (Vatti's active edge list),
// quadratic in the pieces; each join here meets only two compact neighbours' outlines.
cl::Paths unite_all(std::vector<cl::Paths> groups) {
    if (groups.empty()) return {};
    while (groups.size() > 1) {
        std::vector<cl::Paths> next((groups.size() + 1) / 2);
        tbb::parallel_for(size_t(0), next.size(), [&](size_t i) {
            next[i] = 2 * i + 1 < groups.size() ? unite(groups[2 * i], groups[2 * i + 1]) : std::move(groups[2 * i]);
        });
        groups = std::move(next);
    }
    return std::move(groups[0]);
}

}  // namespace

std::vector<FillRegion> visible_fills(const Mesh& mesh, const Camera& camera, int width, int height,
                                      const std::optional<SectionPlane>& section, glm::vec3 base_color) {
    const ImageProjection proj(camera, width, height);
    const std::vector<Flat> flats = project_faces(mesh, proj, camera, section);
    const FaceGrid grid(flats, width, height);
    std::vector<cl::Paths> pieces(flats.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, flats.size(), 64), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t i = r.begin(); i != r.end(); ++i) pieces[i] = visible_part(flats, grid, uint32_t(i));
    });
    // Each material's pieces in image order (their grid cell's Morton code), 16 to a group.
    std::vector<std::pair<uint64_t, uint32_t>> order;
    order.reserve(flats.size());
    for (uint32_t i = 0; i < flats.size(); ++i) {
        if (pieces[i].empty()) continue;
        const auto [c0, r0, c1, r1] = grid.range(flats[i]);
        order.emplace_back(morton(uint32_t(c0 + c1) / 2, uint32_t(r0 + r1) / 2), i);
    }
    std::sort(order.begin(), order.end());
    std::map<uint32_t, std::vector<cl::Paths>> by_material;
    for (const auto& [code, i] : order) {
        std::vector<cl::Paths>& groups = by_material[flats[i].material];
        if (groups.empty() || groups.back().size() >= 16) groups.emplace_back();
        groups.back().insert(groups.back().end(), pieces[i].begin(), pieces[i].end());
    }
    const cl::Path frame =
        to_path({{0.0, 0.0}, {double(width), 0.0}, {double(width), double(height)}, {0.0, double(height)}});
    std::vector<FillRegion> regions;
    for (auto& [material, groups] : by_material) {
        // The joined pieces, cut to the image.
        cl::Clipper clipper;
        clipper.AddPaths(unite_all(std::move(groups)), cl::ptSubject, true);
        clipper.AddPath(frame, cl::ptClip, true);
        cl::Paths joined;
        clipper.Execute(cl::ctIntersection, joined, cl::pftNonZero, cl::pftNonZero);
        if (joined.empty()) continue;
        FillRegion region;
        region.material = material;
        region.color = material < mesh.materials.size() ? mesh.materials[material].diffuse : base_color;
        for (const cl::Path& path : joined) {
            std::vector<glm::vec2> ring;
            ring.reserve(path.size());
            for (const cl::IntPoint& q : path)
                ring.emplace_back(float(double(q.X) / kUnits), float(double(q.Y) / kUnits));
            region.rings.push_back(std::move(ring));
        }
        regions.push_back(std::move(region));
    }
    return regions;
}

}  // namespace inkshade::geometry
