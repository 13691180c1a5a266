// mtoon's outline, as three-vrm 3.x draws it (mtoon.vert under OUTLINE): the mesh again, back
// faces only, each vertex moved out along its unit normal n:
//   world-coordinates:  clip = view_proj * (p + width * tex * n, 1)      (width in world units)
//   screen-coordinates: clip.xy += 2 * width * tex * m,  m = normalize((view_proj * (n, 0)).xy)
//                       with m.x scaled by P[0][0] / P[1][1] (1 / aspect): a move of
//                       width * H / clip.w pixels, so width is a fraction of the image height at
//                       clip w = 1 (orthographic: everywhere) and thinner farther away
//   then clip.z += 1e-6 * clip.w                                          ("anti-artifact magic")
// tex is outlineWidthMultiplyTexture's green channel (1 without one). The fragment stage shades
// at the unmoved point (three-vrm keeps vViewPosition and vNormal of the unmoved vertex).
uniform int u_outline_width_mode;  // 1 world, 2 screen (0: not drawn)
uniform float u_outline_width;
uniform mat4 u_projection;
#ifdef INKSHADE_MTOON_TEXTURES
uniform sampler2D u_outline_width_multiply_texture;  // data: green channel as stored
uniform mat3 u_outline_width_multiply_texture_uv_transform = mat3(1.0);  // KHR_texture_transform
float outline_width_multiply() {
    vec2 uv = (u_outline_width_multiply_texture_uv_transform * vec3(a_uv.x, 1.0 - a_uv.y, 1.0)).xy;
    return textureLod(u_outline_width_multiply_texture, uv, 0.0).g;
}
#else
float outline_width_multiply() { return 1.0; }
#endif

vec4 mtoon_outline_position(vec4 clip, vec3 world, vec3 normal, float tex) {
    vec3 n = normalize(normal);
    float w = u_outline_width * tex;
    if (u_outline_width_mode == 1) {
        clip = u_view_proj * vec4(world + w * n, 1.0);
    } else {
        vec2 m = (u_view_proj * vec4(n, 0.0)).xy;
        m = length(m) > 0.0 ? normalize(m) : vec2(0.0);
        m.x *= u_projection[0][0] / u_projection[1][1];
        clip.xy += 2.0 * w * m;
    }
    clip.z += 1e-6 * clip.w;
    return clip;
}
