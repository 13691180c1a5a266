// A three.js scene file as a request: its mesh, material, lights, camera, size and antialias,
// where the caller did not set the option itself (docs/threejs.md).
#include "inkshade/scene.hpp"
#include "inkshade/threejs_scene.hpp"

namespace inkshade {

void apply_threejs_scene(const std::string& path, SceneRequest& r,
                         const std::function<bool(const std::string&)>& given) {
    const ThreejsScene scene = load_threejs_scene(path);
    r.style_data = threejs_scene_style(scene);
    if (!given("model")) r.model = scene.mesh;
    if (scene.size && !given("size")) r.size = *scene.size;
    if (!given("samples")) r.samples = scene.antialias ? 4 : 1;  // WebGLRenderer's antialias

    if (const auto& c = scene.camera) {
        CameraOptions& o = r.camera;
        if (!given("fov")) o.fov_degrees = c->fov_degrees;
        if (!given("ortho")) o.orthographic = c->orthographic;
        if (c->orthographic && !given("ortho-height")) o.ortho_height = c->ortho_height;
        if (!given("up")) o.up = c->up;
        // An orbit given by the caller (azimuth, elevation, distance) replaces the scene's
        // placement; so does an explicit eye.
        if (!given("azimuth") && !given("elevation") && !given("distance")) {
            if (!given("eye")) o.eye = c->position;
            if (!given("target")) o.target = c->target;
            if (!given("near")) o.near_plane = c->near_plane;
            if (!given("far")) o.far_plane = c->far_plane;
        }
    }
    if (scene.light_position) {
        if (!given("light-type")) r.light_type = scene.light_type;
        if (!given("light-pos")) r.light_position = *scene.light_position;
        if (!given("light-target")) r.light_target = *scene.light_target;
    }
}

}  // namespace inkshade
