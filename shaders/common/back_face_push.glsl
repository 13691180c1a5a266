// Back faces lose depth ties to front faces (src/render/back_faces.hpp): the draw of back faces
// sets u_back_face_push, a constant clip-space z offset that moves each vertex a tolerance
// farther along its view ray (image position unchanged); 0 in the draw of front faces.
uniform float u_back_face_push;

vec4 pushed_back(vec4 clip) { return vec4(clip.xy, clip.z + u_back_face_push, clip.w); }
