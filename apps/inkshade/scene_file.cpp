#include "scene_file.hpp"

#include "inkshade/threejs_scene.hpp"

namespace inkshade::cli {

namespace {

// Option text that parse_vec3 reads back to exactly these floats.
std::string vec3_text(const glm::vec3& v) {
    return format_number(v.x) + "," + format_number(v.y) + "," + format_number(v.z);
}

}  // namespace

void apply_scene_file(const std::string& path, const CLI::App& cmd, SceneOptions& o) {
    const ThreejsScene scene = load_threejs_scene(path);
    o.scene_style = threejs_scene_style(scene);
    auto given = [&](const char* option) { return cmd.count(option) > 0; };
    if (!given("MODEL")) o.model = scene.mesh;
    if (scene.size && !given("--size")) o.size = std::to_string(scene.size->x) + "x" + std::to_string(scene.size->y);
    if (!given("--samples")) o.samples = scene.antialias ? 4 : 1;  // WebGLRenderer's antialias

    if (const auto& c = scene.camera) {
        if (!given("--fov")) o.fov = c->fov_degrees;
        if (!given("--ortho")) o.ortho = c->orthographic;
        if (c->orthographic && !given("--ortho-height")) o.ortho_height = c->ortho_height;
        if (!given("--up")) o.up = vec3_text(c->up);
        // An orbit given on the command line (--azimuth, --elevation, --distance) replaces the
        // scene's placement; so does an explicit eye.
        if (!given("--azimuth") && !given("--elevation") && !given("--distance")) {
            if (!given("--eye")) o.eye = vec3_text(c->position);
            if (!given("--target")) o.target = vec3_text(c->target);
            if (!given("--near")) o.near = c->near_plane;
            if (!given("--far")) o.far = c->far_plane;
        }
    }
    if (scene.light_position) {
        if (!given("--light-type")) o.light_type = scene.light_type == LightType::Point ? "point" : "directional";
        if (!given("--light-pos")) o.light_pos = vec3_text(*scene.light_position);
        if (!given("--light-target")) o.light_target = vec3_text(*scene.light_target);
    }
}

}  // namespace inkshade::cli
