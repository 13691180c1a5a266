// One Renderer::render call as its passes see it: what to draw, the scene, and the resources
// (render/pass.hpp) passes hand each other.
#pragma once
#include <future>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "inkshade/aov.hpp"
#include "inkshade/camera.hpp"
#include "inkshade/image.hpp"
#include "inkshade/line_drawing.hpp"
#include "inkshade/renderer.hpp"
#include "render/field_vertices.hpp"
#include "render/frame_targets.hpp"
#include "render/gpu_mesh.hpp"
#include "render/pass.hpp"

namespace inkshade::render {

struct Frame {
    // What to draw.
    const Camera& camera;
    const Light& light;
    const ShadingSelection& shading;
    const ShadingModel& model;
    const RenderOptions& options;
    const std::vector<LineSettings>& lines;  // the style's, image- and object-space

    // The scene.
    const BoundingBox& bounds;
    float edge_length = 0.0f;       // the mesh's typical edge length, world units (render/edge_length.hpp)
    bool closed = false;            // closed and outward (back faces invisible from outside)
    bool cull_back_faces = false;   // closed and wholly in front of the near plane (cull_back_faces())
    LineExtractor& line_extractor;  // MeshLineData
    const Mesh& cpu_mesh;           // positions, triangles and normals (colours dropped after the upload)
    GpuMesh* mesh = nullptr;        // GpuMesh: null until the upload (MeshUse::OneFrame)
    FrameTargets& targets;          // Color, ResolvedColor, ShadowMap, GBuffer
    Resources reads;                // what the planned passes read (PassPlan::reads)

    // Made during the frame.
    std::vector<LineSettings> object_lines;                     // the style's object-space lines, in order
    std::optional<LineDrawing> drawing;                         // LineDrawing
    std::map<std::string, std::vector<float>> view_attributes;  // ViewAttributes, by provider
    Image image;                                                // Image
    AovImages* aovs = nullptr;                                  // Aov: where options.aovs go (null: none asked)
    std::optional<FieldVertices> field_vertices;                // ViewAttributes: the surface fields' (fields pass)

    // FieldSamples: the surface fields' interpolation into *aovs, on a worker while the passes
    // after field-samples run; the aov pass waits for it. Last, so that it is destroyed (which
    // waits) before anything the task reads.
    std::future<void> field_interpolation;

    // The style's settings of line type `type` (the last when listed twice), or null.
    const LineSettings* line(const std::string& type) const;
    float aspect() const { return float(options.width) / float(options.height); }
};

// The object-space lines of `lines`, in order, asking for their visible parts only (what the
// strokes draw; hidden ones are SVG-only), then `border` in the hull's stroke (rims shorter
// than max(4 widths, 16 px) dropped) when `lines` has a hull with `borders` on and no border of
// its own and the mesh `may_have_borders` (it is not closed). Throws InputError for an unknown
// line type.
std::vector<LineSettings> object_lines_of(const std::vector<LineSettings>& lines, bool may_have_borders);

// Back faces may be culled only when none can be seen: a closed outward surface with the
// whole bounding box in front of the near plane (the camera outside, nothing clipped open).
bool cull_back_faces(bool closed, const BoundingBox& bounds, const Camera& camera);

}  // namespace inkshade::render
