// A labelled grid of images (the demo's contact sheet), drawn on the CPU.
#pragma once
#include <string>
#include <vector>

#include "inkshade/image.hpp"

namespace inkshade {

struct LabelledImage {
    std::string label;
    Image image;
};

// Tiles the images (all the same size) `columns` per row on a white sheet with a caption
// under each tile, drawn with stb_easy_font at `text_scale` pixels per font unit.
Image contact_sheet(const std::vector<LabelledImage>& tiles, int columns, int text_scale = 2);

}  // namespace inkshade
