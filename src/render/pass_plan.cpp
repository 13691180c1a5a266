#include "render/pass_plan.hpp"

#include <algorithm>

#include "render/frame.hpp"

namespace inkshade::render {

namespace {

struct Step {
    PlannedPass pass;
    PassIo io;
};

}  // namespace

PassPlan plan_passes(const Frame& frame, bool before_upload) {
    std::vector<Step> steps;
    for (const PassType* type : pass_types())
        if (std::optional<PassIo> io = type->plan(frame))
            steps.push_back({{type, io->writes.contains(Resource::Color) ? PassTarget::Color : PassTarget::Own}, *io});

    // Culling: walking back from the image and the AOVs, a pass stays when a pass after it reads
    // what it writes.
    Resources needed{Resource::Image, Resource::Aov};
    std::vector<Step> kept;
    for (auto it = steps.rbegin(); it != steps.rend(); ++it) {
        if (!it->io.writes.intersects(needed)) continue;
        needed |= it->io.reads;
        kept.insert(kept.begin(), *it);
    }

    // Per-pixel passes after the resolve, the last first so that they keep their order.
    const auto resolve = std::find_if(kept.begin(), kept.end(),
                                      [](const Step& s) { return s.io.writes.contains(Resource::ResolvedColor); });
    if (resolve != kept.end()) {
        size_t resolve_at = size_t(resolve - kept.begin());
        for (size_t i = resolve_at; i-- > 0;) {
            if (!kept[i].pass.type->per_pixel) continue;
            const bool color_drawn_later =
                std::any_of(kept.begin() + std::ptrdiff_t(i) + 1, kept.begin() + std::ptrdiff_t(resolve_at),
                            [](const Step& s) { return s.io.writes.contains(Resource::Color); });
            if (color_drawn_later) continue;
            Step moved = kept[i];
            moved.pass.target = PassTarget::ResolvedColor;
            kept.erase(kept.begin() + std::ptrdiff_t(i));
            --resolve_at;
            kept.insert(kept.begin() + std::ptrdiff_t(resolve_at) + 1, moved);
        }
    }

    PassPlan plan;
    for (const Step& s : kept) {
        plan.reads |= s.io.reads;
        const bool early = before_upload && s.io.reads.contains(Resource::MeshLineData);
        (early ? plan.before_upload : plan.passes).push_back(s.pass);
    }
    return plan;
}

}  // namespace inkshade::render
