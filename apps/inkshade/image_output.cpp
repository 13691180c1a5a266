#include "image_output.hpp"

#include "inkshade/error.hpp"

namespace inkshade::cli {

namespace {

const char* const kQualityOnlyJpeg = "--quality: applies to .jpg and .jpeg output only";
const char* const kBitDepthOnlyPng = "--bit-depth: applies to .png output only";

}  // namespace

void ImageOutputOptions::add_to(CLI::App& cmd) {
    cmd.add_option("--quality", quality, "JPEG quality 1..100 (default 95)")->check(CLI::Range(1, 100));
}

void ImageOutputOptions::take_bit_depth(const CLI::App& cmd, const SceneRequest& request) {
    if (cmd.count("--bit-depth")) bit_depth = request.bit_depth;
}

ImageOutput image_output(const std::string& path, const ImageOutputOptions& options) {
    ImageOutput out{.path = path, .format = image_format_of(path)};
    if (options.quality && out.format != ImageFormat::Jpeg) throw InputError(kQualityOnlyJpeg);
    if (options.bit_depth && out.format != ImageFormat::Png) throw InputError(kBitDepthOnlyPng);
    out.quality = options.quality.value_or(95);
    out.bit_depth = options.bit_depth.value_or(8);  // make_scene checks the value
    return out;
}

void refuse_image_options(const ImageOutputOptions& options) {
    if (options.quality) throw InputError(kQualityOnlyJpeg);
    if (options.bit_depth) throw InputError(kBitDepthOnlyPng);
}

void check_background(const ImageOutput& output, const glm::vec4& background) {
    if (output.format == ImageFormat::Jpeg && background.a < 1.0f)
        throw InputError(output.path + ": JPEG has no transparency; write .png for a transparent background");
}

void write_image(const ImageOutput& output, const Image& image) {
    if (output.format == ImageFormat::Jpeg)
        write_jpeg(output.path, image, output.quality);
    else
        write_png(output.path, image, output.bit_depth);
}

}  // namespace inkshade::cli
