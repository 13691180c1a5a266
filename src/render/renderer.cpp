#include "inkshade/renderer.hpp"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <map>
#include <optional>

#include "geometry/normals.hpp"
#include "geometry/orientation.hpp"
#include "geometry/visibility.hpp"
#include "gpu/framebuffer.hpp"
#include "gpu/gl_context.hpp"
#include "gpu/shader_program.hpp"
#include "inkshade/color.hpp"
#include "inkshade/error.hpp"
#include "inkshade/line_drawing.hpp"
#include "render/gbuffer.hpp"
#include "render/gpu_mesh.hpp"
#include "render/lines/hull.hpp"
#include "render/lines/image_lines_pass.hpp"
#include "render/lines/threejs_outline.hpp"
#include "render/shadow_pass.hpp"
#include "render/stroke_pass.hpp"
#include "render/surface_lines.hpp"

namespace inkshade {

namespace {

std::string uniform_name(const std::string& param) {
    std::string u = "u_" + param;
    for (char& c : u)
        if (c == '-' || c == '.') c = '_';
    return u;
}

// Times one pass by finishing the GPU work before and after it (benchmark mode only).
class PassTimer {
public:
    PassTimer(std::vector<PassTiming>* out, std::string name) : out_(out), name_(std::move(name)) {
        if (!out_) return;
        glFinish();
        start_ = std::chrono::steady_clock::now();
        // GPU time from timestamp queries (ARB_timer_query, core since 3.3) around the pass.
        glGenQueries(2, queries_);
        glQueryCounter(queries_[0], GL_TIMESTAMP);
    }
    ~PassTimer() {
        if (!out_) return;
        glQueryCounter(queries_[1], GL_TIMESTAMP);
        glFinish();
        auto end = std::chrono::steady_clock::now();
        GLuint64 t0 = 0, t1 = 0;
        glGetQueryObjectui64v(queries_[0], GL_QUERY_RESULT, &t0);  // available: finished above
        glGetQueryObjectui64v(queries_[1], GL_QUERY_RESULT, &t1);
        glDeleteQueries(2, queries_);
        out_->push_back({name_, std::chrono::duration<double, std::milli>(end - start_).count(),
                         t1 >= t0 ? double(t1 - t0) * 1e-6 : 0.0});
    }

private:
    std::vector<PassTiming>* out_;
    std::string name_;
    std::chrono::steady_clock::time_point start_;
    GLuint queries_[2] = {0, 0};
};

// Sets u_NAME for every parameter of the model (the value given, else the default).
void upload_params(gpu::ShaderProgram& program, const ShadingModel& model, const ParamValues& values) {
    for (const ParamSpec& spec : model.params) {
        if (spec.compile_time) continue;  // a #define of the program variant
        const ParamValue& v = value_or_default(spec, values);
        const std::string u = uniform_name(spec.name);
        switch (spec.type) {
            case ParamType::Float: program.set(u, v.at(0)); break;
            case ParamType::Int:
            case ParamType::Bool:
            case ParamType::Choice: program.set(u, int(v.at(0))); break;
            case ParamType::Color: {
                const glm::vec3 c(v.at(0), v.at(1), v.at(2));
                program.set(u, spec.srgb ? srgb_to_linear(c) : c);  // three.js colours: decoded once here
                break;
            }
            case ParamType::FloatList: {
                std::vector<float> padded(size_t(spec.max_count), v.empty() ? 0.0f : v.back());
                std::copy_n(v.begin(), std::min(v.size(), padded.size()), padded.begin());
                program.set_array(u + "[0]", padded);
                program.set(u + "_count", int(std::min(v.size(), padded.size())));
                break;
            }
        }
    }
}

// The model's values with a material's VRM MToon values (Material::mtoon) in place of those
// the material carries, when the model has `use-material-params` and it is on.
ParamValues with_material_params(const ShadingModel& model, const ParamValues& values, const Material* material) {
    ParamValues merged = values;
    if (!material) return merged;
    for (const ParamSpec& spec : model.params) {
        if (spec.compile_time) continue;  // a program variant, not a per-draw uniform
        auto it = material->mtoon.find(spec.name);
        if (it != material->mtoon.end() && it->second.size() == value_or_default(spec, values).size())
            merged[spec.name] = it->second;
    }
    return merged;
}

constexpr GLuint kBaseTextureUnit = 2;  // 1 is the shadow map's

}  // namespace

struct Renderer::Impl {
    std::unique_ptr<gpu::GlContext> context;
    std::unique_ptr<render::GpuMesh> mesh;
    BoundingBox bounds;
    bool closed = false;  // closed and outward: back faces invisible from outside
    std::map<std::string, std::unique_ptr<gpu::ShaderProgram>> programs;  // by model name
    std::unique_ptr<gpu::Framebuffer> framebuffer;
    std::unique_ptr<render::ShadowPass> shadow;  // created on first use
    // The shadow map depends only on the mesh and the light: it is kept while both are
    // unchanged (new views of one model under one light, as batch and the viewer render).
    bool shadow_valid = false;
    glm::mat4 shadow_light_view_proj{0.0f};
    // Line passes, created on first use.
    std::unique_ptr<render::GBuffer> gbuffer;  // the image's size
    std::unique_ptr<render::HullPass> hull;
    std::unique_ptr<render::ThreejsOutlinePass> threejs_outline;
    std::unique_ptr<render::ImageLinesPass> image_lines;
    // The mesh of set_mesh (copied or moved in, since the caller's need not outlive set_mesh),
    // shared with the line extractor; after the GL upload only positions, triangles and normals
    // are kept. `mesh` (the GL buffers) is null until the upload.
    std::shared_ptr<Mesh> cpu_mesh;
    // Object-space lines: extracted on the CPU (ray-cast visibility), drawn as strokes;
    // curvature and the ray scene come on first use.
    std::unique_ptr<LineExtractor> line_extractor;
    std::unique_ptr<render::StrokePass> strokes;

