#version 450 core
// stipple: object-space stippling, ink dots (tinted by the base colour) that grow denser where
// the surface is darker.
//   tone t = luminance(E * max(n.l, 0) + A), darkness k = (1 - t)^threshold-curve;
//   dots = jittered feature points of a 3-D lattice in normalized model space (one per cell,
//   within 0.3 of its centre, and a rank, from cell_hash), so they stay on the surface while
//   the camera moves; only the 2x2x2 cells around a pixel are searched; a point belongs to the
//   surface's dot layer when it lies within half a cell of the tangent plane, and draws a
//   disc in that plane;
//   lattice spacing = a power of two chosen from the pixel footprint on the surface (square
//   root of a pixel's area there, from d(pos)/dx and d(pos)/dy) so that a full-dark area holds
//   `density` dots per dot-size^2 pixels;
//   the two nearest levels are blended by letting the dots of each appear with a probability
//   that keeps the dot count per pixel constant (no popping with zoom: the idea of
//   Praun et al. 2001's tonal art maps across mip levels and Bénard et al. 2009's
//   fractalized solid textures);
//   a dot with rank u (hashed, uniform) is inked when u < w * k, its area growing from 0 to
//   pi * (dot-size / 2)^2 pixels as w * k - u goes from 0 to 0.15 (radius grows with darkness),
//   with a 1-pixel anti-aliased rim;
//   colour = mix(paper-color, ink-color * C, ink coverage).
#include "common/surface.glsl"
#include "common/cell_hash.glsl"
uniform float u_dot_size;
uniform float u_density;
uniform vec3 u_ink_color;
uniform vec3 u_paper_color;
uniform float u_threshold_curve;

const float kGrowRamp = 0.15;  // rank interval over which a dot grows to full size
const float kDotJitter = 0.3;  // dots lie within this of their cell's centre (cell units)

// Ink coverage in [0, 1] at xf (pixels from the dot's cell corner + (0.5 - kDotJitter)) of the
// dot of the cell whose hash is hc; see level_ink.
float dot_ink(uint hc, vec3 o, vec3 xf, vec3 n, float px_per_cell, float r2_full, float presence) {
    vec4 u = bytes_to_unit(cell_hash_mix(hc));  // xyz: jitter, w: rank
    vec3 d = (o + (2.0 * kDotJitter) * u.xyz) * px_per_cell - xf;  // pixels
    float dn = dot(d, n);
    float t2 = dot(d, d) - dn * dn;  // squared distance in the tangent plane
    // Area grows linearly with the rank margin; (r^2 - t^2) / 2r ~ r - t near the rim gives a
    // 1-pixel anti-aliased edge without a square root per dot.
    float r2 = r2_full * clamp((presence - u.w) * (1.0 / kGrowRamp), 0.0, 1.0);
    float cov = clamp((r2 - t2) * 0.5 * inversesqrt(max(r2, 1e-4)) + 0.5, 0.0, 1.0);
    return (abs(dn) < 0.5 * px_per_cell && r2 > 0.0) ? cov : 0.0;
}

