#include "inkshade/renderer.hpp"

#include <map>

#include "geometry/normals.hpp"
#include "geometry/orientation.hpp"
#include "geometry/visibility.hpp"
#include "gpu/gl_context.hpp"
#include "inkshade/error.hpp"
#include "inkshade/line_drawing.hpp"
#include "render/edge_length.hpp"
#include "render/frame.hpp"
#include "render/model_strokes.hpp"
#include "render/gpu_mesh.hpp"
#include "render/pass_plan.hpp"
#include "render/pass_timer.hpp"
#include "render/stroke_pass.hpp"

namespace inkshade {

struct Renderer::Impl {
    // First, so it is destroyed last: every GL object below goes before the context owning it.
    std::unique_ptr<gpu::GlContext> context;
    // The mesh of set_mesh (copied or moved in, since the caller's need not outlive set_mesh),
    // shared with the line extractor; after the GL upload only positions, triangles and normals
    // are kept. `mesh` (the GL buffers) is null until the upload.
    std::shared_ptr<Mesh> cpu_mesh;
    std::unique_ptr<render::GpuMesh> mesh;
    BoundingBox bounds;
    bool closed = false;       // closed and outward: back faces invisible from outside
    float edge_length = 0.0f;  // render::typical_edge_length
    // Object-space lines: extracted on the CPU (ray-cast visibility), drawn as strokes;
    // curvature and the ray scene come on first use.
    std::unique_ptr<LineExtractor> line_extractor;
    render::FrameTargets targets;
    std::map<const render::PassType*, std::unique_ptr<render::Pass>> passes;  // made on first use
    std::unique_ptr<render::StrokePass> strokes;                              // draw_lines, on first use

