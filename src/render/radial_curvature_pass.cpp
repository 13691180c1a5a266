// `radial-curvature`: the per-vertex radial curvature of the current view, computed on the CPU
// (LineExtractor::radial_curvature) for models that read it (the `kr` debug view).
#include "render/frame.hpp"

namespace inkshade::render {

namespace {

class RadialCurvaturePass final : public Pass {
public:
    void run(Frame& frame) override { frame.set_vertex_scalar(frame.line_extractor.radial_curvature(frame.camera)); }
};

// Runs when the shading pass reads VertexScalar (ShadingModel::radial_curvature).
const PassRegistration radial_curvature_pass{{
    .name = "radial-curvature",
    .stage = Stage::Attributes,
    .plan = [](const Frame&) -> std::optional<PassIo> {
        return PassIo{.reads = {Resource::MeshLineData}, .writes = {Resource::VertexScalar}};
    },
    .create = create_pass<RadialCurvaturePass>,
}};

}  // namespace

}  // namespace inkshade::render
