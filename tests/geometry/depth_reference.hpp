// An answer key for hidden-line removal that shares nothing with src/geometry/visibility.cpp
// but the camera mapping: a CPU z-buffer of the mesh at `scale` times the image resolution,
// and a checker that samples every path of a line drawing against it. Test support only (no GL).
//
// The z-buffer stores linear view depth (distance from the eye plane along the view direction,
// ImageProjection::view_depth), interpolated perspective-correctly: 1/z is affine in screen
// space for perspective views, z for orthographic ones. Both sides of every triangle are drawn
// (no culling): a line is hidden by any surface, front- or back-facing. A pixel is covered
// when its centre lies inside or on the triangle; shared edges are evaluated with the same
// vertex order from both triangles, so a centre on one is never missed by both.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iosfwd>
#include <vector>

#include <glm/glm.hpp>

#include "geometry/visibility.hpp"
#include "inkshade/camera.hpp"
#include "inkshade/image.hpp"
#include "inkshade/line_drawing.hpp"
#include "inkshade/mesh.hpp"

namespace inkshade::test {

class DepthReference {
public:
    // Rasterises every triangle of `mesh` whose vertices all lie within the camera's near/far
    // range; the others are counted in clipped_triangles() (the tests' scenes have none, and
    // assert so, instead of this clipping them against the near plane).
    DepthReference(const Mesh& mesh, const Camera& camera, int width, int height, int scale = 4);

    int scale() const { return scale_; }
    int width() const { return width_; }  // of the image, in image pixels
    int height() const { return height_; }
    const geometry::ImageProjection& projection() const { return view_; }
    size_t clipped_triangles() const { return clipped_; }

    // View depth of the nearest surface at the centre of high-resolution pixel (i, j), which
    // covers [i, i + 1] / scale x [j, j + 1] / scale of the image; +infinity where no surface
    // covers it and outside the image.
    double depth(int i, int j) const;

    // View depth of a window depth as LinePath::depth stores it (the GL depth buffer's [0, 1]):
    // perspective z_ndc = 2d − 1, z = 2nf / ((f + n) − z_ndc (f − n)); orthographic z = n + d (f − n).
    double view_depth_of_window(double window_depth) const;

    // How much nearer than a line sample a surface must be to count as in front of it:
    // 1e-4 × the mesh's bounding-box diagonal, the implementation's own ray tolerance
    // (RayScene::tolerance). The tests' closest surfaces that must hide each other (two
    // plates) are 1e-3 of the scene apart, ten times this.
    double eps() const { return eps_; }
    // The depth a pixel spans at view depth z: the world size of one image pixel there (the
    // height of the view at z over the image height; orthographic: ortho_height / height).
    double pixel_depth(double z) const;

private:
    geometry::ImageProjection view_;
    int width_, height_, scale_;
    int hi_width_, hi_height_;
    std::vector<float> depth_;
    size_t clipped_ = 0;
    double eps_ = 0.0;
};

// What check_paths found, lengths in image pixels.
struct VisibilityErrors {
    double visible_length = 0.0;          // length of the paths checked as visible
    double hidden_length = 0.0;           // ... as hidden
    double wrongly_visible_length = 0.0;  // visible, but a nearer surface covers all of it
    double wrongly_hidden_length = 0.0;   // hidden, but nothing is in front of any of it
    // Hidden samples with something in front in part of the 3 x 3 window only: within 1.5
    // high-resolution pixels of an occluder's outline (or in front by less than eps), where a
    // hidden line running along an outline, meeting it at a grazing angle or at a contour's
    // cusp is right or wrong by less than the window. Reported, not judged.
    double hidden_near_outline_length = 0.0;
    // Hidden samples that the z-buffer shows (false hidden): no surface of the 3 x 3 window is
    // in front by more than the depth a pixel spans there (DepthReference::pixel_depth), as
    // rtsc's depth test keeps a line (3 x 3 max plus a bias). Includes wrongly hidden ones.
    double hidden_shallow_length = 0.0;
    // Visible samples with every depth of the window in front by more than the depth a pixel
    // spans: hidden by the own-surface rule too (docs/lines.md), whatever surface it is.
    double visible_deep_length = 0.0;
    double outside_length = 0.0;         // samples outside the image (not checked)
    double level_mismatch_length = 0.0;  // visible paths with level != 0, hidden with level < 1
    std::vector<glm::vec2> wrongly_visible_at, wrongly_hidden_at;  // the first few, for messages

    // Fractions of the visible and hidden lengths (0 when that length is 0).
    double wrongly_visible_fraction() const;
    double wrongly_hidden_fraction() const;
    double shallow_hidden_fraction() const;  // of the hidden length
    double deep_visible_fraction() const;    // of the visible length
    VisibilityErrors& operator+=(const VisibilityErrors& other);
};
std::ostream& operator<<(std::ostream& out, const VisibilityErrors& errors);

// Samples every path every `spacing_px` along the image polyline (midpoints of equal steps,
// closing segment included for closed paths), the window depth interpolated linearly between
// points (exact for a straight 3D segment: window depth is affine in screen space along it),
// then converted to view depth z. With the 3 x 3 high-resolution pixels around the sample:
//   a visible sample is wrong ("hidden by a nearer surface") when all 9 depths are < z − eps;
//   a hidden sample is wrong ("actually in front") when none of the 9 depths is < z − eps.
// The 3 x 3 window lets a line on an outline or on a crease sit on either side of the pixel
// centres without failing: within 1.5 high-resolution pixels (0.375 px at scale 4) of an
// occluder's outline either answer is accepted, for visible and hidden samples alike.
VisibilityErrors check_paths(const DepthReference& reference, const std::vector<LinePath>& paths, bool hidden,
                             double spacing_px = 0.25);
// Both lists of a layer (visible with hidden = false, hidden with hidden = true).
VisibilityErrors check_layer(const DepthReference& reference, const LineLayer& layer, double spacing_px = 0.25);

// A picture for looking into a failure: the reference's depth in grey (nearer is lighter,
// scaled to the frame; no surface: cream) over the image square [origin, origin + size_px]²,
// `zoom` output pixels per image pixel, with the layer's samples as dots: visible green,
// hidden blue, wrongly visible red, wrongly hidden magenta, other false hidden (hidden_shallow_length) orange.
Image picture(const DepthReference& reference, const LineLayer& layer, glm::dvec2 origin, double size_px, int zoom);

// Calls f(point, window_depth, length, path) for the samples of `paths` as check_paths takes them.
template <class F>
void for_each_sample(const std::vector<LinePath>& paths, double spacing_px, F&& f) {
    for (const LinePath& path : paths) {
        const size_t n = path.points.size();
        if (n == 0) continue;
        if (n == 1) {
            f(glm::dvec2(path.points[0]), double(path.depth[0]), 0.0, path);
            continue;
        }
        const size_t segments = path.closed ? n : n - 1;
        for (size_t i = 0; i < segments; ++i) {
            const size_t j = (i + 1) % n;
            const glm::dvec2 a(path.points[i]), b(path.points[j]);
            const double da = path.depth[i], db = path.depth[j];
            const double length = glm::length(b - a);
            const int steps = std::max(1, int(std::ceil(length / spacing_px)));
            for (int s = 0; s < steps; ++s) {
                const double t = (s + 0.5) / steps;
                f(a + t * (b - a), da + t * (db - da), length / steps, path);
            }
        }
    }
}

}  // namespace inkshade::test
