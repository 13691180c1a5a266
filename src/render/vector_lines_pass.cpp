// `vector-lines`: the style's object-space lines extracted on the CPU (ray-cast visibility) as
// image polylines, for the strokes pass (render/stroke_pass.hpp).
#include "render/frame.hpp"

namespace inkshade::render {

namespace {

class VectorLinesPass final : public Pass {
public:
    void run(Frame& frame) override {
        frame.drawing = frame.line_extractor.draw(frame.camera, frame.options.width, frame.options.height,
                                                  frame.object_lines, nullptr, frame.options.stroke_sequence,
                                                  {.light = frame.light, .section = std::nullopt});
    }
};

// Runs when the strokes pass reads LineDrawing.
const PassRegistration vector_lines_pass{{
    .name = "vector-lines",
    .stage = Stage::VectorLines,
    .plan = [](const Frame&) -> std::optional<PassIo> {
        return PassIo{.reads = {Resource::MeshLineData}, .writes = {Resource::LineDrawing}};
    },
    .create = create_pass<VectorLinesPass>,
}};

}  // namespace

}  // namespace inkshade::render
