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
    void draw(const GBuffer& gbuffer, const Camera& camera, int width, int height, const LineSettings* edges,
              const LineSettings* suggestive);

private:
    std::map<std::string, std::unique_ptr<gpu::ShaderProgram>> programs_;  // by defines
    GLuint vao_ = 0;
};

}  // namespace inkshade::render
