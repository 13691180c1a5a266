// A labelled grid of images (the demo's contact sheet), drawn on the CPU.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "inkshade/image.hpp"

namespace inkshade {

struct LabelledImage {
    std::string label;
    Image image;
};

// Tiles the images (all the same size) `columns` per row on a white sheet with a caption
// under each tile, drawn with stb_easy_font at `text_scale` pixels per font unit.
Image contact_sheet(const std::vector<LabelledImage>& tiles, int columns, int text_scale = 2);

// The top-left pixel of tile `index` on the sheet contact_sheet makes of `count` tiles of
// `tile_size` pixels, `columns` a row: the tile's image covers `tile_size` pixels from there.
glm::ivec2 contact_sheet_tile_origin(size_t index, size_t count, int columns, glm::ivec2 tile_size, int text_scale = 2);

}  // namespace inkshade
