// The GPU targets passes draw into, kept between frames: made on first use and again only when
// the image size changes.
#pragma once
#include <memory>
#include <optional>

#include <glm/glm.hpp>

#include "gpu/framebuffer.hpp"
#include "render/gbuffer.hpp"
#include "render/shadow_map.hpp"

namespace inkshade::render {

struct FrameTargets {
    std::unique_ptr<gpu::Framebuffer> color;  // Color and ResolvedColor: the image's size
    std::unique_ptr<GBuffer> gbuffer;         // GBuffer: the image's size
    // ShadowMap depends only on the mesh and the light: it is kept while both stay (new views of
    // one model under one light, as batch and the viewer render).
    std::unique_ptr<ShadowMap> shadow_map;
    std::optional<glm::mat4> shadow_light;  // the light view-projection it holds; none: stale

    // The colour target for `options`: kept when its size, samples and bit depth match.
    gpu::Framebuffer& color_for(int width, int height, int samples, int bit_depth);
};

}  // namespace inkshade::render
