// `field-samples`: the face drawn at each pixel for the surface-field AOVs (docs/aov.md), drawn
// before the shading so that their interpolation on the CPU (render/surface_fields.hpp) runs on
// a worker beside the shading pass's GL work; the aov pass waits for it. The face is the one the
// aov pass's depth, normal and ids show: one sample a pixel, back faces only where no front
// face lies just behind (render/back_faces.hpp); its number is the mesh's own
// (GpuMesh::draw_face_numbers).
#include <future>

#include "gpu/gl_handle.hpp"
#include "gpu/gl_state.hpp"
#include "gpu/shader_program.hpp"
#include "inkshade/error.hpp"
#include "render/back_faces.hpp"
#include "render/frame.hpp"
#include "render/gl_rows.hpp"
#include "render/surface_fields.hpp"

namespace inkshade::render {

namespace {

struct FaceTargets {
    FaceTargets(int w, int h) : width(w), height(h) {
        face = gpu::GlTexture::create(GL_TEXTURE_2D);
        glTextureStorage2D(face.id(), 1, GL_R32UI, w, h);
        depth = gpu::GlRenderbuffer::create();
        glNamedRenderbufferStorage(depth.id(), GL_DEPTH_COMPONENT32F, w, h);
        fbo = gpu::GlFramebuffer::create();
        glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, face.id(), 0);
        glNamedFramebufferRenderbuffer(fbo.id(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth.id());
        if (glCheckNamedFramebufferStatus(fbo.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw RuntimeError("cannot create the surface-field targets (out of memory?)");
    }
    int width, height;
    gpu::GlTexture face;
    gpu::GlRenderbuffer depth;
    gpu::GlFramebuffer fbo;
};

class FieldSamplesPass final : public Pass {
public:
    void run(Frame& frame) override {
        if (!frame.field_vertices) return;
        const int width = frame.options.width, height = frame.options.height;
        if (!targets_ || targets_->width != width || targets_->height != height)
            targets_ = std::make_unique<FaceTargets>(width, height);
        draw(frame);
        std::vector<uint32_t> faces = read_faces();
        // The frame outlives the task: the aov pass waits for it, and Frame's destructor too.
        frame.field_interpolation = std::async(std::launch::async, [&frame, faces = std::move(faces)] {
            interpolate_fields(frame, frame.options.aovs.fields(), faces, *frame.aovs);
        });
    }

private:
    void draw(Frame& frame) {
        const gpu::ViewportScope viewport({0, 0, targets_->width, targets_->height});
        const gpu::BlendScope blend(std::nullopt);
        glBindFramebuffer(GL_FRAMEBUFFER, targets_->fbo.id());
        const gpu::DepthScope depth(GL_LESS);  // before the clear: it writes depth only with the mask on
        const GLuint no_face[4] = {0, 0, 0, 0};
        const GLfloat far = 1.0f;
        glClearBufferuiv(GL_COLOR, 0, no_face);
        glClearBufferfv(GL_DEPTH, 0, &far);
        if (!program_) program_ = std::make_unique<gpu::ShaderProgram>("aov/face.vert", "aov/face.frag");
        gpu::ShaderProgram& p = *program_;
        p.use();
        p.set("u_view_proj", frame.camera.projection(frame.aspect()) * frame.camera.view());
        draw_front_then_back(frame, p, [&] { frame.mesh->draw_face_numbers(frame.cpu_mesh); });
    }

    // The face drawn at each pixel + 1 (0: background), top row first.
    std::vector<uint32_t> read_faces() const {
        const size_t width = size_t(targets_->width), height = size_t(targets_->height);
        std::vector<uint32_t> faces(width * height);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glGetTextureImage(targets_->face.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT,
                          GLsizei(faces.size() * sizeof(uint32_t)), faces.data());
        flip_rows(faces, width);
        return faces;
    }

    std::unique_ptr<FaceTargets> targets_;
    std::unique_ptr<gpu::ShaderProgram> program_;
};

const PassRegistration field_samples_pass{{
    .name = "field-samples",
    .stage = Stage::FieldSamples,
    .plan = [](const Frame& frame) -> std::optional<PassIo> {
        if (!frame.aovs || frame.options.aovs.fields().empty()) return std::nullopt;
        return PassIo{.reads = {Resource::GpuMesh, Resource::ViewAttributes}, .writes = {Resource::FieldSamples}};
    },
    .create = create_pass<FieldSamplesPass>,
}};

}  // namespace

}  // namespace inkshade::render
