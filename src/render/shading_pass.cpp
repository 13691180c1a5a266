// `shading`: the shading model (inkshade/shading.hpp) into the cleared colour target, with the
// surface line types it tests per fragment (render/surface_lines.hpp), the shadow map and the
// base-colour textures, read and written in the frame's colour convention
// (render/color_convention.hpp), and C made as the selection's BaseColorUse says. What the model
// declares it reads (ShadingModel::inputs) is provided here for every model alike: the shadow
// map, and the vertex attributes with their GLSL (render/shading_inputs.hpp).
#include <algorithm>
#include <cctype>
#include <functional>
#include <map>

#include "gpu/gl_state.hpp"
#include "gpu/shader_program.hpp"
#include "inkshade/color.hpp"
#include "render/color_convention.hpp"
#include "render/back_faces.hpp"
#include "render/frame.hpp"
#include "render/mtoon_textures.hpp"
#include "render/shading_inputs.hpp"
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

// A model that declares the shadow map, with the parameter that switches it on.
bool casts_shadows(const Frame& frame) { return frame.model.reads(ShadingInputKind::ShadowMap, frame.shading.params); }

// The MToon textures' samplers, in the units after the base colour's (GpuMesh::draw_by_material).
void set_mtoon_samplers(gpu::ShaderProgram& program) {
    for (int slot = 0; slot < kMtoonTextureSlotCount; ++slot)
        program.set(kMtoonTextureSlots[slot].sampler, int(kBaseTextureUnit) + 1 + slot);
}

// The range's material's texture transforms (Material::uv_transforms; KHR_texture_transform),
// identity where it has none: the base colour's, and with `mtoon` each MToon texture's.
void set_uv_transforms(gpu::ShaderProgram& program, const GpuMesh& mesh, size_t range, bool mtoon) {
    const Material* material = mesh.range_material(range);
    auto transform = [&](const std::string& key) {
        if (!material) return glm::mat3(1.0f);
        const auto it = material->uv_transforms.find(key);
        return it == material->uv_transforms.end() ? glm::mat3(1.0f) : it->second;
    };
    program.set("u_base_uv_transform", transform("base-color-texture"));
    for (int slot = 0; mtoon && slot < kMtoonTextureSlotCount; ++slot)
        program.set(std::string(kMtoonTextureSlots[slot].sampler) + "_uv_transform",
                    transform(kMtoonTextureSlots[slot].name));
}

