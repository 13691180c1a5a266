// Render passes. Each pass type registers itself from the file that implements it (as line types
// and shading models do), with what it reads and writes in a frame and the stage it runs in;
// Renderer::render plans the passes a frame needs (render/pass_plan.hpp) and runs them. The
// declared resources follow the frame graph of Filament and Frostbite (O'Donnell 2017, "FrameGraph:
// Extensible Rendering Architecture in Frostbite") in miniature: no graph compiler, only a
// culling of passes whose output nothing reads, and two moves: passes that read MeshLineData
// run before the GL upload under MeshUse::OneFrame, and per-pixel passes go after the resolve
// when they can (PassType::per_pixel).
//
// Adding a raster line type or a post pass: one file that registers the LineType and its
// PassType, plus its shader.
#pragma once
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace inkshade::render {

struct Frame;

// What passes hand each other within a frame (and, for the shadow map and the line data,
// between frames). Frame (render/frame.hpp) holds them.
enum class Resource : uint8_t {
    MeshLineData,        // the object-space lines' mesh-wide CPU data (LineExtractor)
    GpuMesh,             // the mesh's GL buffers
    ViewAttributes,      // per-vertex attributes of this view a model declares (radial curvature)
    ShadowMap,           // depth from the light (kept while the mesh and the light stay)
    Color,               // the multisampled colour, depth and stencil target
    GBuffer,             // the single-sample geometry buffer of image-space lines
    GBufferFaceNormals,  // its face-normal target (written only when some pass reads it)
    LineDrawing,         // object-space lines as image polylines
    ResolvedColor,       // the single-sample colour the image is read from
    Image,               // the returned image
    Aov,                 // the AOV buffers (RenderOptions::aovs), returned beside the image
    FieldSamples,        // the surface fields' interpolation, running beside the shading
};

// A set of resources.
class Resources {
public:
    constexpr Resources() = default;
    constexpr Resources(std::initializer_list<Resource> list) {
        for (Resource r : list) bits_ |= bit(r);
    }
    constexpr bool contains(Resource r) const { return (bits_ & bit(r)) != 0; }
    constexpr bool intersects(Resources other) const { return (bits_ & other.bits_) != 0; }
    constexpr Resources& operator|=(Resources other) {
        bits_ |= other.bits_;
        return *this;
    }
    constexpr bool operator==(const Resources&) const = default;

private:
    static constexpr uint32_t bit(Resource r) { return uint32_t(1) << unsigned(r); }
    uint32_t bits_ = 0;
};

// What a pass reads and writes in one frame.
struct PassIo {
    Resources reads;
    Resources writes;
};

// When a pass runs: stages in this order, the passes of one stage by name.
enum class Stage : uint8_t {
    Shadow,        // light-space depth
    Attributes,    // per-view vertex data (radial curvature)
    FieldSamples,  // the face at each pixel for the surface fields (their own target)
    Shading,       // the shading model into Color (clears it)
    MeshLines,     // the mesh drawn again over the shading (hull, threejs-outline)
    GBuffer,       // geometry buffers for image-space lines
    ImageLines,    // full-screen passes over the G-buffer
    VectorLines,   // object-space lines as image polylines (CPU)
    Strokes,       // polylines drawn as strokes
    Resolve,       // Color to ResolvedColor
    Readback,      // ResolvedColor to Image
    Aov,           // AOV buffers drawn and read back (their own targets)
};

// A pass's GL objects and caches, made on first use and kept by the renderer.
class Pass {
public:
    virtual ~Pass() = default;
    // Draws or computes what the pass writes. A pass that writes Color (or ResolvedColor, when
    // moved after the resolve) finds that target bound; any other binds its own.
    virtual void run(Frame& frame) = 0;
};

struct PassType {
    std::string name;  // also its PassTiming name (`inkshade render --timing`)
    Stage stage = Stage::Shading;
    // What the pass reads and writes in `frame`, or nullopt when the frame does not ask for it
    // (its line type is not in the style, its map is still valid). A planned pass whose writes
    // no later planned pass reads is culled, so producers (the G-buffer, the shadow map) run
    // only for their readers.
    std::optional<PassIo> (*plan)(const Frame& frame) = nullptr;
    // Shades each pixel once, without depth or stencil: drawn onto ResolvedColor after the
    // resolve when no later pass draws into Color (one blend a pixel instead of one a sample,
    // the same bytes).
    bool per_pixel = false;
    std::unique_ptr<Pass> (*create)() = nullptr;
};

// `static const PassRegistration reg{{...}};` in the pass's file.
struct PassRegistration {
    explicit PassRegistration(PassType type);
};

// For PassType::create.
template <class T>
std::unique_ptr<Pass> create_pass() {
    return std::make_unique<T>();
}

// Every registered pass type, by stage, then name.
std::vector<const PassType*> pass_types();

}  // namespace inkshade::render
