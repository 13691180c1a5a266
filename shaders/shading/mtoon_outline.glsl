// mtoon's outline, as three-vrm 3.5.5 draws it (mtoon.vert under OUTLINE): the mesh again, back
// faces only, each vertex moved out along its unit normal n by an offset o:
//   world-coordinates:  o = width * tex * n                               (width in world units)
//   screen-coordinates: o = width * tex * n * depth / P[1][1]             (OUTLINE_WIDTH_SCREEN)
//   clip = view_proj * (p + o, 1), then clip.z += 1e-6 * clip.w            ("anti-artifact magic")
// depth is the unmoved point's view depth (three-vrm's vViewPosition.z) and P[1][1] the
// projection's y scale (1 / tan(fov / 2), or 2 / the orthographic height). A perspective camera
// so moves a silhouette width * H / 2 pixels at every depth (H the image height); an orthographic
// one moves it width * depth * H / 2 pixels, wider farther from the camera.
// tex is outlineWidthMultiplyTexture's green channel (1 without one). The fragment stage shades
// at the unmoved point (three-vrm keeps vViewPosition and vNormal of the unmoved vertex).
uniform int u_outline_width_mode;  // 1 world, 2 screen (0: not drawn)
uniform float u_outline_width;
uniform mat4 u_projection;
uniform mat4 u_view;
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
    float w = u_outline_width * tex;
    if (u_outline_width_mode == 2) w *= -(u_view * vec4(world, 1.0)).z / u_projection[1][1];
    clip = u_view_proj * vec4(world + w * normalize(normal), 1.0);
    clip.z += 1e-6 * clip.w;
    return clip;
}