// Whether the range's material has a normal map (the one MToon texture whose absence the shader
// must know: no texel value means "no perturbation" exactly).
void set_normal_texture_on(gpu::ShaderProgram& program, const GpuMesh& mesh, size_t range) {
    program.set("u_normal_texture_on", mesh.range_has_mtoon_texture(range, kMtoonNormalTextureSlot) ? 1 : 0);
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

// The program variant's switches besides the model's own (ShadingPass::program_for).
struct Variant {
    bool textured = false;
    bool mtoon_textures = false;
    bool base_color_only = false;
    bool unlit = false;
    bool alpha = false;
};

bool blended(const Material* material) { return material && material->alpha_mode == AlphaMode::Blend; }

// A material's glTF alpha mode, coverage and sides (common/surface.glsl); null: opaque, lit as seen.
void set_material_rules(gpu::ShaderProgram& program, const Material* material) {
    program.set("u_alpha_mode", material ? int(material->alpha_mode) : 0);
    program.set("u_base_alpha", material ? material->alpha : 1.0f);
    program.set("u_alpha_cutoff", material ? material->alpha_cutoff : 0.5f);
    program.set("u_double_sided", material && material->sides == FaceSides::Double ? 1 : 0);
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
    program.set("u_time", frame.options.time);
}

// Premultiplied clear: a transparent background resolves to alpha-weighted edges.
void clear_frame(const glm::vec4& bg) {
    glClearColor(bg.r * bg.a, bg.g * bg.a, bg.b * bg.a, bg.a);
    glClearDepth(1.0);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

// The shadow pass's map and light, for a model that casts shadows.
void set_shadow_uniforms(gpu::ShaderProgram& program, const Frame& frame) {
    const ShadowMap& map = *frame.targets.shadow_map;
    map.bind(kShadowUnit);
    program.set("u_shadow_map", int(kShadowUnit));
    program.set("u_light_view_proj", *frame.targets.shadow_light);
    program.set("u_shadow_texel_world", frame.bounds.diagonal() / float(map.size()));
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
        // glTF alpha modes and sides (debug views show geometry: every face, opaque).
        const bool rules = mesh.has_material_rules() && !model.debug_view;
        const bool alpha = rules && mesh.has_alpha_materials();
        const Variant variant{textured, mtoon_textures, base_color_only, unlit, alpha};
        provide_attributes(frame, declared_attributes(model, shading.params));
        gpu::ShaderProgram& program =
            program_for(model, shading.params, surface_lines, variant, /*outline=*/false, frame.light);

        clear_frame(frame.options.background);
        const gpu::DepthScope depth(GL_LESS);
        std::optional<gpu::CapabilityScope> multisample;
        if (frame.options.samples > 1) multisample.emplace(GL_MULTISAMPLE, true);

        program.use();
        set_frame_uniforms(program, frame, c, convention);
        if (casts_shadows(frame)) set_shadow_uniforms(program, frame);
        upload_params(program, model, shading.params);
        surface_lines.upload(program);
        if (textured || material_params || unlit || rules) program.set("u_base_texture", int(kBaseTextureUnit));
        if (mtoon_textures) set_mtoon_samplers(program);
        set_material_rules(program, nullptr);
        // Per material range: its values, unlit flag, alpha mode, sides and normal map.
        auto prepare = [&](size_t r) {
            const Material* material = mesh.range_material(r);
            if (material_params) upload_params(program, model, with_material_params(model, shading.params, material));
            if (unlit) program.set("u_unlit", material && material->unlit ? 1 : 0);
            if (rules) set_material_rules(program, material);
            if (mtoon_textures) set_normal_texture_on(program, mesh, r);
            if (textured || mtoon_textures) set_uv_transforms(program, mesh, r, mtoon_textures);
        };
        // Two-sided (open meshes show their lit inside), front faces winning depth ties
        // (render/back_faces.hpp); back faces culled when none can be seen. Opaque and cut-out
        // materials first, blended ones after them (three.js's opaque, then transparent list);
        // glTF single-sided materials without back faces (three.js FrontSide).
        draw_front_then_back(frame, program, [&](bool back) {
            if (!textured && !material_params && !unlit && !rules) return mesh.draw();
            for (size_t r = 0; r < mesh.range_count(); ++r) {
                const Material* material = mesh.range_material(r);
                if (rules && material && (blended(material) || (back && material->sides == FaceSides::Front))) continue;
                prepare(r);
                mesh.draw_range(r, kBaseTextureUnit, texels_of(convention));
            }
        });
        const bool outline = draws_outline(model, shading.params, material_params);
        if (outline)
            draw_outline(frame, c, convention, variant, material_params,
                         [&](size_t r) { return !(rules && blended(mesh.range_material(r))); });
        if (rules && mesh.has_blend_materials())
            draw_blended(frame, program, prepare, convention, [&](size_t r) {
                if (outline)
                    draw_outline(frame, c, convention, variant, material_params, [r](size_t o) { return o == r; });
            });
    }

private:
    // mtoon's outline (three-vrm's second draw of an MToon material, shaders/shading/mtoon_outline.glsl):
    // back faces moved out along their normals, depth-tested (three.js's LessEqual) and written
    // against the model just drawn, material by material when the materials carry their own
    // outline values; unlit materials have none (they are not MToon materials).
    // `which`: the ranges drawn (a blended material's outline is drawn right after it, with its
    // surface's blending, as three.js draws the second geometry group of the same mesh).
    void draw_outline(const Frame& frame, const Albedo& c, ColorConvention convention, Variant variant,
                      bool material_params, const std::function<bool(size_t)>& which) {
        const ShadingModel& model = frame.model;
        const ParamValues& params = frame.shading.params;
        const bool textured = variant.textured;
        variant.unlit = false;
        gpu::ShaderProgram& program =
            program_for(model, params, SurfaceLines{nullptr}, variant, /*outline=*/true, frame.light);
        program.use();
        set_frame_uniforms(program, frame, c, convention);
        program.set("u_projection", frame.camera.projection(frame.aspect()));
        if (casts_shadows(frame)) set_shadow_uniforms(program, frame);  // the map is bound already; binding again is free
        upload_params(program, model, params);
        const bool rules = frame.mesh->has_material_rules() && !model.debug_view;
        if (textured || material_params || rules) program.set("u_base_texture", int(kBaseTextureUnit));
        if (variant.mtoon_textures) set_mtoon_samplers(program);
        set_material_rules(program, nullptr);
        GLboolean depth_write = GL_TRUE;
        glGetBooleanv(GL_DEPTH_WRITEMASK, &depth_write);  // a blended material's, when drawn with it
        const gpu::DepthScope depth(GL_LEQUAL, depth_write == GL_TRUE);
        const gpu::CullScope cull(GL_FRONT);
        const BackFacePushScope push(frame, program);
        GpuMesh& mesh = *frame.mesh;
        if (!textured && !material_params && !rules) return mesh.draw();
        for (size_t r = 0; r < mesh.range_count(); ++r) {
            if (!which(r)) continue;
            const Material* material = mesh.range_material(r);
            if (material_params) {
                if (material && material->unlit) continue;
                const ParamValues merged = with_material_params(model, params, material);
                if (!outline_on(model, merged)) continue;
                upload_params(program, model, merged);
            }
            if (rules) set_material_rules(program, material);
            if (variant.mtoon_textures) set_normal_texture_on(program, mesh, r);
            if (textured || variant.mtoon_textures) set_uv_transforms(program, mesh, r, variant.mtoon_textures);
            mesh.draw_range(r, kBaseTextureUnit, texels_of(convention));
        }
    }

    // BLEND materials after everything opaque, as three.js draws its transparent list: by
    // renderOrder (three-vrm's render queue), then back to front by the distance of each
    // material's faces (the centre of their box; three.js takes each object's origin), blended
    // "over" (premultiplied: the shader writes colour x alpha) with depth tested and written
    // only with transparentWithZWrite. A double-sided one draws its back faces first, then its
    // front faces (three.js's two passes for a transparent DoubleSide material).
    void draw_blended(const Frame& frame, gpu::ShaderProgram& program, const std::function<void(size_t)>& prepare,
                      ColorConvention convention, const std::function<void(size_t)>& after) {
        const GpuMesh& mesh = *frame.mesh;
        const glm::vec3 forward = glm::normalize(frame.camera.target - frame.camera.eye);
        std::vector<size_t> order;
        for (size_t r = 0; r < mesh.range_count(); ++r)
            if (blended(mesh.range_material(r))) order.push_back(r);
        auto depth_of = [&](size_t r) { return glm::dot(mesh.range_center(r) - frame.camera.eye, forward); };
        std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
            const int oa = mesh.range_material(a)->render_order, ob = mesh.range_material(b)->render_order;
            if (oa != ob) return oa < ob;
            return depth_of(a) > depth_of(b);
        });
        const gpu::BlendScope blend(gpu::BlendFunc{GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA});
        for (size_t r : order) {
            const Material* material = mesh.range_material(r);
            program.use();
            prepare(r);
            const gpu::DepthScope depth(GL_LESS, material->blend_depth_write);
            if (material->sides != FaceSides::Front) {
                const gpu::CullScope cull(GL_FRONT);
                const BackFacePushScope push(frame, program);
                mesh.draw_range(r, kBaseTextureUnit, texels_of(convention));
            }
            {
                const gpu::CullScope cull(GL_BACK);
                program.set("u_back_face_push", 0.0f);
                mesh.draw_range(r, kBaseTextureUnit, texels_of(convention));
            }
            after(r);
        }
    }

    // One compiled variant per model and compile-time parameter values (#defines, not uniform
    // branches: llvmpipe executes switched-off branches too). A shadow-casting model's
    // `shadows` parameter is one of them (INKSHADE_SHADOWS, common/shadow.glsl). `textured`:
    // the variant that samples the base-colour texture (INKSHADE_BASE_TEXTURE);
    // `base_color_only`: the one that leaves out the vertex/material colours (BaseColorUse::Only).
    // `unlit`: the one that draws unlit materials as they are (INKSHADE_UNLIT). A model file's
    // spot light and physical falloff (common/lighting.glsl) are variants too, and so is mtoon's
    // outline draw (`outline`: INKSHADE_MTOON_OUTLINE) and its materials' textures
    // (`mtoon_textures`: INKSHADE_MTOON_TEXTURES), and glTF's MASK and BLEND alpha modes
    // (`alpha`: INKSHADE_MATERIAL_ALPHA; a discard, which llvmpipe's early depth test avoids).
    // The declared vertex attributes add their declarations (render/shading_inputs.hpp).
    gpu::ShaderProgram& program_for(const ShadingModel& model, const ParamValues& values, const SurfaceLines& lines,
                                    const Variant& variant, bool outline, const Light& light) {
        std::string defines = variant.textured ? "#define INKSHADE_BASE_TEXTURE 1\n" : "";
        if (variant.mtoon_textures) defines += "#define INKSHADE_MTOON_TEXTURES 1\n";
        if (outline) defines += "#define INKSHADE_MTOON_OUTLINE 1\n";
        if (variant.base_color_only) defines += "#define INKSHADE_BASE_COLOR_ONLY 1\n";
        if (variant.unlit) defines += "#define INKSHADE_UNLIT 1\n";
        if (variant.alpha) defines += "#define INKSHADE_MATERIAL_ALPHA 1\n";
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
        const std::vector<DeclaredAttribute> attributes = declared_attributes(model, values);
        defines += attribute_defines(attributes);
        const std::string fragment_defines = lines.defines() + attribute_fragment_inputs(attributes);
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
        if (reads_view_attributes(frame.model, frame.shading.params)) io.reads |= {Resource::ViewAttributes};
        return io;
    },
    .create = create_pass<ShadingPass>,
}};

}  // namespace

}  // namespace inkshade::render