    // set_mesh: the previous mesh is released first, so two are never held at once.
    void stage(std::shared_ptr<Mesh> m, MeshUse use);
    // GL buffers of cpu_mesh; its colours, uvs and materials (but their names) are dropped afterwards.
    void upload();
    Image render(const Camera& camera, const Light& light, const ShadingSelection& shading,
                 const std::vector<LineSettings>& lines, const RenderOptions& options, AovImages* aovs,
                 std::vector<PassTiming>* timings);
    // Runs `planned` in order, each timed when `timings` is given.
    void run(const std::vector<render::PlannedPass>& planned, render::Frame& frame, std::vector<PassTiming>* timings);
};

Renderer::Renderer() : impl_(std::make_unique<Impl>()) {
    impl_->context = gpu::create_headless_context();
    impl_->context->make_current();
}

Renderer::Renderer(std::function<void()> make_current) : impl_(std::make_unique<Impl>()) {
    impl_->context = gpu::wrap_external_context(std::move(make_current));
    impl_->context->make_current();
}

Renderer::~Renderer() {
    if (!impl_ || !impl_->context) return;
    try {
        impl_->context->make_current();
    } catch (const std::exception&) {
        // The context is gone (a window closed first): its GL objects went with it, and GL calls
        // without a context must not be made. Nothing may throw out of a destructor.
        (void)impl_.release();
        return;
    }
    // impl_ now goes with the context current, its GL objects before the context (Impl's order).
}

std::string Renderer::gl_renderer() const {
    impl_->context->make_current();
    return impl_->context->renderer();
}

void Renderer::Impl::stage(std::shared_ptr<Mesh> m, MeshUse use) {
    if (m->triangles.empty()) throw InputError("mesh has no triangles");
    context->make_current();
    line_extractor.reset();
    mesh.reset();
    cpu_mesh.reset();
    targets.shadow_light.reset();
    // Before the upload: its edge keys (24 bytes a triangle) and the GL buffers are never
    // held at once.
    closed = geometry::is_closed_outward(*m);
    bounds = m->bounds();
    edge_length = render::typical_edge_length(*m);
    geometry::ensure_vertex_normals(*m);  // what the line extractor needs, so it can share
    geometry::reserve_embree_padding(m->positions);
    cpu_mesh = std::move(m);
    line_extractor = std::make_unique<LineExtractor>(std::shared_ptr<const Mesh>(cpu_mesh));
    if (use == MeshUse::ManyFrames) upload();
}

void Renderer::Impl::upload() {
    mesh = std::make_unique<render::GpuMesh>(*cpu_mesh);
    // The GL buffers and textures hold these now; the line extractor reads only the face
    // materials and the material names (material boundaries, line sets' selections).
    cpu_mesh->colors = {};
    cpu_mesh->uvs = {};
    for (Material& m : cpu_mesh->materials) m = Material{.name = std::move(m.name)};
}

void Renderer::Impl::run(const std::vector<render::PlannedPass>& planned, render::Frame& frame,
                         std::vector<PassTiming>* timings) {
    for (const render::PlannedPass& p : planned) {
        render::PassTimer timer(timings, p.type->name);
        std::unique_ptr<render::Pass>& pass = passes[p.type];
        if (!pass) pass = p.type->create();
        if (p.target == render::PassTarget::Color) targets.color->bind();
        if (p.target == render::PassTarget::ResolvedColor) targets.color->bind_resolved();
        pass->run(frame);
    }
}

namespace {

void check_bit_depth(const RenderOptions& options) {
    if (options.bit_depth != 8 && options.bit_depth != 16)
        throw InputError("bit depth: expected 8 or 16, got " + std::to_string(options.bit_depth));
}

}  // namespace

void Renderer::set_mesh(const Mesh& mesh, MeshUse use) { impl_->stage(std::make_shared<Mesh>(mesh), use); }

void Renderer::set_mesh(Mesh&& mesh, MeshUse use) { impl_->stage(std::make_shared<Mesh>(std::move(mesh)), use); }

Image Renderer::render(const Camera& camera, const Light& light, const ShadingSelection& shading,
                       const RenderOptions& options, std::vector<PassTiming>* timings) {
    return render(camera, light, shading, {}, options, timings);
}

Image Renderer::render(const Camera& camera, const Light& light, const ShadingSelection& shading,
                       const std::vector<LineSettings>& lines, const RenderOptions& options,
                       std::vector<PassTiming>* timings) {
    return impl_->render(camera, light, shading, lines, options, nullptr, timings);
}

Image Renderer::render(const Camera& camera, const Light& light, const ShadingSelection& shading,
                       const std::vector<LineSettings>& lines, const RenderOptions& options, AovImages& aovs,
                       std::vector<PassTiming>* timings) {
    return impl_->render(camera, light, shading, lines, options, &aovs, timings);
}

Image Renderer::Impl::render(const Camera& camera, const Light& light, const ShadingSelection& shading,
                             const std::vector<LineSettings>& lines, const RenderOptions& options, AovImages* aovs,
                             std::vector<PassTiming>* timings) {
    Impl* const impl_ = this;  // the body reads as the public method's did
    if (!impl_->cpu_mesh) throw RuntimeError("no mesh to render (set_mesh first)");
    check_bit_depth(options);
    const ShadingModel& model = shading_model(shading.model);
    // A model's own strokes (hatching) join the style's lines.
    std::vector<LineSettings> all_lines = lines;
    if (auto own = render::model_strokes(model, shading.params, light, camera, impl_->bounds))
        all_lines.push_back(std::move(*own));
    std::vector<LineSettings> object_lines = render::object_lines_of(all_lines, !impl_->closed);  // checks every type
    impl_->context->make_current();
    render::Frame frame{
        .camera = camera,
        .light = light,
        .shading = shading,
        .model = model,
        .options = options,
        .lines = all_lines,
        .bounds = impl_->bounds,
        .edge_length = impl_->edge_length,
        .closed = impl_->closed,
        .cull_back_faces = render::cull_back_faces(impl_->closed, impl_->bounds, camera),
        .line_extractor = *impl_->line_extractor,
        .cpu_mesh = *impl_->cpu_mesh,
        .mesh = impl_->mesh.get(),
        .targets = impl_->targets,
        .object_lines = std::move(object_lines),
        .aovs = aovs,
    };

    // The passes the style and the shading model need, in order.
    const render::PassPlan plan = render::plan_passes(frame, /*before_upload=*/!impl_->mesh);
    frame.reads = plan.reads;
    if (!impl_->mesh) {
        // MeshUse::OneFrame: what needs the mesh-wide line data first, that data freed before
        // the GL buffers exist.
        impl_->run(plan.before_upload, frame, timings);
        impl_->line_extractor->release_mesh_data();
        impl_->upload();
        frame.mesh = impl_->mesh.get();
    }
    impl_->targets.color_for(options.width, options.height, options.samples, options.bit_depth);
    impl_->run(plan.passes, frame, timings);
    return std::move(frame.image);
}

Image Renderer::draw_lines(const LineDrawing& drawing, const RenderOptions& options) {
    check_bit_depth(options);
    if (drawing.width != options.width || drawing.height != options.height)
        throw InputError("the line drawing is " + std::to_string(drawing.width) + "x" + std::to_string(drawing.height) +
                         ", the image " + std::to_string(options.width) + "x" + std::to_string(options.height));
    impl_->context->make_current();
    gpu::Framebuffer& target =
        impl_->targets.color_for(options.width, options.height, options.samples, options.bit_depth);
    target.bind();
    // The shading pass's clear: premultiplied, so a transparent background reads back as it does.
    const glm::vec4& bg = options.background;
    glClearColor(bg.r * bg.a, bg.g * bg.a, bg.b * bg.a, bg.a);
    glClearDepth(1.0);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    if (!impl_->strokes) impl_->strokes = std::make_unique<render::StrokePass>();
    impl_->strokes->draw_layers(drawing.layers, options.width, options.height, options.samples);
    target.resolve();
    return target.read(bg.a < 1.0f);
}

}  // namespace inkshade
