// Fragment-stage inputs shared by the shading models, and the per-pixel surface frame.
#include "common/lighting.glsl"

in vec3 v_world_pos;
in vec3 v_world_normal;
in vec3 v_color;

layout(location = 0) out vec4 o_color;

struct Surface {
    vec3 p;       // world position
    vec3 n;       // unit normal, flipped towards the viewer on back faces (two-sided)
    vec3 v;       // unit vector towards the viewer
    vec3 l;       // unit vector towards the light
    vec3 albedo;  // C
};

Surface surface() {
    Surface s;
    s.p = v_world_pos;
    s.n = normalize(v_world_normal);
    // Back faces of open meshes are lit as seen (avoids the seeds' inverted-inside artefact).
    if (!gl_FrontFacing) s.n = -s.n;
    s.v = to_viewer(s.p);
    s.l = to_light(s.p);
    s.albedo = u_base_color * v_color;
    return s;
}
