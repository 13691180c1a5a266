#include "render/lines/threejs_outline.hpp"

#include "inkshade/color.hpp"

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
            float_param("thickness", 0.003f, 0.0f, 1.0f,
                        "offset in normalised device coordinates, about thickness*H/2 pixels (OutlineEffect default 0.003)"),
            color_param("color", glm::vec3(0.0f),
                        "outline colour, linear like OutlineEffect's [r, g, b] array (written sRGB-encoded)"),
            float_param("alpha", 1.0f, 0.0f, 1.0f, "outline opacity; below 1 blended over the model (OutlineEffect default 1)"),
        },
}};

}  // namespace

// The fragment stage is the hull's: one flat colour.
ThreejsOutlinePass::ThreejsOutlinePass()
    : program_(std::make_unique<gpu::ShaderProgram>("lines/threejs_outline.vert", "lines/hull.frag")) {}

void ThreejsOutlinePass::draw(const GpuMesh& mesh, const Camera& camera, int width, int height,
                              const LineSettings& settings) {
    const float thickness = line_param(settings, "thickness").at(0);
    const float alpha = line_param(settings, "alpha").at(0);
    if (thickness <= 0.0f || alpha <= 0.0f) return;
    const ParamValue& c = line_param(settings, "color");
    gpu::ShaderProgram& p = *program_;
    p.use();
    p.set("u_view_proj", camera.projection(float(width) / float(height)) * camera.view());
    p.set("u_thickness", thickness);
    p.set("u_color", glm::vec4(linear_to_srgb(glm::vec3(c.at(0), c.at(1), c.at(2))), alpha));

    // BackSide material, three.js's LessEqual depth test against the model drawn before.
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    // As the hull: opaque without blending or depth writes (a line, not a surface hiding later
    // lines); alpha < 1 is three.js's transparent NormalBlending ("over"; the framebuffer holds
    // premultiplied colour), with depth writes so overlapping layers blend once.
    const bool blend = alpha < 1.0f;
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

}  // namespace inkshade::render
