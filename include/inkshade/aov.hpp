// AOVs (arbitrary output variables): per-pixel buffers beside the image for learning — linear
// depth, camera-space normals, object and material ids, the foreground mask, one mask per line
// type — and the camera file that reprojects them (docs/aov.md).
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
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
    // The surface fields (float32, before any threshold, 0 on the background; docs/aov.md):
    Ndotv,  // n·v: interpolated smooth normal, per-pixel view vector
    Kr,     // radial curvature κr (DeCarlo et al. 2003)
    Dwkr,   // D_w κr, its derivative along the projected view vector
    K1,     // principal curvatures, k1 >= k2 (Rusinkiewicz 2004)
    K2,
    Pdir1,  // 2 x float32: the principal directions in image space, unit (x right, y down)
    Pdir2,
    ShadingScales,  // Lambert n·l with normals smoothed at kShadingScales widths
    Camera,         // OUT.camera.json alone (every other AOV writes it too)
};

// The AOV names in Aov's order ("depth", "normal", "id", "material", "mask", "lines",
// "lineset-ids", "ndotv", "kr", "dwkr", "k1", "k2", "pdir1", "pdir2", "shading-scales", "camera").
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
    // Those made by the renderer's aov pass (depth, normal, id, material, mask, the surface fields).
    constexpr AovSet gpu() const {
        AovSet s = fields();
        s.bits_ |= bits_ & (bit(Aov::Depth) | bit(Aov::Normal) | bit(Aov::Id) | bit(Aov::Material) | bit(Aov::Mask));
        return s;
    }
    // The surface fields (ndotv ... shading-scales), computed from the visible face at each pixel.
    constexpr AovSet fields() const {
        AovSet s;
        for (Aov a : {Aov::Ndotv, Aov::Kr, Aov::Dwkr, Aov::K1, Aov::K2, Aov::Pdir1, Aov::Pdir2, Aov::ShadingScales})
            if (contains(a)) s.add(a);
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

// The widths of the shading-scales AOV (OUT.shading-s0.png, ...).
inline constexpr int kShadingScales = 5;

// What makes the surface fields comparable across meshes and views (the camera file's
// "fields"): rtsc's feature size of the mesh (world units), the 90th percentile of |value| over
// the visible pixels of each curvature field asked for (Neural Contours divides by it), and the
// smoothing widths of shading-scales (world units, finest first).
struct FieldScales {
    float feature_size = 0.0f;
    std::vector<std::pair<std::string, float>> p90;  // ("kr", ...) in Aov's order
    std::vector<float> shading_sigmas;
    bool empty() const { return feature_size == 0.0f && p90.empty() && shading_sigmas.empty(); }
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
    // The surface fields: one float per pixel (pdir1, pdir2: two), 0 on the background.
    std::vector<float> ndotv, kr, dwkr, k1, k2, pdir1, pdir2;
    std::vector<std::vector<float>> shading;  // shading-scales: n·l in [0, 1] per width, finest first
    FieldScales field_scales;                 // with any field
};

// The buffer of a surface field (`aov` one of AovSet::fields() but shading-scales), and its
// floats per pixel.
std::vector<float>& field_buffer(AovImages& images, Aov aov);
const std::vector<float>& field_buffer(const AovImages& images, Aov aov);
int field_channels(Aov aov);

// What a camera file records: the camera as framed, the image it made and the model around it.
struct CameraRecord {
    Camera camera;
    int width = 0, height = 0;
    UpAxis up_axis = UpAxis::PosY;
    BoundingBox bounds;  // the model's, world units
    FieldScales fields;  // with a surface field: written as "fields"
};

// Implemented by io. The camera file (docs/aov.md): K (pixels, OpenCV convention), the
// world-to-camera matrix (OpenGL view matrix and the OpenCV one), projection, near/far, image
// size, up axis, model bounds.
std::string format_camera_json(const CameraRecord& record);

// Implemented by io. The camera file's "fields" as JSON text: {"feature_size": ..., "p90":
// {"kr": ..., ...}, "shading_sigmas": [...]}, members absent when not computed.
std::string format_field_scales(const FieldScales& scales);

// "out/a.png" + "depth" + ".exr" -> "out/a.depth.exr": the files beside an image.
std::string aov_path(const std::string& image_path, const std::string& aov, const std::string& extension);

// Implemented by io. Writes `set`'s files beside `image_path`, each atomically: depth
// (.depth.exr, float32 channel Z), normal (.normal.png, RGB 16 bits, n * 0.5 + 0.5), id and
// material (.id.png, .material.png, gray 16 bits; larger ids are clamped to 65535), mask (.mask.png,
// gray 8 bits), lines (.lines-TYPE.png or .lines-SET-TYPE.png each, gray 8 bits), lineset-ids
// (.lineset-SET.png each, gray 8 bits), the surface fields (.NAME.exr, float32 channel Y, or X
// and Y for pdir1/pdir2), shading-scales (.shading-s0.png ..., gray 16 bits) and, for any set,
// the camera file (.camera.json, with images.field_scales as "fields"). Returns the file names written (without
// directories), in that order. Throws RuntimeError("FILE: reason").
std::vector<std::string> write_aov_files(const std::string& image_path, AovSet set, const AovImages& images,
                                         const CameraRecord& camera);

// The file names write_aov_files writes for `set` (line masks: one for each of `line_masks`,
// line_mask_name's; line-set masks: one for each of `linesets`).
std::vector<std::string> aov_file_names(const std::string& image_path, AovSet set,
                                        const std::vector<std::string>& line_masks,
                                        const std::vector<std::string>& linesets = {});

}  // namespace inkshade
