// `threejs-outline`: three.js's OutlineEffect, the outline three.js toon scenes draw: back faces
// pushed out by `thickness` in normalised device coordinates (shaders/lines/threejs_outline.vert),
// drawn after the model in the sRGB-encoded outline colour (docs/threejs.md).
#include "gpu/shader_program.hpp"
#include "inkshade/color.hpp"
#include "render/frame.hpp"
#include "render/lines/back_face_shell.hpp"

namespace inkshade::render {

namespace {

// OutlineEffect's names and defaults (defaultThickness 0.003, defaultColor [0, 0, 0],
// defaultAlpha 1). Its colour is an array read with Color.fromArray, i.e. linear, and the
// outline shader sRGB-encodes it like every three.js material.
const LineTypeRegistration threejs_outline_type{{
    .name = "threejs-outline",
    .summary = "three.js OutlineEffect: back faces pushed out by thickness in normalised device coordinates",
    .space = LineSpace::Image,
    .params =
        {
            float_param(
                "thickness", 0.003f, 0.0f, 1.0f,
                "offset in normalised device coordinates, about thickness*H/2 pixels (OutlineEffect default 0.003)"),
            color_param("color", glm::vec3(0.0f),
                        "outline colour, linear like OutlineEffect's [r, g, b] array (written sRGB-encoded)"),
            float_param("alpha", 1.0f, 0.0f, 1.0f,
                        "outline opacity; below 1 blended over the model (OutlineEffect default 1)"),
        },
}};

// Draws into the colour target (depth-tested against the shaded model).
class ThreejsOutlinePass final : public Pass {
public:
    // The fragment stage is the hull's: one flat colour.
    ThreejsOutlinePass() : program_("lines/threejs_outline.vert", "lines/hull.frag") {}

    void run(Frame& frame) override {
        const LineSettings& settings = *frame.line("threejs-outline");
        const float thickness = line_param(settings, "thickness").at(0);
        const float alpha = line_param(settings, "alpha").at(0);
        if (thickness <= 0.0f || alpha <= 0.0f) return;
        const ParamValue& c = line_param(settings, "color");
        const Camera& camera = frame.camera;
        gpu::ShaderProgram& p = program_;
        p.use();
        p.set("u_view_proj", camera.projection(frame.aspect()) * camera.view());
        p.set("u_thickness", thickness);
        p.set("u_color", glm::vec4(linear_to_srgb(glm::vec3(c.at(0), c.at(1), c.at(2))), alpha));
        // BackSide material, three.js's LessEqual depth test against the model drawn before; as
        // the hull: opaque without depth writes, alpha < 1 as three.js's transparent NormalBlending.
        draw_back_face_shell(frame, p, GL_LEQUAL, alpha < 1.0f);
    }

private:
    gpu::ShaderProgram program_;
};

// After `hull` (same stage, by name).
const PassRegistration threejs_outline_pass{{
    .name = "threejs-outline",
    .stage = Stage::MeshLines,
    .plan = [](const Frame& frame) -> std::optional<PassIo> {
        if (!frame.line("threejs-outline")) return std::nullopt;
        return PassIo{.reads = {Resource::GpuMesh, Resource::Color}, .writes = {Resource::Color}};
    },
    .create = create_pass<ThreejsOutlinePass>,
}};

}  // namespace

}  // namespace inkshade::render
