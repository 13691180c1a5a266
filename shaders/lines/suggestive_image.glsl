// suggestive-image: the image-space method of Qu, Chen & Zwicker 2022 (section 3.8) computed on the GPU. Suggestive contours are where
// n.v has a local minimum in the direction of w (DeCarlo et al. 2003): D_w(n.v) = 0 and
// D_w D_w(n.v) > 0, w = v - (n.v) n. Per pixel p, f = n.v from the G-buffer, d = the unit
// image direction of w (view-space w.xy), h = the spacing in pixels (below):
//   f_x  = Sobel: sum_j s_j (f[+h,j] - f[-h,j]) / 8h,          s = (1, 2, 1)    f_y likewise
//   f_xx = sum_j s_j (f[+h,j] - 2 f[0,j] + f[-h,j]) / 4h^2                       f_yy likewise
//   f_xy = (f[+h,+h] - f[+h,-h] - f[-h,+h] + f[-h,-h]) / 4h^2
// (central differences smoothed across with the Sobel weights)
//   D_w f = f_x d.x + f_y d.y        D_w D_w f = f_xx d.x^2 + 2 f_xy d.x d.y + f_yy d.y^2
// (Qu et al. 2022 used one-sided differences, their eqs. 10 and 11; central ones put the line on the
// minimum rather than half a pixel off). Image-space derivatives along the projection of w
// vanish where the surface ones do, and the second derivative keeps its sign there.
//
// The spacing spans the mesh's triangles: h = max(step, edge-span * L / footprint) pixels, L the
// mesh's typical edge length and footprint a pixel's world size at this pixel's depth. n.v from
// interpolated normals is smooth inside a triangle and kinks at its edges; differences over less
// than a triangle see each kink as a sharp valley of its own, a dash along each edge (rows of
// dashes on coarse meshes, cracks on a CAD part's faces whose normals bend slightly), while over
// a triangle or more they measure the surface's own curvature (the kinks average out).
//
// A pixel draws when S = D_w D_w f * H^2 (H = image height: derivatives per image height,
// resolution independent) exceeds `threshold`, n.v > `min-ndotv`, |w| is not ~0, and its
// stencils stay on one object without depth jumps. Its distance to the zero crossing of D_w f
// along w is one Newton step on that field, |D_w f| / r pixels with r its rate of change along
// d between the pixels on either side (r = D_w D_w f where f is quadratic over the stencil;
// where the valley's floor is flat at this scale r is small and the pixel is not on the line, so
// lines keep their width); coverage = clamp(width/2 - distance + 0.5) (anti-aliased), times the
// fade clamp((S - threshold) / fade) and a fade from 0 at n.v = min-ndotv to 1 at 2 min-ndotv.
uniform int u_sc_step;
uniform float u_sc_span_world;  // edge-span x the mesh's typical edge length, world units
uniform vec2 u_sc_footprint;    // world size of a pixel at linear depth z: x + y z
uniform float u_sc_threshold;
uniform float u_sc_fade;
uniform float u_sc_min_ndotv;
uniform float u_sc_width;

// n.v at the 3x3 taps q + (i, j) h, f[(j + 1) * 3 + (i + 1)], or false when the stencil leaves
// the piece of surface of c: a tap on another object (or the background), or a depth jump: a
// second difference of linear depth through q above `jump` (zero on a plane of any slope; a
// crease adds at most its change of slope times the spacing).
bool sc_stencil(ivec2 q, int h, GSample c, float jump, out float f[9]) {
    float z[9];
    for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i) {
            GSample t = gbuffer_at(q + ivec2(i, j) * h);
            if (t.id != c.id) return false;
            f[(j + 1) * 3 + (i + 1)] = t.ndotv;
            z[(j + 1) * 3 + (i + 1)] = t.depth;
        }
    for (int k = 0; k < 4; ++k)  // opposite taps k and 8 - k through the centre 4
        if (abs(z[k] + z[8 - k] - 2.0 * z[4]) > jump) return false;
    return true;
}

