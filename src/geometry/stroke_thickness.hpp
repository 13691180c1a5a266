// Thickness along a stroke: the width of every point of an image path as the layer's width
// times its modifiers, as Freestyle's thickness shaders and Blender's line style thickness
// modifiers set it (Grabli et al. 2010, "Programmable Rendering of Line Drawing from 3D
// Scenes", ACM Transactions on Graphics 29(2)):
//   taper in/out        TaperShader / "Along Stroke": 0 at an end, full after a length
//   depth               "Distance from Camera": near and far factors over the model's depth
//   image curvature     "Curvature 3D" done in the image: factors at zero and high curvature
//   occlusion level     a factor per surface in front (hidden layers drawn thinner)
//   calligraphic        CalligraphicShader / "Calligraphy": thick along the nib, thin across
//   noise               ThicknessNoiseShader / "Noise": seeded value noise along arc length
//   strength (taper)    a point's strength, e.g. a suggestive contour fading in
#pragma once
#include <cstdint>
#include <vector>

#include "geometry/view_depth_range.hpp"
#include "inkshade/line_drawing.hpp"

namespace inkshade::geometry {

struct StrokeThickness {
    float width = 1.0f;                       // pixels: the layer's `width`
    bool strength_scales = false;             // `taper`: width × strength
    float taper_in_px = 0.0f;                 // width grows linearly from 0 over this arc length; 0 = none
    float taper_out_px = 0.0f;                // and falls to 0 over this much before the end
    glm::vec2 depth_factors{1.0f, 1.0f};      // at the nearest and the farthest depth, linear between
    glm::vec2 curvature_factors{1.0f, 1.0f};  // at zero curvature and at 1 / curvature_radius_px and above
    float curvature_radius_px = 10.0f;
    float level_factor = 1.0f;        // width × level_factor ^ occlusion level
    float calligraphy = 0.0f;         // 0..1: how thin a stroke across the nib gets (1 - calligraphy)
    float nib_angle_degrees = 90.0f;  // the direction of thickest strokes, from the image's +x, counter-clockwise
    float noise = 0.0f;               // relative amplitude: width × (1 + noise × n(s)), n in [-1, 1]
    float noise_period_px = 50.0f;    // the noise's wavelength along the stroke
    uint32_t seed = 0;

    // Whether any modifier can make widths differ from `width` (strength only with taper).
    bool varies() const;
};

// The width of each point of `path` (pixels, >= 0). `stream` tells apart the noise of
// different paths of one seed. Taper in/out applies to open paths (a loop has no ends).
std::vector<float> stroke_widths(const LinePath& path, const StrokeThickness& thickness, const ViewDepthRange& depth,
                                 uint32_t stream);

// Image-space curvature (1/px) at each point: the circle through the point and the points
// about kCurvatureSpanPx before and after it along the path (exact on a sampled circle).
std::vector<float> image_curvature(const LinePath& path);
constexpr double kCurvatureSpanPx = 2.0;

}  // namespace inkshade::geometry
