#include "render/frame_targets.hpp"

#include <algorithm>

namespace inkshade::render {

gpu::Framebuffer& FrameTargets::color_for(int width, int height, int samples, int bit_depth) {
    if (!color || color->width() != width || color->height() != height || color->samples() != std::max(1, samples) ||
        color->bit_depth() != bit_depth) {
        color.reset();  // the old one goes first: two full-size targets are never held at once
        color = std::make_unique<gpu::Framebuffer>(width, height, samples, bit_depth);
    }
    return *color;
}

}  // namespace inkshade::render
