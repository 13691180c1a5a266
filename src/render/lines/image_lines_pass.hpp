// The full-screen pass drawing the G-buffer line types (`edges`, `suggestive-image`) over the
// image in one go (shaders/lines/image_lines.frag): one pass whatever the number of types,
// since each full-screen pass costs ~15-19 ms at 1024² on llvmpipe.
#pragma once
#include <map>
#include <memory>
#include <string>

#include "gpu/shader_program.hpp"
#include "inkshade/camera.hpp"
#include "inkshade/lines.hpp"
#include "inkshade/mesh.hpp"
#include "render/gbuffer.hpp"

namespace inkshade::render {

class ImageLinesPass {
public:
    ImageLinesPass();
    ~ImageLinesPass();
    // Whether `edges` needs the face-normal target (crease detection on).
    static bool needs_face_normals(const LineSettings* edges);
    // Draws into the bound framebuffer (no depth test: the G-buffer holds the visible surface
    // only), blended over. Either settings pointer may be null. The G-buffer is the image's size.
    // Only pixels that can draw a line are shaded: those of `bounds` (the mesh's world box)
    // projected, plus the edge detector's reach (image_lines_region).
    void draw(const GBuffer& gbuffer, const Camera& camera, const BoundingBox& bounds, int width, int height,
              const LineSettings* edges, const LineSettings* suggestive);

    // GL window rectangle (x, y, width, height; origin bottom left) that holds every pixel the
    // projection of `bounds` covers, grown by `margin` pixels and cut to the image; the whole
    // image when a corner of the box is not in front of the eye. Outside it, every G-buffer tap
    // of a pixel is background, where neither line type draws.
    static glm::ivec4 image_lines_region(const BoundingBox& bounds, const Camera& camera, int width, int height,
                                         int margin);

private:
    std::map<std::string, std::unique_ptr<gpu::ShaderProgram>> programs_;  // by defines
    GLuint vao_ = 0;
};

}  // namespace inkshade::render
