// `aov`: the AOV buffers of RenderOptions::aovs (inkshade/aov.hpp, docs/aov.md). Two draws of
// the mesh into targets of its own: one sample a pixel for depth, normal and ids (values of the
// surface at the pixel centre, never blended across an edge), then the coverage mask at the
// image's samples, averaged by the resolve as the image's edges are. The surface fields are
// interpolated beside the shading (render/field_samples_pass.cpp); this pass waits for them.
#include <algorithm>

#include "gpu/gl_handle.hpp"
#include "gpu/gl_state.hpp"
#include "gpu/shader_program.hpp"
#include "inkshade/error.hpp"
#include "render/back_faces.hpp"
#include "render/frame.hpp"
#include "render/gl_rows.hpp"

namespace inkshade::render {

namespace {

gpu::GlTexture make_texture(int width, int height, GLenum format) {
    gpu::GlTexture t = gpu::GlTexture::create(GL_TEXTURE_2D);
    glTextureStorage2D(t.id(), 1, format, width, height);
    return t;
}

void check_complete(const gpu::GlFramebuffer& fbo) {
    if (glCheckNamedFramebufferStatus(fbo.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw RuntimeError("cannot create the AOV targets (out of memory?)");
}

struct AovTargets {
    AovTargets(int w, int h, int s) : width(w), height(h), samples(s) {
        normal_depth = make_texture(w, h, GL_RGBA32F);
        object_id = make_texture(w, h, GL_R32UI);
        depth = gpu::GlRenderbuffer::create();
        glNamedRenderbufferStorage(depth.id(), GL_DEPTH_COMPONENT32F, w, h);
        surface = gpu::GlFramebuffer::create();
        glNamedFramebufferTexture(surface.id(), GL_COLOR_ATTACHMENT0, normal_depth.id(), 0);
        glNamedFramebufferTexture(surface.id(), GL_COLOR_ATTACHMENT1, object_id.id(), 0);
        glNamedFramebufferRenderbuffer(surface.id(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth.id());
        const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
        glNamedFramebufferDrawBuffers(surface.id(), 2, buffers);
        check_complete(surface);

        coverage_samples = gpu::GlRenderbuffer::create();
        if (s > 1)
            glNamedRenderbufferStorageMultisample(coverage_samples.id(), s, GL_R8, w, h);
        else
            glNamedRenderbufferStorage(coverage_samples.id(), GL_R8, w, h);
        coverage_msaa = gpu::GlFramebuffer::create();
        glNamedFramebufferRenderbuffer(coverage_msaa.id(), GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                       coverage_samples.id());
        check_complete(coverage_msaa);
        coverage = make_texture(w, h, GL_R8);
        coverage_resolved = gpu::GlFramebuffer::create();
        glNamedFramebufferTexture(coverage_resolved.id(), GL_COLOR_ATTACHMENT0, coverage.id(), 0);
        check_complete(coverage_resolved);
    }
    int width, height, samples;
    gpu::GlTexture normal_depth, object_id, coverage;
    gpu::GlRenderbuffer depth, coverage_samples;
    gpu::GlFramebuffer surface, coverage_msaa, coverage_resolved;
};

class AovPass final : public Pass {
public:
    void run(Frame& frame) override {
        const AovSet want = frame.options.aovs.gpu();
        AovImages& out = *frame.aovs;
        const int width = frame.options.width, height = frame.options.height;
        GLint max_samples = 1;
        glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
        const int samples = std::clamp(frame.options.samples, 1, std::max(1, int(max_samples)));
        if (!targets_ || targets_->width != width || targets_->height != height || targets_->samples != samples)
            targets_ = std::make_unique<AovTargets>(width, height, samples);
        out.width = width;
        out.height = height;

        const gpu::ViewportScope viewport({0, 0, width, height});
        const gpu::BlendScope blend(std::nullopt);
        const Camera& camera = frame.camera;
        const glm::mat4 view_proj = camera.projection(frame.aspect()) * camera.view();
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        if (want.contains(Aov::Depth) || want.contains(Aov::Normal) || want.contains(Aov::Id) ||
            want.contains(Aov::Material)) {
            draw_surface(frame, view_proj);
            read_surface(frame, want, out);
        }
        if (want.contains(Aov::Mask)) draw_and_read_mask(frame, view_proj, out);
        if (frame.field_interpolation.valid()) frame.field_interpolation.get();  // rethrows its error
    }

private:
    // Depth, camera-space normal and object id of the surface the shading pass shows, at one
    // sample a pixel: back faces only where no front face is just behind.
    void draw_surface(Frame& frame, const glm::mat4& view_proj) {
        glBindFramebuffer(GL_FRAMEBUFFER, targets_->surface.id());
        const gpu::DepthScope depth(GL_LESS);  // before the clear: it writes depth only with the mask on
        const GLfloat zero[4] = {0, 0, 0, 0};
        const GLuint no_id[4] = {0, 0, 0, 0};
        const GLfloat far = 1.0f;
        glClearBufferfv(GL_COLOR, 0, zero);
        glClearBufferuiv(GL_COLOR, 1, no_id);
        glClearBufferuiv(GL_COLOR, 2, no_id);
        glClearBufferfv(GL_DEPTH, 0, &far);
        if (!surface_) surface_ = std::make_unique<gpu::ShaderProgram>("lines/gbuffer.vert", "aov/aov.frag");
        gpu::ShaderProgram& p = *surface_;
        const Camera& camera = frame.camera;
        p.use();
        p.set("u_view_proj", view_proj);
        p.set("u_view", camera.view());
        p.set("u_eye", camera.eye);
        p.set("u_view_dir", glm::normalize(camera.target - camera.eye));
        p.set("u_orthographic", camera.orthographic ? 1 : 0);
        draw_front_then_back(frame, p, [&] { frame.mesh->draw(); });
    }

    // Only the targets asked for are read: the surface fields need the face target alone.
    void read_surface(const Frame& frame, AovSet want, AovImages& out) const {
        if (want.contains(Aov::Depth) || want.contains(Aov::Normal)) read_normal_depth(want, out);
        if (want.contains(Aov::Id) || want.contains(Aov::Material)) read_ids(frame, want, out);
    }

    void read_normal_depth(AovSet want, AovImages& out) const {
        const size_t width = size_t(out.width), pixels = width * size_t(out.height);
        std::vector<float> normal_depth(pixels * 4);
        glGetTextureImage(targets_->normal_depth.id(), 0, GL_RGBA, GL_FLOAT,
                          GLsizei(normal_depth.size() * sizeof(float)), normal_depth.data());
        flip_rows(normal_depth, width * 4);
        if (want.contains(Aov::Depth)) {
            out.depth.resize(pixels);
            for (size_t i = 0; i < pixels; ++i) out.depth[i] = normal_depth[4 * i + 3];
        }
        if (want.contains(Aov::Normal)) {
            out.normal.resize(pixels * 3);
            for (size_t i = 0; i < pixels; ++i)
                for (int c = 0; c < 3; ++c) out.normal[3 * i + size_t(c)] = normal_depth[4 * i + size_t(c)];
        }
    }

    void read_ids(const Frame& frame, AovSet want, AovImages& out) const {
        const size_t width = size_t(out.width), pixels = width * size_t(out.height);
        std::vector<uint32_t> ids(pixels);
        glGetTextureImage(targets_->object_id.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT,
                          GLsizei(ids.size() * sizeof(uint32_t)), ids.data());
        flip_rows(ids, width);
        // Object ids (part x material) to the part and the material.
        const std::vector<glm::uvec2>& parts = frame.mesh->object_parts();
        auto part = [&](uint32_t id, int k) { return id == 0 || id > parts.size() ? 0u : parts[id - 1][k]; };
        if (want.contains(Aov::Id)) {
            out.id.resize(pixels);
            std::transform(ids.begin(), ids.end(), out.id.begin(), [&](uint32_t id) { return part(id, 0); });
        }
        if (want.contains(Aov::Material)) {
            out.material.resize(pixels);
            std::transform(ids.begin(), ids.end(), out.material.begin(), [&](uint32_t id) { return part(id, 1); });
        }
    }

    // The coverage mask at the image's samples, resolved: every face covers, whichever way it faces.
    void draw_and_read_mask(Frame& frame, const glm::mat4& view_proj, AovImages& out) {
        const int width = out.width, height = out.height;
        glBindFramebuffer(GL_FRAMEBUFFER, targets_->coverage_msaa.id());
        const GLfloat zero[4] = {0, 0, 0, 0};
        glClearBufferfv(GL_COLOR, 0, zero);
        const gpu::DepthScope depth(std::nullopt, false);
        const gpu::CullScope cull(std::nullopt);
        if (!coverage_) coverage_ = std::make_unique<gpu::ShaderProgram>("lines/gbuffer.vert", "aov/coverage.frag");
        coverage_->use();
        coverage_->set("u_view_proj", view_proj);
        coverage_->set("u_back_face_push", 0.0f);
        frame.mesh->draw();
        glBlitNamedFramebuffer(targets_->coverage_msaa.id(), targets_->coverage_resolved.id(), 0, 0, width, height, 0,
                               0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        out.mask.resize(size_t(width) * size_t(height));
        glGetTextureImage(targets_->coverage.id(), 0, GL_RED, GL_UNSIGNED_BYTE, GLsizei(out.mask.size()),
                          out.mask.data());
        flip_rows(out.mask, size_t(width));
    }

    std::unique_ptr<AovTargets> targets_;
    std::unique_ptr<gpu::ShaderProgram> surface_, coverage_;
};

// Runs when the frame asks for an AOV the renderer draws or a surface field (whose vertex
// values the fields pass computes, render/field_vertices.cpp, and field-samples interpolates).
const PassRegistration aov_pass{{
    .name = "aov",
    .stage = Stage::Aov,
    .plan = [](const Frame& frame) -> std::optional<PassIo> {
        if (!frame.aovs || frame.options.aovs.gpu().empty()) return std::nullopt;
        if (!frame.options.aovs.fields().empty())
            return PassIo{.reads = {Resource::GpuMesh, Resource::FieldSamples}, .writes = {Resource::Aov}};
        return PassIo{.reads = {Resource::GpuMesh}, .writes = {Resource::Aov}};
    },
    .create = create_pass<AovPass>,
}};

}  // namespace

}  // namespace inkshade::render