// Ink coverage of the dots of one lattice level (spacing h in normalized model units) at q with
// unit normal n; `pix` = model units per pixel (see main),
// `presence` = level weight * darkness. A dot is a disc in the tangent plane whose area is
// pi * (dot-size / 2)^2 pixels on screen (an ellipse where the surface is foreshortened).
float level_ink(vec3 q, vec3 n, float h, float pix, float presence) {
    vec3 x = q / h;
    // Points lie within kDotJitter = 0.3 of their cell centres, so every point within 0.7 of x
    // lies in the 2x2x2 cells whose centres surround x. A dot reaches half a cell off the
    // tangent plane and, at the default settings, <= 0.47 cell along it on the coarse level
    // (<= 0.69 in all: exact), <= 0.94 on the fine one, whose farthest rims are cut: ~0.25% of
    // the ink pixels of a 1024^2 sphere differ from a 4x4x4 search. The hash's per-axis products of
    // neighbouring cells differ by an add (cell_hash.glsl).
    ivec3 base = ivec3(floor(x - 0.5));
    uvec3 a = uvec3(base) * kCellHashMul, b = a + kCellHashMul;
    float px_per_cell = h / pix;
    vec3 xf = (x - vec3(base) - (0.5 - kDotJitter)) * px_per_cell;
    float r2 = 0.25 * u_dot_size * u_dot_size;  // squared radius of a full-size dot, pixels
    float ink = dot_ink(a.x ^ a.y ^ a.z, vec3(0, 0, 0), xf, n, px_per_cell, r2, presence);
    ink = max(ink, dot_ink(b.x ^ a.y ^ a.z, vec3(1, 0, 0), xf, n, px_per_cell, r2, presence));
    ink = max(ink, dot_ink(a.x ^ b.y ^ a.z, vec3(0, 1, 0), xf, n, px_per_cell, r2, presence));
    ink = max(ink, dot_ink(b.x ^ b.y ^ a.z, vec3(1, 1, 0), xf, n, px_per_cell, r2, presence));
    ink = max(ink, dot_ink(a.x ^ a.y ^ b.z, vec3(0, 0, 1), xf, n, px_per_cell, r2, presence));
    ink = max(ink, dot_ink(b.x ^ a.y ^ b.z, vec3(1, 0, 1), xf, n, px_per_cell, r2, presence));
    ink = max(ink, dot_ink(a.x ^ b.y ^ b.z, vec3(0, 1, 1), xf, n, px_per_cell, r2, presence));
    ink = max(ink, dot_ink(b.x ^ b.y ^ b.z, vec3(1, 1, 1), xf, n, px_per_cell, r2, presence));
    return ink;
}

void shade() {
    Surface s = surface();
    vec3 q = normalized_object_pos();
    // Pixel footprint on the surface from the singular values s_min <= s_max of the Jacobian
    // J = [dq/dx dq/dy] (model units per pixel along the least and most foreshortened
    // directions): pix = sqrt(s_min * s_max), the square root of a pixel's area on the
    // surface, keeps each dot's area in pixels and the dots per pixel constant where the
    // surface is foreshortened; the ratio is capped at 4 so that dots at grazing angles
    // stretch to at most twice their width along the surface instead of becoming streaks.
    vec3 a = dFdx(q), b = dFdy(q);
    float aa = dot(a, a), bb = dot(b, b), ab = dot(a, b);
    float root = sqrt((aa - bb) * (aa - bb) + 4.0 * ab * ab);
    float s_min = sqrt(max(0.5 * (aa + bb - root), 1e-30)), s_max = sqrt(max(0.5 * (aa + bb + root), 1e-30));
    float pix = s_min * sqrt(min(s_max / s_min, 4.0));
    // The model matrix is the identity (renderer.cpp), so the world normal is the model one.
    vec3 n = normalize(v_world_normal);

    float tone = dot(u_light_color * lambert(s.n, s.l) + u_ambient, vec3(0.2126, 0.7152, 0.0722));
    float darkness = pow(clamp(1.0 - tone, 0.0, 1.0), u_threshold_curve);

    // Lattice level: spacing h_d holds one dot per dot-size^2 / density pixels.
    float h_d = pix * u_dot_size / sqrt(u_density);
    float level = clamp(ceil(log2(h_d)), -16.0, 4.0);
    float f = clamp(level - log2(h_d), 0.0, 1.0);  // 0: coarse level exact, 1: fine level exact
    float h0 = exp2(level);
    float w_coarse = 1.0 - f;
    float w_fine = (exp2(2.0 * f) - (1.0 - f)) * 0.25;  // keeps w_c/h0^2 + w_f/(h0/2)^2 = 1/h_d^2
    float ink = max(level_ink(q, n, h0, pix, w_coarse * darkness), level_ink(q, n, 0.5 * h0, pix, w_fine * darkness));
    o_color = encode_output(mix(u_paper_color, u_ink_color * s.albedo, ink));
}
