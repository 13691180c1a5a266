// `hull`: the inverted hull silhouette (docs/lines-raster.md): a copy of the mesh pushed out
// along its welded normals, front faces culled, drawn in the line colour after the shaded
// model so only the rim around it (and around parts in front of others) stays visible.
#include "gpu/shader_program.hpp"
#include "render/frame.hpp"
#include "render/lines/back_face_shell.hpp"

namespace inkshade::render {

namespace {

std::vector<ParamSpec> hull_params() {
    std::vector<ParamSpec> p = stroke_params(glm::vec3(0.0f), 2.0f);
    p.push_back(choice_param("mode", {"screen", "world"}, 0,
                             "screen: width pixels whatever the distance (offset in clip space); world: "
                             "world-width units along the normal (the vertex offset of Qu, Chen & Zwicker 2022)"));
    p.push_back(float_param("world-width", 0.25f, 0.0f, 1000.0f,
                            "world mode: offset along the normal in world units (Qu et al. 2022 use 0.25)"));
    p.push_back(bool_param("borders", true,
                           "also outline open borders (a hole's rim, a sheet's edge), which have no back face to "
                           "push out: drawn as the object-space `border` type in this stroke (width in pixels)"));
    return p;
}

const LineTypeRegistration hull_type{{
    .name = "hull",
    .summary = "inverted hull silhouette: mesh pushed out along welded normals, front faces culled (the classic "
               "inverted hull)",
    .space = LineSpace::Image,
    .params = hull_params(),
}};

// Draws into the colour target, depth-tested against the shaded model, blended.
class HullPass final : public Pass {
public:
    HullPass() : program_("lines/hull.vert", "lines/hull.frag") {}

    void run(Frame& frame) override {
        const LineSettings& settings = *frame.line("hull");
        const Stroke stroke = stroke_of(settings);
        const bool world = line_param(settings, "mode").at(0) == 1.0f;
        if (stroke.opacity <= 0.0f || (world ? line_param(settings, "world-width").at(0) : stroke.width) <= 0.0f)
            return;
        const Camera& camera = frame.camera;
        gpu::ShaderProgram& p = program_;
        p.use();
        p.set("u_view_proj", camera.projection(frame.aspect()) * camera.view());
        p.set("u_world_mode", world ? 1 : 0);
        p.set("u_world_width", line_param(settings, "world-width").at(0));
        p.set("u_width_px", stroke.width);
        p.set("u_viewport_size", glm::vec2(frame.options.width, frame.options.height));
        p.set("u_color", glm::vec4(stroke.color, stroke.opacity));
        draw_back_face_shell(frame, p, GL_LESS, stroke.opacity < 1.0f);
    }

private:
    gpu::ShaderProgram program_;
};

const PassRegistration hull_pass{{
    .name = "hull",
    .stage = Stage::MeshLines,
    .plan = [](const Frame& frame) -> std::optional<PassIo> {
        if (!frame.line("hull")) return std::nullopt;
        return PassIo{.reads = {Resource::GpuMesh, Resource::Color}, .writes = {Resource::Color}};
    },
    .create = create_pass<HullPass>,
}};

}  // namespace

}  // namespace inkshade::render
