// three.js r187 conventions shared by the threejs-* models (docs/threejs.md): physically based
// light units (a Lambertian surface reflects C/pi of its irradiance), E = light colour x
// intensity with three.js's distance falloff for a point light, and the sRGB encode of its
// colorspace_fragment. Include after common/surface.glsl (u_light_* and u_ambient).
uniform float u_light_intensity;    // three.js DirectionalLight/PointLight.intensity
uniform float u_ambient_intensity;  // AmbientLight.intensity
uniform float u_light_decay;        // PointLight.decay
uniform float u_light_distance;     // PointLight.distance (0: no cut-off)

const float kThreejsReciprocalPi = 0.3183098861837907;

// three.js getDistanceAttenuation: 1 / max(d^decay, 0.01), windowed to zero at `distance`.
float threejs_distance_attenuation(float d) {
    float falloff = 1.0 / max(pow(d, u_light_decay), 0.01);
    if (u_light_distance > 0.0) {
        float x = d / u_light_distance;
        float window = clamp(1.0 - x * x * x * x, 0.0, 1.0);
        falloff *= window * window;
    }
    return falloff;
}

// The direct light's colour at p as three.js's directLight.color: E, attenuated for a point or
// spot light, and a spot light's cone.
vec3 threejs_direct_light(vec3 p) {
    vec3 e = u_light_color * u_light_intensity;
    return u_light_type != 0 ? e * threejs_distance_attenuation(length(u_light_pos - p)) * spot_attenuation(p) : e;
}

vec3 threejs_ambient() { return u_ambient * u_ambient_intensity; }

// three.js sRGBTransferOETF: pow(c, 0.41666) where the standard has 1/2.4 (within 0.002/255).
// Values above 1 clamp, as the 8-bit canvas does after three.js's unclamped encode.
vec4 threejs_output(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    vec3 hi = pow(c, vec3(0.41666)) * 1.055 - vec3(0.055);
    return vec4(mix(hi, c * 12.92, lessThanEqual(c, vec3(0.0031308))), 1.0);
}
