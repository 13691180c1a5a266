#version 450 core
// cel: quantised light (five half-Lambert bands as in Qu, Chen & Zwicker 2022, eq. 4, by
// default; three-tone, highlight and rim settings in the cel-002 and cel-004 presets; three.js
// MeshToonMaterial's gradient map).
//   d     = 0.5 n.l + 0.5 (half-lambert) or max(n.l, 0) (ndotl)
//   level = levels[i] for the first i with d > thresholds[i], else the last level
//   lit   = mix(shade-color, 1, level)          (shade-color black: lit = level, classic cel)
//   out   = C * (E * lit + A)
//         + specular-color * E   where max(n.h, 0)^shininess > specular-threshold and n.l > 0
//         + rim-color * E        where (1 - n.v) * max(n.l, 0)^rim-power > rim-threshold
// The rim rule is the one of Erik Roystan Ross's widely copied "Toon Shader" tutorial for Unity
// (roystan.net).
// Band, highlight and rim edges are hard when smoothing = 0 (classic cel) and otherwise
// blended with smoothstep over smoothing * fwidth(value) around each threshold.
#include "common/surface.glsl"

const int kMaxThresholds = 7;
const int kMaxLevels = 8;

uniform int u_driver;  // 0 half-lambert, 1 ndotl
uniform float u_thresholds[kMaxThresholds];
uniform int u_thresholds_count;
uniform float u_levels[kMaxLevels];
uniform int u_levels_count;
uniform vec3 u_shade_color;
uniform float u_smoothing;
uniform float u_shininess;
uniform float u_specular_threshold;
uniform vec3 u_specular_color;
uniform vec3 u_rim_color;
uniform float u_rim_threshold;
uniform float u_rim_power;

// 1 where value > threshold, 0 below; with smoothing, a smoothstep over
// smoothing * fwidth(value) pixels' worth of change centred on the threshold.
float above(float value, float threshold) {
    float width = u_smoothing * fwidth(value);
    if (width <= 0.0) return value > threshold ? 1.0 : 0.0;
    return smoothstep(threshold - 0.5 * width, threshold + 0.5 * width, value);
}

// First-match band lookup written as a blend so that soft edges mix neighbouring levels:
// level = sum_i levels[i] * above_i * prod_{j<i} (1 - above_j) + fallback * prod_j (1 - above_j).
// With hard edges this is exactly "the first i with d > thresholds[i]" for any order. Every
// threshold tests the same d, so fwidth(d) is taken once and each step is a select, not
// above()'s branch (llvmpipe runs both sides of a varying branch and pays the mask upkeep).
float band_level(float d) {
    int count = min(u_thresholds_count, kMaxThresholds);
    float width = u_smoothing * fwidth(d);
    float remaining = 1.0;
    float level = 0.0;
    for (int i = 0; i < count; ++i) {
        float t = u_thresholds[i];
        float a = width > 0.0 ? smoothstep(t - 0.5 * width, t + 0.5 * width, d) : (d > t ? 1.0 : 0.0);
        level += remaining * a * u_levels[min(i, kMaxLevels - 1)];
        remaining *= 1.0 - a;
    }
    // Below every threshold: the last level. Missing levels repeat the last one given (the
    // uniform array is padded with it); levels beyond count(thresholds) + 1 are unused.
    return level + remaining * u_levels[clamp(u_levels_count - 1, 0, kMaxLevels - 1)];
}

void shade() {
    Surface s = surface();
    float ndotl = dot(s.n, s.l);
    float d = (u_driver == 0) ? 0.5 * ndotl + 0.5 : max(ndotl, 0.0);
    vec3 lit = mix(u_shade_color, vec3(1.0), band_level(d));
    vec3 c = s.albedo * (u_light_color * lit + u_ambient);
#if INKSHADE_SPECULAR
    {
        vec3 h = normalize(s.l + s.v);
        float spec = ndotl > 0.0 ? pow(max(dot(s.n, h), 0.0), u_shininess) : 0.0;
        c += u_specular_color * u_light_color * above(spec, u_specular_threshold);
    }
#endif
#if INKSHADE_RIM
    {
        float rim = ndotl > 0.0 ? (1.0 - dot(s.n, s.v)) * pow(ndotl, u_rim_power) : 0.0;
        c += u_rim_color * u_light_color * above(rim, u_rim_threshold);
    }
#endif
    o_color = encode_output(c);
}
