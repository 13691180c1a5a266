// `shading`: the shading model (inkshade/shading.hpp) into the cleared colour target, with the
// surface line types it tests per fragment (render/surface_lines.hpp), the shadow map and the
// base-colour textures, read and written in the frame's colour convention
// (render/color_convention.hpp), and C made as the selection's BaseColorUse says.
#include <algorithm>
#include <cctype>
#include <map>

#include "gpu/gl_state.hpp"
#include "gpu/shader_program.hpp"
#include "inkshade/color.hpp"
#include "render/color_convention.hpp"
#include "render/back_faces.hpp"
#include "render/frame.hpp"
#include "render/mtoon_textures.hpp"
#include "render/surface_lines.hpp"

namespace inkshade::render {

namespace {

constexpr GLuint kShadowUnit = 1;
constexpr GLuint kBaseTextureUnit = 2;

std::string uniform_name(const std::string& param) {
    std::string u = "u_" + param;
    for (char& c : u)
        if (c == '-' || c == '.') c = '_';
    return u;
}

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

bool param_on(const ShadingModel& model, const ParamValues& values, const char* name) {
    const ParamSpec* spec = model.param(name);
    return spec && value_or_default(*spec, values).at(0) != 0.0f;
}

// Shadow map for models that cast shadows, when their "shadows" parameter is on.
bool casts_shadows(const Frame& frame) {
    return frame.model.shadow_map && param_on(frame.model, frame.shading.params, "shadows");
}

// The MToon textures' samplers, in the units after the base colour's (GpuMesh::draw_by_material).
void set_mtoon_samplers(gpu::ShaderProgram& program) {
    for (int slot = 0; slot < kMtoonTextureSlotCount; ++slot)
        program.set(kMtoonTextureSlots[slot].sampler, int(kBaseTextureUnit) + 1 + slot);
}

// mtoon's outline is on in `values`: a width mode other than none and a width above 0.
bool outline_on(const ShadingModel& model, const ParamValues& values) {
    const ParamSpec* mode = model.param("outline-width-mode");
    const ParamSpec* width = model.param("outline-width");
    return mode && width && value_or_default(*mode, values).at(0) != 0.0f &&
           value_or_default(*width, values).at(0) > 0.0f;
}

// The model draws an outline: its values turn it on, or materials may carry their own
// (Material::mtoon, whose outline values replace the style's per material).
bool draws_outline(const ShadingModel& model, const ParamValues& values, bool material_params) {
    return model.param("outline-width-mode") && (outline_on(model, values) || material_params);
}

// What C is made of (BaseColorUse, docs/shading.md "Base colour"): the base colour, and
// whether the mesh's vertex/material colours and textures multiply it.
struct Albedo {
    glm::vec3 base{1.0f};
    bool mesh_colors = true;
};

Albedo albedo(const ShadingSelection& shading, const GpuMesh& mesh) {
    switch (shading.base_color_use) {
        case BaseColorUse::Multiply: break;
        case BaseColorUse::Fallback: return {mesh.has_own_colors() ? glm::vec3(1.0f) : shading.base_color, true};
        case BaseColorUse::Only: return {shading.base_color, false};
    }
    return {shading.base_color, true};
}

// The uniforms every shading model reads (common/lighting.glsl, common/surface.glsl).
void set_frame_uniforms(gpu::ShaderProgram& program, const Frame& frame, const Albedo& albedo,
                        ColorConvention convention) {
    const Camera& camera = frame.camera;
    const Light& light = frame.light;
    const glm::mat4 model_matrix(1.0f);
    program.set("u_model", model_matrix);
    program.set("u_view_proj", camera.projection(frame.aspect()) * camera.view());
    program.set("u_view", camera.view());
    program.set("u_normal_matrix", glm::mat3(glm::transpose(glm::inverse(model_matrix))));
    program.set("u_eye", camera.eye);
    program.set("u_view_dir", glm::normalize(camera.target - camera.eye));
    program.set("u_orthographic", camera.orthographic ? 1 : 0);
    program.set("u_light_type", light.type == LightType::Directional ? 0 : light.type == LightType::Point ? 1 : 2);
    program.set("u_light_pos", light.position);
    program.set("u_light_target", light.target);
    program.set("u_light_color", light.color * light.intensity);
    program.set("u_light_cone", glm::vec2(light.cos_outer, light.cos_inner));
    program.set("u_light_range", light.range);
    program.set("u_light_falloff_decay", light.decay);
    program.set("u_ambient", light.ambient);
    program.set("u_base_color", albedo.base);
    program.set("u_srgb_output", convention == ColorConvention::Linear ? 1 : 0);
    program.set("u_bbox_min", frame.bounds.min);
    program.set("u_bbox_max", frame.bounds.max);
    program.set("u_viewport_size", glm::vec2(frame.options.width, frame.options.height));
}

class ShadingPass final : public Pass {
public:
    void run(Frame& frame) override {
        const ShadingModel& model = frame.model;
        const ShadingSelection& shading = frame.shading;
        GpuMesh& mesh = *frame.mesh;
        const ColorConvention convention = color_convention(model, shading.params, frame.options);
        const Albedo c = albedo(shading, mesh);
        // Every shading model samples the base-colour texture (common/surface.glsl; gouraud in
        // its own fragment stage); debug views show geometry only.
        const bool textured = mesh.textured() && !model.debug_view && c.mesh_colors;
        const bool material_params =
            mesh.has_material_params() && param_on(model, shading.params, "use-material-params");
        const bool unlit = mesh.has_unlit_materials() && !model.debug_view;
        // A VRM material's MToon textures go with its values (use-material-params).
        const bool mtoon_textures = material_params && mesh.has_mtoon_textures() && model.param("matcap-color");
        const SurfaceLines surface_lines{frame.line("rim-contour")};
        // A mesh whose colours are all white needs no variant to leave them out.
        const bool base_color_only = !c.mesh_colors && mesh.has_own_colors();
        gpu::ShaderProgram& program = program_for(model, shading.params, surface_lines, textured, mtoon_textures,
                                                  base_color_only, unlit, /*outline=*/false, frame.light);

        const glm::vec4& bg = frame.options.background;
        // Premultiplied clear: a transparent background resolves to alpha-weighted edges.
        glClearColor(bg.r * bg.a, bg.g * bg.a, bg.b * bg.a, bg.a);
        glClearDepth(1.0);
        glClearStencil(0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        const gpu::DepthScope depth(GL_LESS);
        std::optional<gpu::CapabilityScope> multisample;
        if (frame.options.samples > 1) multisample.emplace(GL_MULTISAMPLE, true);

        program.use();
        set_frame_uniforms(program, frame, c, convention);
        if (casts_shadows(frame)) {
            const ShadowMap& map = *frame.targets.shadow_map;
            map.bind(kShadowUnit);
            program.set("u_shadow_map", int(kShadowUnit));
            program.set("u_light_view_proj", *frame.targets.shadow_light);
            program.set("u_shadow_texel_world", frame.bounds.diagonal() / float(map.size()));
        }
        upload_params(program, model, shading.params);
        surface_lines.upload(program);
        if (textured || material_params || unlit) program.set("u_base_texture", int(kBaseTextureUnit));
        if (mtoon_textures) set_mtoon_samplers(program);
        // Two-sided (open meshes show their lit inside), front faces winning depth ties
        // (render/back_faces.hpp); back faces culled when none can be seen.
        draw_front_then_back(frame, program, [&] {
            if (!textured && !material_params && !unlit) return mesh.draw();
            mesh.draw_by_material(kBaseTextureUnit, texels_of(convention), [&](const Material* material) {
                if (material_params)
                    upload_params(program, model, with_material_params(model, shading.params, material));
                if (unlit) program.set("u_unlit", material && material->unlit ? 1 : 0);
                return true;
            });
        });
        if (draws_outline(model, shading.params, material_params))
            draw_outline(frame, c, convention, textured, mtoon_textures, base_color_only, material_params);
    }

private:
    // mtoon's outline (three-vrm's second draw of an MToon material, shaders/shading/mtoon_outline.glsl):
    // back faces moved out along their normals, depth-tested (three.js's LessEqual) and written
    // against the model just drawn, material by material when the materials carry their own
    // outline values; unlit materials have none (they are not MToon materials).
    void draw_outline(const Frame& frame, const Albedo& c, ColorConvention convention, bool textured,
                      bool mtoon_textures, bool base_color_only, bool material_params) {
        const ShadingModel& model = frame.model;
        const ParamValues& params = frame.shading.params;
        gpu::ShaderProgram& program =
            program_for(model, params, SurfaceLines{nullptr}, textured, mtoon_textures, base_color_only,
                        /*unlit=*/false, /*outline=*/true, frame.light);
        program.use();
        set_frame_uniforms(program, frame, c, convention);
        program.set("u_projection", frame.camera.projection(frame.aspect()));
        if (casts_shadows(frame)) {
            program.set("u_shadow_map", int(kShadowUnit));
            program.set("u_light_view_proj", *frame.targets.shadow_light);
            program.set("u_shadow_texel_world", frame.bounds.diagonal() / float(frame.targets.shadow_map->size()));
        }
        upload_params(program, model, params);
        if (textured || material_params) program.set("u_base_texture", int(kBaseTextureUnit));
        if (mtoon_textures) set_mtoon_samplers(program);
        const gpu::DepthScope depth(GL_LEQUAL, /*write=*/true);
        const gpu::CullScope cull(GL_FRONT);
        const BackFacePushScope push(frame, program);
        GpuMesh& mesh = *frame.mesh;
        if (!textured && !material_params) return mesh.draw();
        mesh.draw_by_material(kBaseTextureUnit, texels_of(convention), [&](const Material* material) {
            if (!material_params) return true;
            if (material && material->unlit) return false;
            const ParamValues merged = with_material_params(model, params, material);
            if (!outline_on(model, merged)) return false;
            upload_params(program, model, merged);
            return true;
        });
    }

    // One compiled variant per model and compile-time parameter values (#defines, not uniform
    // branches: llvmpipe executes switched-off branches too). A shadow-casting model's
    // `shadows` parameter is one of them (INKSHADE_SHADOWS, common/shadow.glsl). `textured`:
    // the variant that samples the base-colour texture (INKSHADE_BASE_TEXTURE);
    // `base_color_only`: the one that leaves out the vertex/material colours (BaseColorUse::Only).
    // `unlit`: the one that draws unlit materials as they are (INKSHADE_UNLIT). A model file's
    // spot light and physical falloff (common/lighting.glsl) are variants too, and so is mtoon's
    // outline draw (`outline`: INKSHADE_MTOON_OUTLINE) and its materials' textures
    // (`mtoon_textures`: INKSHADE_MTOON_TEXTURES).
    gpu::ShaderProgram& program_for(const ShadingModel& model, const ParamValues& values, const SurfaceLines& lines,
                                    bool textured, bool mtoon_textures, bool base_color_only, bool unlit, bool outline,
                                    const Light& light) {
        std::string defines = textured ? "#define INKSHADE_BASE_TEXTURE 1\n" : "";
        if (mtoon_textures) defines += "#define INKSHADE_MTOON_TEXTURES 1\n";
        if (outline) defines += "#define INKSHADE_MTOON_OUTLINE 1\n";
        if (base_color_only) defines += "#define INKSHADE_BASE_COLOR_ONLY 1\n";
        if (model.radial_curvature) defines += "#define INKSHADE_RADIAL_CURVATURE 1\n";
        if (unlit) defines += "#define INKSHADE_UNLIT 1\n";
        if (light.type == LightType::Spot) defines += "#define INKSHADE_SPOT_LIGHT 1\n";
        if (light.physical_falloff && light.type != LightType::Directional)
            defines += "#define INKSHADE_PHYSICAL_FALLOFF 1\n";
        for (const ParamSpec& spec : model.params) {
            if (!spec.compile_time) continue;
            const ParamValue& v = value_or_default(spec, values);
            std::string macro = "INKSHADE_" + spec.name;
            for (char& c : macro) c = c == '-' ? '_' : char(std::toupper(static_cast<unsigned char>(c)));
            defines += "#define " + macro + " " + std::to_string(int(v.at(0))) + "\n";
        }
        const std::string fragment_defines = lines.defines();
        auto& p = programs_[model.name + "|" + defines + fragment_defines];
        if (!p) p = std::make_unique<gpu::ShaderProgram>(model.vertex, model.fragment, defines, fragment_defines);
        return *p;
    }

    std::map<std::string, std::unique_ptr<gpu::ShaderProgram>> programs_;  // by model and defines
};

const PassRegistration shading_pass{{
    .name = "shading",
    .stage = Stage::Shading,
    .plan = [](const Frame& frame) -> std::optional<PassIo> {
        PassIo io{.reads = {Resource::GpuMesh}, .writes = {Resource::Color}};
        if (casts_shadows(frame)) io.reads |= {Resource::ShadowMap};
        if (frame.model.radial_curvature) io.reads |= {Resource::VertexScalar};
        return io;
    },
    .create = create_pass<ShadingPass>,
}};

}  // namespace

}  // namespace inkshade::render
