// `radial-curvature`: the per-vertex radial curvature κr of the current view, computed on the
// CPU from the Rusinkiewicz 2004 curvatures (LineExtractor::radial_curvature), read as v_kr
// (the `kr` debug view); and its pass, which computes it each frame from the mesh-wide line data.
#include "render/frame.hpp"
#include "render/shading_inputs.hpp"

namespace inkshade::render {

namespace {

constexpr const char* kName = "radial-curvature";

std::vector<float> radial_curvature(const Frame& frame) { return frame.line_extractor.radial_curvature(frame.camera); }

const VertexAttributeRegistration radial_curvature_attribute{{
    .name = kName,
    .glsl = "kr",
    .per_view = true,
    .compute = radial_curvature,
}};

class RadialCurvaturePass final : public Pass {
public:
    void run(Frame& frame) override { frame.view_attributes[kName] = radial_curvature(frame); }
};

// Runs for a model that declares the attribute (the shading pass then reads ViewAttributes).
const PassRegistration radial_curvature_pass{{
    .name = kName,
    .stage = Stage::Attributes,
    .plan = [](const Frame& frame) -> std::optional<PassIo> {
        if (!reads_attribute(frame, kName)) return std::nullopt;
        return PassIo{.reads = {Resource::MeshLineData}, .writes = {Resource::ViewAttributes}};
    },
    .create = create_pass<RadialCurvaturePass>,
}};

}  // namespace

}  // namespace inkshade::render
