// Fragment-stage inputs shared by the shading models, and the per-pixel surface frame. A model
// defines `void shade()`, writing o_color; main is common/shading_main.glsl's (included at the
// end), which runs shade() and then the surface line types.
#include "common/lighting.glsl"

in vec3 v_world_pos;
in vec3 v_world_normal;
in vec3 v_color;
in vec3 v_object_pos;
#if defined(INKSHADE_BASE_TEXTURE) || defined(INKSHADE_MTOON_TEXTURES)
in vec2 v_uv;
// Where the textures are read: the uvs as texture coordinates (s, t), t = 0 at the image's top
// row, as three.js reads a glTF texture (flipY false). A model that moves them (mtoon's UV
// animation) defines INKSHADE_TEXTURE_UV before including this file, and texture_uv() itself.
#ifdef INKSHADE_TEXTURE_UV
vec2 texture_uv();
#else
vec2 texture_uv() { return vec2(v_uv.x, 1.0 - v_uv.y); }
#endif
#endif
#ifdef INKSHADE_BASE_TEXTURE
// Base-colour texture, read in the frame's colour convention (bound by the shading pass:
// the bytes as stored, or decoded from sRGB to linear light) at texture_uv(): rows stored top
// first while uvs have v = 0 at the bottom (inkshade::Texture), hence t = 1 - v.
uniform sampler2D u_base_texture;
// Per draw, the material's KHR_texture_transform of its base-colour texture (Material::uv_transforms,
// three.js's mapUvTransform), applied after texture_uv(); identity unless the draw sets one.
uniform mat3 u_base_uv_transform = mat3(1.0);
vec2 base_uv() { return (u_base_uv_transform * vec3(texture_uv(), 1.0)).xy; }
#endif

layout(location = 0) out vec4 o_color;

// Per draw, a glTF material's sides: 1 lights back faces with the normal negated, as three.js's
// DoubleSide does (normal *= faceDirection); 0 keeps Inkshade's seen_normal.
uniform int u_double_sided;

#ifdef INKSHADE_MATERIAL_ALPHA
// Per draw, a glTF material's alpha mode (0 OPAQUE, 1 MASK, 2 BLEND; Material::alpha_mode),
// baseColorFactor.a and alphaCutoff; common/shading_main.glsl applies them.
uniform int u_alpha_mode;
uniform float u_base_alpha;
uniform float u_alpha_cutoff;

// three.js's diffuseColor.a: opacity (baseColorFactor.a) x the base-colour texture's alpha.
float surface_alpha() {
    float a = u_base_alpha;
#ifdef INKSHADE_BASE_TEXTURE
    a *= texture(u_base_texture, base_uv()).a;
#endif
    return a;
}
#endif

uniform vec3 u_bbox_min;      // model-space bounding box, for patterns normalised to the model
uniform vec3 u_bbox_max;
uniform vec2 u_viewport_size; // pixels

// Model-space position scaled so the bounding box's longest side is 1 (origin at its min):
// patterns keep their look on any model size and stay attached to the surface.
vec3 normalized_object_pos() {
    vec3 extent = max(u_bbox_max - u_bbox_min, vec3(1e-20));
    return (v_object_pos - u_bbox_min) / max(extent.x, max(extent.y, extent.z));
}

struct Surface {
    vec3 p;       // world position
    vec3 n;       // unit normal, turned towards the viewer on back faces (seen_normal) or negated (u_double_sided)
    vec3 v;       // unit vector towards the viewer
    vec3 l;       // unit vector towards the light
    vec3 albedo;  // C = base colour x vertex/material colour x texture
};

Surface surface() {
    Surface s;
    s.p = v_world_pos;
    s.v = to_viewer(s.p);
    // Back faces of open meshes are lit as seen (no inside-out rim glow or lighting).
    vec3 n = normalize(v_world_normal);
    s.n = (u_double_sided == 1) ? (gl_FrontFacing ? n : -n) : seen_normal(n, s.v, gl_FrontFacing);
    s.l = to_light(s.p);
    s.albedo = u_base_color * v_color;
#ifdef INKSHADE_BASE_TEXTURE
    s.albedo *= texture(u_base_texture, base_uv()).rgb;
#endif
    return s;
}

#include "common/shading_main.glsl"
