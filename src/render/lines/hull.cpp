#include "render/lines/hull.hpp"

namespace inkshade::render {

namespace {

std::vector<ParamSpec> hull_params() {
    std::vector<ParamSpec> p = stroke_params(glm::vec3(0.0f), 2.0f);
    p.push_back(choice_param("mode", {"screen", "world"}, 0,
                             "screen: width pixels whatever the distance (offset in clip space); world: "
                             "world-width units along the normal (seed 000's vertex offset)"));
    p.push_back(float_param("world-width", 0.25f, 0.0f, 1000.0f,
                            "world mode: offset along the normal in world units (seed 000 uses 0.25)"));
    return p;
}

const LineTypeRegistration hull_type{{
    .name = "hull",
    .summary = "inverted hull silhouette: mesh pushed out along welded normals, front faces culled (seeds 000, 001)",
    .space = LineSpace::Image,
    .params = hull_params(),
}};

}  // namespace

void draw_back_face_shell(const GpuMesh& mesh, GLenum depth_func, bool blend) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(depth_func);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    if (blend) {
        glEnable(GL_BLEND);
        glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    } else {
        glDepthMask(GL_FALSE);
    }
    mesh.draw();
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glCullFace(GL_BACK);
    glDisable(GL_CULL_FACE);
}

HullPass::HullPass() : program_(std::make_unique<gpu::ShaderProgram>("lines/hull.vert", "lines/hull.frag")) {}

void HullPass::draw(const GpuMesh& mesh, const Camera& camera, int width, int height, const LineSettings& settings) {
    const Stroke stroke = stroke_of(settings);
    const bool world = line_param(settings, "mode").at(0) == 1.0f;
    if (stroke.opacity <= 0.0f || (world ? line_param(settings, "world-width").at(0) : stroke.width) <= 0.0f) return;
    gpu::ShaderProgram& p = *program_;
    p.use();
    p.set("u_view_proj", camera.projection(float(width) / float(height)) * camera.view());
    p.set("u_world_mode", world ? 1 : 0);
    p.set("u_world_width", line_param(settings, "world-width").at(0));
    p.set("u_width_px", stroke.width);
    p.set("u_viewport_size", glm::vec2(width, height));
    p.set("u_color", glm::vec4(stroke.color, stroke.opacity));

    draw_back_face_shell(mesh, GL_LESS, stroke.opacity < 1.0f);
}

}  // namespace inkshade::render
