// suggestive-image: the image-space method of Qu, Chen & Zwicker 2022 (section 3.8) computed on the GPU. Suggestive contours are where
// n.v has a local minimum in the direction of w (DeCarlo et al. 2003): D_w(n.v) = 0 and
// D_w D_w(n.v) > 0, w = v - (n.v) n. Per pixel p, f = n.v from the G-buffer, d = the unit
// image direction of w (view-space w.xy), h = u_sc_step pixels:
//   f_x  = Sobel: sum_j s_j (f[+h,j] - f[-h,j]) / 8h,          s = (1, 2, 1)    f_y likewise
//   f_xx = sum_j s_j (f[+h,j] - 2 f[0,j] + f[-h,j]) / 4h^2                       f_yy likewise
//   f_xy = (f[+h,+h] - f[+h,-h] - f[-h,+h] + f[-h,-h]) / 4h^2
// (central differences smoothed across with the Sobel weights: n.v from interpolated normals
// has kinks at triangle edges, which plain second differences turn into dotted lines)
//   D_w f = f_x d.x + f_y d.y        D_w D_w f = f_xx d.x^2 + 2 f_xy d.x d.y + f_yy d.y^2
// (Qu et al. 2022 used one-sided differences, their eqs. 10 and 11; central ones put the line on the
// minimum rather than half a pixel off). Image-space derivatives along the projection of w
// vanish where the surface ones do, and the second derivative keeps its sign there.
// A pixel draws when S = D_w D_w f * H^2 (H = image height: derivatives per image height,
// resolution independent) exceeds `threshold`, n.v > `min-ndotv`, |w| is not ~0, and its 3x3
// stencil stays on one object without depth jumps. Its distance to the zero crossing along w
// is one Newton step, |D_w f| / D_w D_w f pixels; coverage = clamp(width/2 - distance + 0.5)
// (anti-aliased), times the fade clamp((S - threshold) / fade) and a fade from 0 at n.v =
// min-ndotv to 1 at 2 min-ndotv.
uniform int u_sc_step;
uniform float u_sc_threshold;
uniform float u_sc_fade;
uniform float u_sc_min_ndotv;
uniform float u_sc_width;

float suggestive_coverage(ivec2 p) {
    GSample c = gbuffer_at(p);
    if (c.id == 0u || c.ndotv < u_sc_min_ndotv) return 0.0;
    float wl = length(c.w);
    if (wl < 1e-3) return 0.0;
    vec2 d = c.w / wl;
    int h = max(u_sc_step, 1);
    float f[9];
    for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i) {
            GSample t = gbuffer_at(p + ivec2(i, j) * h);
            // Stay on one smooth piece of surface: same object, no depth jump.
            if (t.id != c.id || abs(t.depth - c.depth) > 0.05 * c.depth) return 0.0;
            f[(j + 1) * 3 + (i + 1)] = t.ndotv;
        }
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
    float distance = abs(dw) / dww;
    float coverage = clamp(0.5 * u_sc_width - distance + 0.5, 0.0, 1.0);
    float fade = clamp((strength - u_sc_threshold) / max(u_sc_fade, 1e-6), 0.0, 1.0);
    // Trimmed near contours (DeCarlo et al. 2003 drop them where w turns unstable): fades in
    // between min-ndotv and twice that.
    fade *= smoothstep(u_sc_min_ndotv, 2.0 * u_sc_min_ndotv, c.ndotv);
    return coverage * fade;
}
