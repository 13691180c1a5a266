// Rendering a mesh with a shading model into an image, headless (EGL) or in a window.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "inkshade/aov.hpp"
#include "inkshade/camera.hpp"
#include "inkshade/image.hpp"
#include "inkshade/lines.hpp"
#include "inkshade/mesh.hpp"
#include "inkshade/shading.hpp"

namespace inkshade {

struct LineDrawing;
struct StrokeSequence;

struct RenderOptions {
    int width = 1024;
    int height = 1024;
    int samples = 4;                               // MSAA samples, resolved before readback
    glm::vec4 background{1.0f, 1.0f, 1.0f, 1.0f};  // alpha 0 = transparent PNG
    // The linear colour convention: textures decoded from sRGB, the output sRGB-encoded. Default:
    // the display convention, texels and formula values as they are (docs/shading.md).
    bool srgb_output = false;
    // Bits a channel of the colour targets and the image: 8 (RGBA8), or 16 (RGBA16 targets, the
    // image's rgba16 filled beside its rgba) for smooth gradients without banding.
    int bit_depth = 8;
    // The AOVs the renderer draws beside the image (depth, normal, id, material, mask; the
    // others are the scene's: render_scene_aovs), returned by the render overload that takes
    // AovImages. One sample a pixel but the mask, whose samples are averaged.
    AovSet aovs;
    // The moment drawn, in seconds: mtoon's UV animation is at speed x time (Scene::time).
    float time = 0.0f;
    // The sequence this frame belongs to (a turntable, an animation), owned by the caller: the
    // object-space lines' `coherence` layers follow its previous frame and leave this one there
    // (LineExtractor::draw). Null: a frame on its own.
    StrokeSequence* stroke_sequence = nullptr;
};

struct PassTiming {
    std::string pass;
    double milliseconds = 0.0;      // wall time, the pass finished (glFinish) before and after
    double gpu_milliseconds = 0.0;  // GL timestamp queries around the pass (CPU work excluded)
};

// How a mesh given to Renderer::set_mesh will be rendered.
enum class MeshUse {
    // Views of one mesh (viewer, batch, timing runs): the GL buffers are made at set_mesh and the
    // object-space lines' mesh-wide data (curvature, adjacency, ray scene) is kept between frames.
    ManyFrames,
    // One image (`inkshade render`): the first render extracts its object-space lines before
    // the GL upload and frees their mesh-wide data before the raster passes, so the two memory
    // peaks do not add up (10 M triangles, ink-vector style: 1.6 GiB -> under 1 GiB). Later
    // renders still work, recomputing that data each time.
    OneFrame,
};

class Renderer {
public:
    // Creates a headless OpenGL 4.5 context. Throws RuntimeError when none is available.
    Renderer();
    // Renders with the caller's OpenGL 4.5 core context (a window's, e.g. GLFW), which
    // `make_current` makes current; the renderer draws into its own framebuffers and leaves the
    // default framebuffer alone. The context must outlive the renderer.
    explicit Renderer(std::function<void()> make_current);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Replaces the mesh: its GL buffers are made now (ManyFrames) or on the first render
    // (OneFrame). Missing or invalid vertex normals are replaced by angle-weighted ones and the
    // rest made unit (geometry::ensure_vertex_normals), for shading and lines alike. The renderer
    // keeps positions, triangles and normals for object-space lines: copied from a const mesh,
    // taken from a moved one (which saves a copy, 240 MB at 10 M triangles). Throws InputError
    // for a mesh without triangles.
    void set_mesh(const Mesh& mesh, MeshUse use = MeshUse::ManyFrames);
    void set_mesh(Mesh&& mesh, MeshUse use = MeshUse::ManyFrames);

    // Renders the current mesh. With `timings`, each pass is finished (glFinish) and timed.
    Image render(const Camera& camera, const Light& light, const ShadingSelection& shading,
                 const RenderOptions& options, std::vector<PassTiming>* timings = nullptr);

    // Renders the current mesh with the image-space line types among `lines` (LineSpace::Image:
    // hull, rim-contour, edges, suggestive-image, threejs-outline; docs/lines-raster.md,
    // docs/threejs.md); object-space types are skipped here. Passes: shading (with the
    // rim-contour test), hull, threejs-outline, then when edges or
    // suggestive-image are on a G-buffer pass and one full-screen image-lines pass; resolve,
    // readback.
    Image render(const Camera& camera, const Light& light, const ShadingSelection& shading,
                 const std::vector<LineSettings>& lines, const RenderOptions& options,
                 std::vector<PassTiming>* timings = nullptr);

    // The same, and the AOVs options.aovs asks for (their gpu() part) into `aovs`, from the same
    // frame: the same camera and surface as the image.
    Image render(const Camera& camera, const Light& light, const ShadingSelection& shading,
                 const std::vector<LineSettings>& lines, const RenderOptions& options, AovImages& aovs,
                 std::vector<PassTiming>* timings = nullptr);

    // The line drawing alone over options.background, drawn by the pass that strokes render()'s
    // object-space lines, so its pixels are those strokes (`inkshade lines -o x.png`); hidden
    // parts stay SVG-only. Needs no mesh. Throws InputError when the drawing's size is not the
    // image's.
    Image draw_lines(const LineDrawing& drawing, const RenderOptions& options);

    // "llvmpipe (LLVM ...)", "NVIDIA H100 ..." — what GL runs on.
    std::string gl_renderer() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace inkshade
