// `gbuffer`: the mesh again into the G-buffer (render/gbuffer.hpp), for the passes that read it.
#include "gpu/gl_state.hpp"
#include "gpu/shader_program.hpp"
#include "render/back_faces.hpp"
#include "render/frame.hpp"

namespace inkshade::render {

namespace {

class GBufferPass final : public Pass {
public:
    void run(Frame& frame) override {
        const int width = frame.options.width, height = frame.options.height;
        std::unique_ptr<GBuffer>& gbuffer = frame.targets.gbuffer;
        if (!gbuffer || gbuffer->width() != width || gbuffer->height() != height)
            gbuffer = std::make_unique<GBuffer>(width, height);
        // The face-normal target only when a pass reads it (`edges` looking for creases).
        const bool face_normals = frame.reads.contains(Resource::GBufferFaceNormals);
        auto& program = programs_[face_normals ? 1 : 0];
        if (!program)
            program = std::make_unique<gpu::ShaderProgram>(
                "lines/gbuffer.vert", "lines/gbuffer.frag",
                std::string("#define INKSHADE_GBUFFER_FACE_NORMALS ") + (face_normals ? "1" : "0") + "\n");
        const gpu::ViewportScope viewport({0, 0, width, height});
        gbuffer->bind_for_drawing(face_normals);
        const gpu::DepthScope depth(GL_LESS);
        const gpu::BlendScope blend(std::nullopt);

        const Camera& camera = frame.camera;
        gpu::ShaderProgram& p = *program;
        p.use();
        p.set("u_view_proj", camera.projection(float(width) / float(height)) * camera.view());
        p.set("u_view", camera.view());
        p.set("u_eye", camera.eye);
        p.set("u_view_dir", glm::normalize(camera.target - camera.eye));
        p.set("u_orthographic", camera.orthographic ? 1 : 0);
        // The surface the shading pass shows: back faces only where no front face is just behind.
        draw_front_then_back(frame, p, [&] { frame.mesh->draw(); });
    }

private:
    std::unique_ptr<gpu::ShaderProgram> programs_[2];  // without / with face normals
};

// Runs when a pass reads the G-buffer.
const PassRegistration gbuffer_pass{{
    .name = "gbuffer",
    .stage = Stage::GBuffer,
    .plan = [](const Frame&) -> std::optional<PassIo> {
        return PassIo{.reads = {Resource::GpuMesh}, .writes = {Resource::GBuffer, Resource::GBufferFaceNormals}};
    },
    .create = create_pass<GBufferPass>,
}};

}  // namespace

}  // namespace inkshade::render
