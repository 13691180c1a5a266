// rtsc 1.6's suggestive contours with its default settings, rebuilt from rtsc.cc as an answer key
// for the `suggestive` line type (no code shared with src/geometry/suggestive_contours.cpp or
// feature_size.cpp): trimesh2's need_normals (Max 1999 weights), curvature and its derivative
// (Rusinkiewicz 2004; Inkshade's compute_curvature, the same estimator as trimesh2's
// TriMesh_curvature.cc: per-face fits averaged with Voronoi corner areas), rtsc's
// compute_feature_size, compute_perview (kr sin²θ, sctest_num / sctest_den with sug_thresh 0.01),
// draw_isolines with back-face culling and the test_sc trim, draw_faded's alpha (fade 0.03), then
// rtsc's depth test (RtscDepthBuffer) on samples every half pixel. Test support only.
//
// Fading: rtsc draws each segment with alpha num / (den·fade + num), interpolated along it, over
// the shaded mesh; a sample counts with that alpha as its weight (a piece at alpha 0.1 is a
// tenth as dark, and counts a tenth as much), and Inkshade's paths count with their strength.
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "geometry/rtsc_depth_buffer.hpp"
#include "inkshade/camera.hpp"
#include "inkshade/line_drawing.hpp"
#include "inkshade/mesh.hpp"

namespace inkshade::test {

// One half-pixel sample that rtsc draws: image point, alpha and the image length it stands for.
struct RtscLineSample {
    glm::dvec2 p{0.0};
    double alpha = 0.0, length = 0.0;
};

class RtscSuggestive {
public:
    // The view-independent part (rtsc's initialize): normals, curvature, feature size. `mesh` as
    // rtsc reads the file: one vertex per position, every edge smooth.
    explicit RtscSuggestive(const Mesh& mesh);

    float feature_size() const { return feature_size_; }

    // The suggestive contour samples rtsc draws from `camera` (perspective) at width x height,
    // after its depth test.
    std::vector<RtscLineSample> drawn(const Camera& camera, int width, int height) const;

private:
    const Mesh& mesh_;
    std::vector<glm::vec3> normals_, pdir1_, pdir2_;
    std::vector<float> k1_, k2_;
    std::vector<glm::vec4> dcurv_;
    float feature_size_ = 1.0f;
};

// Recall (alpha-weighted length of rtsc's samples within `tolerance_px` of a visible path of
// `layer`) and precision (strength-weighted length of the visible paths within tolerance_px of
// a sample rtsc draws), as RtscAgreement's four sums.
RtscAgreement rtsc_suggestive_agreement(const std::vector<RtscLineSample>& rtsc, const LineLayer& layer,
                                        double tolerance_px = 2.0);

}  // namespace inkshade::test
