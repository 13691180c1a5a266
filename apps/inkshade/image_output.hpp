// The image file of `inkshade render` and `inkshade lines -o x.png`: its format by the
// extension, JPEG quality and PNG bit depth, all checked before any work so that a failing run
// leaves no file.
#pragma once
#include <optional>
#include <string>

#include <CLI/CLI.hpp>
#include <glm/glm.hpp>

#include "inkshade/image.hpp"
#include "inkshade/scene.hpp"

namespace inkshade::cli {

// The options that shape an image file.
struct ImageOutputOptions {
    std::optional<int> quality;    // --quality 1..100, JPEG only
    std::optional<int> bit_depth;  // --bit-depth 8|16, PNG only: a scene option (SceneRequest::bit_depth)

    void add_to(CLI::App& cmd);  // --quality
    // Takes the request's bit depth where `cmd` was given --bit-depth.
    void take_bit_depth(const CLI::App& cmd, const SceneRequest& request);
};

struct ImageOutput {
    std::string path;
    ImageFormat format = ImageFormat::Png;
    int quality = 95;   // JPEG
    int bit_depth = 8;  // PNG; the render's too (SceneRequest::bit_depth)
};

// The output `path` with `options` applied. Throws InputError for an extension other than
// .png, .jpg or .jpeg, --quality with PNG and --bit-depth with JPEG.
ImageOutput image_output(const std::string& path, const ImageOutputOptions& options);

// Throws InputError for --quality or --bit-depth given with an output that is no image (SVG).
void refuse_image_options(const ImageOutputOptions& options);

// JPEG has no alpha: throws InputError when `background` is not opaque.
void check_background(const ImageOutput& output, const glm::vec4& background);

// Writes `image` as `output` asks, atomically. Throws RuntimeError.
void write_image(const ImageOutput& output, const Image& image);

}  // namespace inkshade::cli