// D_w f at q, or false when its stencil leaves c's surface.
bool sc_first_derivative(ivec2 q, int h, vec2 d, GSample c, float jump, out float dw) {
    float f[9];
    if (!sc_stencil(q, h, c, jump, f)) return false;
    float hh = float(h);
    float fx = ((f[2] + 2.0 * f[5] + f[8]) - (f[0] + 2.0 * f[3] + f[6])) / (8.0 * hh);
    float fy = ((f[6] + 2.0 * f[7] + f[8]) - (f[0] + 2.0 * f[1] + f[2])) / (8.0 * hh);
    dw = fx * d.x + fy * d.y;
    return true;
}

float suggestive_coverage(ivec2 p) {
    GSample c = gbuffer_at(p);
    if (c.id == 0u || c.ndotv < u_sc_min_ndotv) return 0.0;
    float wl = length(c.w);
    if (wl < 1e-3) return 0.0;
    vec2 d = c.w / wl;
    float footprint = u_sc_footprint.x + u_sc_footprint.y * c.depth;
    int h = clamp(int(round(u_sc_span_world / max(footprint, 1e-30))), max(u_sc_step, 1), 64);
    // A depth jump: more than 5 % of the depth plus a change of slope of 2 over the spacing (a
    // crease between faces, not another surface behind).
    float jump = 0.05 * c.depth + 2.0 * float(h) * footprint;
    float f[9];
    if (!sc_stencil(p, h, c, jump, f)) return 0.0;
    float hh = float(h);
    // f[(j + 1) * 3 + (i + 1)] = f at (i h, j h).
    float fx = ((f[2] + 2.0 * f[5] + f[8]) - (f[0] + 2.0 * f[3] + f[6])) / (8.0 * hh);
    float fy = ((f[6] + 2.0 * f[7] + f[8]) - (f[0] + 2.0 * f[1] + f[2])) / (8.0 * hh);
    float fxx = ((f[0] - 2.0 * f[1] + f[2]) + 2.0 * (f[3] - 2.0 * f[4] + f[5]) + (f[6] - 2.0 * f[7] + f[8])) /
                (4.0 * hh * hh);
    float fyy = ((f[0] - 2.0 * f[3] + f[6]) + 2.0 * (f[1] - 2.0 * f[4] + f[7]) + (f[2] - 2.0 * f[5] + f[8])) /
                (4.0 * hh * hh);
    float fxy = (f[8] - f[2] - f[6] + f[0]) / (4.0 * hh * hh);
    float dw = fx * d.x + fy * d.y;
    float dww = fxx * d.x * d.x + 2.0 * fxy * d.x * d.y + fyy * d.y * d.y;
    float H = float(u_image_size.y);
    float strength = dww * H * H;
    if (strength <= u_sc_threshold) return 0.0;
    // Rate of change of D_w f along d, from the neighbours one pixel step along d (the nearest
    // of the 8 directions).
    ivec2 s = ivec2(round(d));
    float dw_minus, dw_plus;
    if (!sc_first_derivative(p - s, h, d, c, jump, dw_minus) || !sc_first_derivative(p + s, h, d, c, jump, dw_plus))
        return 0.0;
    float rate = (dw_plus - dw_minus) / (2.0 * dot(vec2(s), d));
    if (rate <= 0.0) return 0.0;
    float distance = abs(dw) / rate;
    float coverage = clamp(0.5 * u_sc_width - distance + 0.5, 0.0, 1.0);
    float fade = clamp((strength - u_sc_threshold) / max(u_sc_fade, 1e-6), 0.0, 1.0);
    // Trimmed near contours (DeCarlo et al. 2003 drop them where w turns unstable): fades in
    // between min-ndotv and twice that.
    fade *= smoothstep(u_sc_min_ndotv, 2.0 * u_sc_min_ndotv, c.ndotv);
    return coverage * fade;
}
