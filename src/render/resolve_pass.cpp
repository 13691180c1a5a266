// `resolve`: the multisampled colour target into the single-sample one the image is read from.
#include "render/frame.hpp"

namespace inkshade::render {

namespace {

class ResolvePass final : public Pass {
public:
    void run(Frame& frame) override { frame.targets.color->resolve(); }
};

const PassRegistration resolve_pass{{
    .name = "resolve",
    .stage = Stage::Resolve,
    .plan = [](const Frame&) -> std::optional<PassIo> {
        return PassIo{.reads = {Resource::Color}, .writes = {Resource::ResolvedColor}};
    },
    .create = create_pass<ResolvePass>,
}};

}  // namespace

}  // namespace inkshade::render
