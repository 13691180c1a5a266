// rtsc 1.6's depth test for lines, as a second answer key beside DepthReference: rtsc draws
// the mesh into the depth buffer with back faces culled and glPolygonOffset(5, 30) (each
// front face pushed back by 5 times its depth slope per pixel plus 30 depth units), then draws
// its lines with GL_LEQUAL. A line fragment is drawn when its window depth is at most the
// buffer's at the pixel it falls in. Test support only (no GL): fidelity to rtsc's drawing,
// not a visibility oracle (a culled back face or an offset face can let a line show that a
// surface hides).
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "geometry/visibility.hpp"
#include "inkshade/camera.hpp"
#include "inkshade/line_drawing.hpp"
#include "inkshade/mesh.hpp"

namespace inkshade::test {

class RtscDepthBuffer {
public:
    RtscDepthBuffer(const Mesh& mesh, const Camera& camera, int width, int height);

    // Does a line fragment at image point p (pixels) with window depth d (LinePath::depth)
    // pass the depth test? Outside the image: false.
    bool passes(glm::dvec2 p, double window_depth) const;

private:
    geometry::ImageProjection view_;
    int width_, height_;
    std::vector<double> depth_;  // window depth, 1 where no front face covers the centre
};

// How a drawing's visible paths of one layer agree with rtsc's depth test applied to all its
// paths (visible and hidden, the same extraction): lengths in pixels. With `drawn`, the
// visible paths compared are drawn's (another extraction of the same view, e.g. with the
// default auto-smooth where `layer` has rtsc's smooth normals).
struct RtscAgreement {
    double rtsc_visible = 0.0;  // length rtsc's test draws
    double recalled = 0.0;      // ... of it within `tolerance_px` of a visible path
    double visible = 0.0;       // length of the visible paths
    double precise = 0.0;       // ... of it within tolerance_px of a sample rtsc draws
    double recall() const { return rtsc_visible > 0.0 ? recalled / rtsc_visible : 1.0; }
    double precision() const { return visible > 0.0 ? precise / visible : 1.0; }
    RtscAgreement& operator+=(const RtscAgreement& o);
};
RtscAgreement rtsc_agreement(const RtscDepthBuffer& buffer, const LineLayer& layer, double tolerance_px = 2.0,
                             const LineLayer* drawn = nullptr);

}  // namespace inkshade::test