    // set_mesh: the previous mesh is released first, so two are never held at once.
    void stage(std::shared_ptr<Mesh> m, MeshUse use);
    // GL buffers of cpu_mesh; its colours, uvs and materials are dropped afterwards.
    void upload();

    // One compiled variant per model and compile-time parameter values (#defines, not
    // uniform branches: llvmpipe executes switched-off branches too). A shadow-casting
    // model's `shadows` parameter is one of them (INKSHADE_SHADOWS, common/shadow.glsl).
    // `textured`: the variant that samples the base-colour texture (INKSHADE_BASE_TEXTURE).
    gpu::ShaderProgram& program_for(const ShadingModel& model, const ParamValues& values,
                                    const render::SurfaceLines& lines, bool textured) {
        std::string defines = textured ? "#define INKSHADE_BASE_TEXTURE 1\n" : "";
        if (model.radial_curvature) defines += "#define INKSHADE_RADIAL_CURVATURE 1\n";
        for (const ParamSpec& spec : model.params) {
            if (!spec.compile_time) continue;
            const ParamValue& v = value_or_default(spec, values);
            std::string macro = "INKSHADE_" + spec.name;
            for (char& c : macro) c = c == '-' ? '_' : char(std::toupper(static_cast<unsigned char>(c)));
            defines += "#define " + macro + " " + std::to_string(int(v.at(0))) + "\n";
        }
        const std::string fragment_defines = lines.defines();
        auto& p = programs[model.name + "|" + defines + fragment_defines];
        if (!p) p = std::make_unique<gpu::ShaderProgram>(model.vertex, model.fragment, defines, fragment_defines,
                                                         lines.epilogue(model.fragment));
        return *p;
    }

