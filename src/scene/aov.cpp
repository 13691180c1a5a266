// The scene's AOVs (inkshade/aov.hpp): the renderer's buffers from the image's frame, and one
// mask per line type, and per line set, drawn by a frame of its own.
#include <optional>

#include "inkshade/scene.hpp"

namespace inkshade {

namespace {

// Lines `lines` alone, white, over a black surface and background: the red channel is their
// coverage, antialiased by the image's MSAA, with the lines' own opacity.
// `before`: the scene's stroke sequence as the image's frame found it, so a coherent line's mask
// has the image's dashes (a copy each: the mask frames do not advance the sequence).
std::vector<uint8_t> line_mask(Renderer& renderer, const Scene& scene, const Camera& camera, const Light& light,
                               std::vector<LineSettings> lines, const StrokeSequence* before) {
    for (LineSettings& white : lines) white.params["color"] = {1.0f, 1.0f, 1.0f};
    // Black whatever the mesh's colours, textures or unlit materials: they multiply the base colour.
    ShadingSelection black{
        .model = "lambert", .params = {}, .base_color = glm::vec3(0.0f), .base_color_use = BaseColorUse::Multiply};
    Light dark = light;
    dark.color = glm::vec3(0.0f);
    dark.ambient = glm::vec3(0.0f);
    RenderOptions options = scene.options;
    options.background = {0.0f, 0.0f, 0.0f, 1.0f};
    options.srgb_output = false;  // coverage, not a colour to encode
    options.bit_depth = 8;
    options.aovs = {};
    StrokeSequence sequence = before ? *before : StrokeSequence{};
    options.stroke_sequence = before ? &sequence : nullptr;
    const Image image = renderer.render(camera, dark, black, lines, options);
    std::vector<uint8_t> mask(size_t(image.width) * size_t(image.height));
    for (size_t i = 0; i < mask.size(); ++i) mask[i] = image.rgba[4 * i];
    return mask;
}

}  // namespace

Image render_scene(Renderer& renderer, const Scene& scene, const Camera& camera, const Light& light, AovImages& aovs,
                   std::vector<PassTiming>* timings) {
    aovs = {};
    RenderOptions options = scene.options;
    options.time = scene.time;  // mtoon's UV animation
    const bool masks = scene.aovs.contains(Aov::Lines) || scene.aovs.contains(Aov::LineSets);
    std::optional<StrokeSequence> before;
    if (masks && options.stroke_sequence) before = *options.stroke_sequence;
    Image image = renderer.render(camera, light, scene.shading(), scene.style.lines, options, aovs, timings);
    aovs.width = image.width;
    aovs.height = image.height;
    const StrokeSequence* first = before ? &*before : nullptr;
    if (scene.aovs.contains(Aov::Lines))
        for (const LineSettings& line : scene.style.lines)
            aovs.lines.push_back({line.type, line_mask(renderer, scene, camera, light, {line}, first), line.lineset});
    if (scene.aovs.contains(Aov::LineSets))
        for (const std::string& set : line_set_names(scene.style.lines)) {
            std::vector<LineSettings> lines;
            for (const LineSettings& l : scene.style.lines)
                if (l.lineset == set) lines.push_back(l);
            aovs.linesets.push_back(
                {set.empty() ? kDefaultLineSet : set, line_mask(renderer, scene, camera, light, lines, first)});
        }
    return image;
}

CameraRecord camera_record(const Scene& scene, const Camera& camera, const BoundingBox& bounds) {
    return {.camera = camera,
            .width = scene.options.width,
            .height = scene.options.height,
            .up_axis = scene.camera.up_axis.value_or(UpAxis::PosY),
            .bounds = bounds};
}

}  // namespace inkshade
