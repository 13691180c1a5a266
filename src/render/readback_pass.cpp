// `readback`: the resolved colour into the returned image, at the colour target's bit depth
// (RenderOptions::bit_depth: 16 fills Image::rgba16 too).
#include "render/frame.hpp"

namespace inkshade::render {

namespace {

class ReadbackPass final : public Pass {
public:
    // A transparent background: colour divided by alpha (Framebuffer::read).
    void run(Frame& frame) override { frame.image = frame.targets.color->read(frame.options.background.a < 1.0f); }
};

const PassRegistration readback_pass{{
    .name = "readback",
    .stage = Stage::Readback,
    .plan = [](const Frame&) -> std::optional<PassIo> {
        return PassIo{.reads = {Resource::ResolvedColor}, .writes = {Resource::Image}};
    },
    .create = create_pass<ReadbackPass>,
}};

}  // namespace

}  // namespace inkshade::render
