// `image-lines`: the full-screen pass drawing the G-buffer line types (`edges`,
// `suggestive-image`) over the image in one go (shaders/lines/image_lines.frag): one pass
// whatever the number of types, since each full-screen pass costs ~15-19 ms at 1024² on llvmpipe.
#pragma once
#include <map>
#include <memory>
#include <string>

#include "gpu/gl_handle.hpp"
#include "gpu/shader_program.hpp"
#include "inkshade/camera.hpp"
#include "inkshade/lines.hpp"
#include "inkshade/mesh.hpp"
#include "render/gbuffer.hpp"
#include "render/pass.hpp"

namespace inkshade::render {

class ImageLinesPass final : public Pass {
public:
    ImageLinesPass();
    // Draws into the bound target (no depth test: the G-buffer holds the visible surface only),
    // blended over. Only pixels that can draw a line are shaded: those of the mesh's bounding
    // box projected, plus the edge detector's reach (image_lines_region).
    void run(Frame& frame) override;

    // GL window rectangle (x, y, width, height; origin bottom left) that holds every pixel the
    // projection of `bounds` covers, grown by `margin` pixels and cut to the image; the whole
    // image when a corner of the box is not in front of the eye. Outside it, every G-buffer tap
    // of a pixel is background, where neither line type draws.
    static glm::ivec4 image_lines_region(const BoundingBox& bounds, const Camera& camera, int width, int height,
                                         int margin);

private:
    std::map<std::string, std::unique_ptr<gpu::ShaderProgram>> programs_;  // by defines
    gpu::GlVertexArray vao_;  // empty: the full-screen triangle comes from gl_VertexID
};

}  // namespace inkshade::render