    gpu::Framebuffer& framebuffer_for(const RenderOptions& o) {
        if (!framebuffer || framebuffer->width() != o.width || framebuffer->height() != o.height ||
            framebuffer->samples() != std::max(1, o.samples)) {
            framebuffer.reset();
            framebuffer = std::make_unique<gpu::Framebuffer>(o.width, o.height, o.samples);
        }
        return *framebuffer;
    }
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
    // GL objects go before the context that owns them.
    impl_->gbuffer.reset();
    impl_->strokes.reset();
    impl_->hull.reset();
    impl_->threejs_outline.reset();
    impl_->image_lines.reset();
    impl_->framebuffer.reset();
    impl_->shadow.reset();
    impl_->programs.clear();
    impl_->mesh.reset();
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
    shadow_valid = false;
    // Before the upload: its edge keys (24 bytes a triangle) and the GL buffers are never
    // held at once.
    closed = geometry::is_closed_outward(*m);
    bounds = m->bounds();
    geometry::ensure_vertex_normals(*m);  // what the line extractor needs, so it can share
    geometry::reserve_embree_padding(m->positions);
    cpu_mesh = std::move(m);
    line_extractor = std::make_unique<LineExtractor>(std::shared_ptr<const Mesh>(cpu_mesh));
    if (use == MeshUse::ManyFrames) upload();
}

void Renderer::Impl::upload() {
    mesh = std::make_unique<render::GpuMesh>(*cpu_mesh);
    // The GL buffers and textures hold these now; the line extractor never reads them.
    cpu_mesh->colors = {};
    cpu_mesh->uvs = {};
    cpu_mesh->materials = {};
    cpu_mesh->face_materials = {};
}

void Renderer::set_mesh(const Mesh& mesh, MeshUse use) { impl_->stage(std::make_shared<Mesh>(mesh), use); }

void Renderer::set_mesh(Mesh&& mesh, MeshUse use) { impl_->stage(std::make_shared<Mesh>(std::move(mesh)), use); }

namespace {

// Back faces may be culled only when none can be seen: a closed outward surface with the
// whole bounding box in front of the near plane (the camera outside, nothing clipped open).
bool can_cull_back_faces(bool closed, const BoundingBox& b, const Camera& camera) {
    if (!closed) return false;
    const glm::mat4 view = camera.view();
    for (int i = 0; i < 8; ++i) {
        glm::vec3 p((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z);
        if (-(view * glm::vec4(p, 1.0f)).z <= camera.near_plane) return false;
    }
    return true;
}

}  // namespace

Image Renderer::render(const Camera& camera, const Light& light, const ShadingSelection& shading,
                       const RenderOptions& options, std::vector<PassTiming>* timings) {
    return render(camera, light, shading, {}, options, timings);
}

Image Renderer::render(const Camera& camera, const Light& light, const ShadingSelection& shading,
                       const std::vector<LineSettings>& lines, const RenderOptions& options,
                       std::vector<PassTiming>* timings) {
    if (!impl_->cpu_mesh) throw RuntimeError("no mesh to render (set_mesh first)");
    // The image-space line types of the style get GPU passes; object-space ones are extracted
    // on the CPU and drawn as strokes.
    const LineSettings *hull = nullptr, *rim = nullptr, *edges = nullptr, *suggestive = nullptr,
                       *threejs_outline = nullptr;
    std::vector<LineSettings> vector_lines;
    for (const LineSettings& l : lines) {
        if (line_type(l.type).space == LineSpace::Object) vector_lines.push_back(l);
        if (line_type(l.type).space != LineSpace::Image) continue;
        if (l.type == "hull") hull = &l;
        else if (l.type == "rim-contour") rim = &l;
        else if (l.type == "edges") edges = &l;
        else if (l.type == "suggestive-image") suggestive = &l;
        else if (l.type == "threejs-outline") threejs_outline = &l;
    }
    render::SurfaceLines surface_lines;
    surface_lines.rim = rim;

    impl_->context->make_current();
    const ShadingModel& model = shading_model(shading.model);
    // MeshUse::OneFrame: what needs the mesh-wide line data (object-space lines, the kr view's
    // curvature) first, that data freed before the GL buffers exist.
    std::optional<LineDrawing> early_drawing;
    std::optional<std::vector<float>> early_kr;
    if (!impl_->mesh) {
        if (model.radial_curvature) {
            PassTimer t(timings, "radial-curvature");
            early_kr = impl_->line_extractor->radial_curvature(camera);
        }
        if (!vector_lines.empty()) {
            PassTimer t(timings, "vector-lines");
            early_drawing = impl_->line_extractor->draw(camera, options.width, options.height, vector_lines);
        }
        impl_->line_extractor->release_mesh_data();
        impl_->upload();
        if (early_kr) impl_->mesh->set_vertex_scalar(*early_kr);
    }
    gpu::Framebuffer& fb = impl_->framebuffer_for(options);
    const float aspect = float(options.width) / float(options.height);

    // Shadow map for models that cast shadows, when their "shadows" parameter is on.
    const ParamSpec* shadows_spec = model.param("shadows");
    const bool shadows =
        model.shadow_map && shadows_spec && value_or_default(*shadows_spec, shading.params).at(0) != 0.0f;
    // Every shading model samples the base-colour texture (common/surface.glsl; gouraud in its
    // own fragment stage); debug views show geometry only.
    const bool textured = impl_->mesh->textured() && !model.debug_view;
    const ParamSpec* material_params_spec = model.param("use-material-params");
    const bool material_params = impl_->mesh->has_material_params() && material_params_spec &&
                                 value_or_default(*material_params_spec, shading.params).at(0) != 0.0f;
    gpu::ShaderProgram& program = impl_->program_for(model, shading.params, surface_lines, textured);
    const bool cull = can_cull_back_faces(impl_->closed, impl_->bounds, camera);
    glm::mat4 light_view_proj(1.0f);
    if (shadows) {
        light_view_proj = render::light_view_projection(light, impl_->bounds);
        if (!impl_->shadow_valid || light_view_proj != impl_->shadow_light_view_proj) {
            PassTimer t(timings, "shadow");
            if (!impl_->shadow) impl_->shadow = std::make_unique<render::ShadowPass>();
            impl_->shadow->render(*impl_->mesh, light_view_proj, impl_->closed);
            impl_->shadow_valid = true;
            impl_->shadow_light_view_proj = light_view_proj;
        }
    }

    if (model.radial_curvature && !early_kr) {
        PassTimer t(timings, "radial-curvature");
        impl_->mesh->set_vertex_scalar(impl_->line_extractor->radial_curvature(camera));
    }
    {
        PassTimer t(timings, "shading");
        fb.bind();
        const glm::vec4& bg = options.background;
        // Premultiplied clear: a transparent background resolves to alpha-weighted edges.
        glClearColor(bg.r * bg.a, bg.g * bg.a, bg.b * bg.a, bg.a);
        glClearDepth(1.0);
        glClearStencil(0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        // Two-sided by default (open meshes show their lit inside); culling is only a speed-up.
        if (cull) {
            glEnable(GL_CULL_FACE);
            glCullFace(GL_BACK);
        } else {
            glDisable(GL_CULL_FACE);
        }
        if (options.samples > 1) glEnable(GL_MULTISAMPLE);

        program.use();
        const glm::mat4 model_matrix(1.0f);
        program.set("u_model", model_matrix);
        program.set("u_view_proj", camera.projection(aspect) * camera.view());
        program.set("u_view", camera.view());
        program.set("u_normal_matrix", glm::mat3(glm::transpose(glm::inverse(model_matrix))));
        program.set("u_eye", camera.eye);
        program.set("u_view_dir", glm::normalize(camera.target - camera.eye));
        program.set("u_orthographic", camera.orthographic ? 1 : 0);
        program.set("u_light_type", light.type == LightType::Point ? 1 : 0);
        program.set("u_light_pos", light.position);
        program.set("u_light_target", light.target);
        program.set("u_light_color", light.color);
        program.set("u_ambient", light.ambient);
        program.set("u_base_color", shading.base_color);
        program.set("u_srgb_output", options.srgb_output ? 1 : 0);
        program.set("u_bbox_min", impl_->bounds.min);
        program.set("u_bbox_max", impl_->bounds.max);
        program.set("u_viewport_size", glm::vec2(options.width, options.height));
        if (shadows) {
            constexpr GLuint kShadowUnit = 1;
            impl_->shadow->bind(kShadowUnit);
            program.set("u_shadow_map", int(kShadowUnit));
            program.set("u_light_view_proj", light_view_proj);
            program.set("u_shadow_texel_world", impl_->bounds.diagonal() / float(impl_->shadow->size()));
        }
        upload_params(program, model, shading.params);
        surface_lines.upload(program);
        if (textured || material_params) {
            program.set("u_base_texture", int(kBaseTextureUnit));
            impl_->mesh->draw_by_material(kBaseTextureUnit, [&](const Material* material) {
                if (material_params)
                    upload_params(program, model, with_material_params(model, shading.params, material));
            });
        } else {
            impl_->mesh->draw();
        }
    }
    if (hull) {
        PassTimer t(timings, "hull");
        fb.bind();
        if (!impl_->hull) impl_->hull = std::make_unique<render::HullPass>();
        impl_->hull->draw(*impl_->mesh, camera, options.width, options.height, *hull);
    }
    if (threejs_outline) {
        PassTimer t(timings, "threejs-outline");
        fb.bind();
        if (!impl_->threejs_outline) impl_->threejs_outline = std::make_unique<render::ThreejsOutlinePass>();
        impl_->threejs_outline->draw(*impl_->mesh, camera, options.width, options.height, *threejs_outline);
    }
    const bool image_lines = edges || suggestive;
    if (image_lines) {
        PassTimer t(timings, "gbuffer");
        if (!impl_->gbuffer || impl_->gbuffer->width() != options.width || impl_->gbuffer->height() != options.height)
            impl_->gbuffer = std::make_unique<render::GBuffer>(options.width, options.height);
        impl_->gbuffer->draw(*impl_->mesh, camera, render::ImageLinesPass::needs_face_normals(edges), cull);
    }
    const auto draw_image_lines = [&] {
        PassTimer t(timings, "image-lines");
        if (!impl_->image_lines) impl_->image_lines = std::make_unique<render::ImageLinesPass>();
        impl_->image_lines->draw(*impl_->gbuffer, camera, impl_->bounds, options.width, options.height, edges,
                                 suggestive);
    };
    // Without object-space strokes to draw over them, the image-space lines go onto the resolved
    // image (bind_resolved): the same bytes, one blend a pixel instead of one a sample.
    const bool image_lines_after_resolve = image_lines && vector_lines.empty();
    if (image_lines && !image_lines_after_resolve) {
        fb.bind();
        draw_image_lines();
    }
    if (!vector_lines.empty()) {
        LineDrawing drawing;
        if (early_drawing) {
            drawing = std::move(*early_drawing);
        } else {
            PassTimer t(timings, "vector-lines");
            drawing = impl_->line_extractor->draw(camera, options.width, options.height, vector_lines);
        }
        PassTimer t(timings, "strokes");
        fb.bind();
        if (!impl_->strokes) impl_->strokes = std::make_unique<render::StrokePass>();
        for (LineLayer& layer : drawing.layers) {
            const Stroke stroke = stroke_of(layer.settings);
            render::StrokeStyle style{stroke.color, stroke.opacity, stroke.width,
                                      line_param(layer.settings, "taper").at(0) != 0.0f};
            // Hidden parts are already cut away exactly by ray casting; without per-point depth
            // the stroke pass skips its depth test, which would otherwise nibble at the half of a
            // contour stroke that lies over the surface it outlines. Hidden layers are SVG-only.
            for (LinePath& path : layer.visible) path.depth.clear();
            impl_->strokes->draw(layer.visible, style, options.width, options.height, options.samples);
        }
    }
    {
        PassTimer t(timings, "resolve");
        fb.resolve();
    }
    if (image_lines_after_resolve) {
        fb.bind_resolved();
        draw_image_lines();
    }
    PassTimer t(timings, "readback");
    return fb.read(options.background.a < 1.0f);
}

}  // namespace inkshade
