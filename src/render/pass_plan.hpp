// Which registered passes a frame runs, in what order and into which target.
#pragma once
#include <vector>

#include "render/pass.hpp"

namespace inkshade::render {

// Where a pass draws: the runner binds it before the pass runs.
enum class PassTarget : uint8_t {
    Own,            // nothing bound for it (it binds its own target, or draws nothing)
    Color,          // the multisampled target
    ResolvedColor,  // the resolved image (a per-pixel pass moved after the resolve)
};

struct PlannedPass {
    const PassType* type = nullptr;
    PassTarget target = PassTarget::Own;
};

struct PassPlan {
    // MeshUse::OneFrame, first frame: the passes that read MeshLineData, run before the GL
    // upload so that data is freed before the GL buffers exist (the two memory peaks do not add up).
    std::vector<PlannedPass> before_upload;
    std::vector<PlannedPass> passes;  // the rest, in order
    Resources reads;                  // everything the planned passes read
};

// Plans `frame`'s passes: each registered type's plan(frame), in stage order; passes whose
// writes no later planned pass reads are culled (walking back from Image); per-pixel passes with
// no later pass drawing into Color move after the resolve; with `before_upload` (no GPU mesh
// yet) the readers of MeshLineData go first.
PassPlan plan_passes(const Frame& frame, bool before_upload);

}  // namespace inkshade::render
