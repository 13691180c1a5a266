// AOVs (arbitrary output variables): per-pixel buffers beside the image for learning — linear
// depth, camera-space normals, object and material ids, the foreground mask, one mask per line
// type — and the camera file that reprojects them (docs/aov.md).
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "inkshade/camera.hpp"
#include "inkshade/mesh.hpp"

namespace inkshade {

enum class Aov : uint8_t {
    Depth,     // float32: distance along the view axis (-z in camera space), 0 = background
    Normal,    // 3 x float32: unit normal in camera space (x right, y up, z towards the viewer)
    Id,        // uint32: object id, connected parts of the mesh from 1 in order of first face
    Material,  // uint32: material index + 1 (1 for a mesh without materials), 0 = background
    Mask,      // uint8: the fraction of the pixel the model covers (MSAA coverage)
    Lines,     // uint8: one mask per line type the image draws, antialiased
    LineSets,  // uint8: one mask per line set the image draws (its lines together), antialiased
    Camera,    // OUT.camera.json alone (every other AOV writes it too)
};

// The AOV names in Aov's order ("depth", "normal", "id", "material", "mask", "lines",
// "lineset-ids", "camera").
const std::vector<std::string>& aov_names();
const char* aov_name(Aov aov);
// The AOV called `name` (any case), or nothing.
std::optional<Aov> aov_named(std::string_view name);

class AovSet {
public:
    constexpr AovSet() = default;
    constexpr void add(Aov a) { bits_ |= bit(a); }
    constexpr bool contains(Aov a) const { return (bits_ & bit(a)) != 0; }
    constexpr bool empty() const { return bits_ == 0; }
    // Those drawn by the renderer's aov pass (depth, normal, id, material, mask).
    constexpr AovSet gpu() const {
        AovSet s;
        s.bits_ = bits_ & (bit(Aov::Depth) | bit(Aov::Normal) | bit(Aov::Id) | bit(Aov::Material) | bit(Aov::Mask));
        return s;
    }
    constexpr bool operator==(const AovSet&) const = default;

private:
    static constexpr uint32_t bit(Aov a) { return uint32_t(1) << unsigned(a); }
    uint32_t bits_ = 0;
};

// The names joined by ',' in Aov's order ("depth,normal"): for job hashes and metadata.
std::string format_aov_set(AovSet set);

struct LineMask {
    std::string type;             // the line type ("contour", "hull", ...)
    std::vector<uint8_t> pixels;  // width x height, 255 = fully covered by the line
    std::string lineset;          // its line set ("" = the style's own [[lines]])
};

// A line's mask name: "lines-TYPE", or "lines-SET-TYPE" for a line of line set SET.
std::string line_mask_name(const std::string& lineset, const std::string& type);

// The line set of the style's own [[lines]] (every face) as masks and files name it.
inline constexpr const char* kDefaultLineSet = "default";

// One line set's lines together (Pencil+ 4's line set ID output).
struct LineSetMask {
    std::string lineset;          // its name (kDefaultLineSet for the style's own [[lines]])
    std::vector<uint8_t> pixels;  // width x height, 255 = fully covered by its lines
};

// The AOVs of one image, each width x height values row-major, top row first (as Image); a
// buffer not asked for is empty.
struct AovImages {
    int width = 0, height = 0;
    std::vector<float> depth;
    std::vector<float> normal;  // 3 per pixel; (0, 0, 0) on the background
    std::vector<uint32_t> id, material;
    std::vector<uint8_t> mask;
    std::vector<LineMask> lines;        // in the order the style draws its line types
    std::vector<LineSetMask> linesets;  // in the order the style draws its line sets
};

// What a camera file records: the camera as framed, the image it made and the model around it.
struct CameraRecord {
    Camera camera;
    int width = 0, height = 0;
    UpAxis up_axis = UpAxis::PosY;
    BoundingBox bounds;  // the model's, world units
};

// Implemented by io. The camera file (docs/aov.md): K (pixels, OpenCV convention), the
// world-to-camera matrix (OpenGL view matrix and the OpenCV one), projection, near/far, image
// size, up axis, model bounds.
std::string format_camera_json(const CameraRecord& record);

// "out/a.png" + "depth" + ".exr" -> "out/a.depth.exr": the files beside an image.
std::string aov_path(const std::string& image_path, const std::string& aov, const std::string& extension);

// Implemented by io. Writes `set`'s files beside `image_path`, each atomically: depth
// (.depth.exr, float32 channel Z), normal (.normal.png, RGB 16 bits, n * 0.5 + 0.5), id and
// material (.id.png, .material.png, gray 16 bits; larger ids are clamped to 65535), mask (.mask.png,
// gray 8 bits), lines (.lines-TYPE.png or .lines-SET-TYPE.png each, gray 8 bits), lineset-ids
// (.lineset-SET.png each, gray 8 bits) and, for any set, the camera file
// (.camera.json). Returns the file names written (without directories), in that order. Throws
// RuntimeError("FILE: reason").
std::vector<std::string> write_aov_files(const std::string& image_path, AovSet set, const AovImages& images,
                                         const CameraRecord& camera);

// The file names write_aov_files writes for `set` (line masks: one for each of `line_masks`,
// line_mask_name's; line-set masks: one for each of `linesets`).
std::vector<std::string> aov_file_names(const std::string& image_path, AovSet set,
                                        const std::vector<std::string>& line_masks,
                                        const std::vector<std::string>& linesets = {});

}  // namespace inkshade
