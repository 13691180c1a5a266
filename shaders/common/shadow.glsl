// Shadow-map lookup with percentage-closer filtering (Reeves et al. 1987): the mean of 2x2
// taps, `softness` texels apart, each itself bilinear through the hardware depth comparison
// (sampler2DShadow, GL_LINEAR), so 16 depth comparisons cover about 3x3 texels. Four taps
// instead of nine cut mtoon's frame time by 15% on llvmpipe (docs/benchmarks.md).
// Acne is avoided with a normal offset (the lookup point moves texel_world * normal-offset
// along n, Holbein 2011) plus a slope-scaled depth bias of the depth pass (glPolygonOffset).
// INKSHADE_SHADOWS is the model's compile-time `shadows` parameter: a uniform branch would
// still cost the taps on llvmpipe, which runs masked-off code.
#if !defined(INKSHADE_SHADOWS) || !INKSHADE_SHADOWS
float shadow_visibility(vec3 p, vec3 n, vec3 l, float softness_texels) { return 1.0; }
#else
uniform sampler2DShadow u_shadow_map;
uniform mat4 u_light_view_proj;
uniform float u_shadow_texel_world;  // world size of one shadow-map texel

// 1 = fully lit, 0 = fully in shadow.
float shadow_visibility(vec3 p, vec3 n, vec3 l, float softness_texels) {
    // Offset along the normal, more where the light grazes the surface.
    float grazing = 1.0 - clamp(dot(n, l), 0.0, 1.0);
    vec3 q = p + n * u_shadow_texel_world * (1.0 + 2.0 * grazing);
    vec4 clip = u_light_view_proj * vec4(q, 1.0);
    vec3 uvz = clip.xyz / clip.w * 0.5 + 0.5;
    if (any(lessThan(uvz, vec3(0.0))) || any(greaterThan(uvz, vec3(1.0)))) return 1.0;
    vec2 texel = 1.0 / vec2(textureSize(u_shadow_map, 0));
    float sum = 0.0;
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x)
            sum += texture(u_shadow_map, vec3(uvz.xy + (vec2(x, y) - 0.5) * texel * softness_texels, uvz.z));
    return 0.25 * sum;
}
#endif
