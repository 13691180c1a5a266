// The indexed triangle mesh every part of Inkshade works on.
#pragma once
#include <bit>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <cmath>

#include <glm/glm.hpp>

#include "inkshade/file_scene.hpp"

namespace inkshade {

// A decoded base-colour texture (glTF baseColorTexture, MTL map_Kd, PLY `comment TextureFile`).
// Colour space: the RGB bytes are sRGB-encoded, as glTF 2.0 section 3.9.2 requires of base
// colour textures and as every image editor writes them. The renderer reads them in the
// output's colour convention: as stored when the output is written unencoded (the default),
// decoded to linear light when it is sRGB-encoded (docs/shading.md). Alpha is linear.
// Orientation: rows are stored top row of the image first (as in the file and inkshade::Image),
// while Mesh::uvs follow the OBJ/OpenGL convention (v = 0 at the BOTTOM of the image), so
// texel row = (1 - v) * height. Uploaded as is with glTexImage2D (row 0 at t = 0), sample at
// vec2(u, 1 - v). Sampling: `sampler` (a glTF texture's sampler, as three.js's GLTFLoader sets it).

enum class TextureWrap { Repeat, ClampToEdge, MirroredRepeat };
enum class TextureFilter { Nearest, Linear };

// How a texture is read (glTF 2.0 section 5.26 samplers). The default is Inkshade's for files
// that say nothing (OBJ, PLY): repeat, trilinear, anisotropic where the driver has it. A glTF
// texture takes its sampler's values with three.js's defaults for the absent ones (magnify
// linear, minify linear between linear mip levels, repeat) and, as three.js, no anisotropy.
struct TextureSampler {
    TextureWrap wrap_s = TextureWrap::Repeat, wrap_t = TextureWrap::Repeat;
    TextureFilter mag = TextureFilter::Linear;
    TextureFilter min = TextureFilter::Linear;  // within a mip level
    // Between mip levels; none: level 0 only (glTF minFilter NEAREST or LINEAR).
    std::optional<TextureFilter> mipmap = TextureFilter::Linear;
    bool anisotropic = true;
    bool operator==(const TextureSampler&) const = default;
};

struct Texture {
    std::string source;  // file path, or "FILE#image N" for an image embedded in a glTF/GLB
    int width = 0;
    int height = 0;
    std::vector<uint8_t> rgba;  // width * height * 4 bytes, row-major, top row first
    TextureSampler sampler;
};

// glTF 2.0 section 3.9.4 alpha modes: alpha ignored (OPAQUE), a cut-out where alpha is below
// the cutoff (MASK), or blended over what lies behind (BLEND).
enum class AlphaMode { Opaque, Mask, Blend };

// Which faces of a material are drawn and how their back faces are lit: both, each lit as the
// side the viewer sees (Inkshade's default for formats that say nothing); front faces only
// (glTF doubleSided false, three.js FrontSide); both, back faces lit with the normal negated
// (glTF doubleSided true, three.js DoubleSide).
enum class FaceSides { Seen, Front, Double };

struct Material {
    std::string name;
    glm::vec3 diffuse{0.8f, 0.8f, 0.8f};  // MTL Kd / glTF baseColorFactor.rgb, linear (glTF 2.0 §3.9.2)
    // Base-colour texture multiplying `diffuse` (or the vertex colour); null = none. Shared:
    // copies of a Material (and materials using the same image) cost no pixel copies.
    std::shared_ptr<const Texture> texture;
    // MToon parameters of a VRM material (VRM 0.x extensions.VRM.materialProperties, converted as
    // three-vrm does, or VRM 1.0 VRMC_materials_mtoon with the glTF material's emissive and normal
    // map scale; io/vrm_materials.hpp), keyed by the `mtoon` shading model's parameter names:
    // shade-color (3), shading-shift, shading-toony, shading-shift-texture-scale, rim-color (3),
    // rim-fresnel-power, rim-lift, rim-lighting-mix, outline-width-mode (0 none, 1 world,
    // 2 screen), outline-width, outline-color (3), outline-lighting-mix, matcap-color (3),
    // emissive (3), emissive-intensity, normal-scale, uv-animation-scroll-x-speed,
    // uv-animation-scroll-y-speed, uv-animation-rotation-speed, plus gi-equalization.
    // Colours linear. Empty = not an MToon material.
    std::map<std::string, std::vector<float>> mtoon;
    // The textures of a VRM MToon material (VRMC_materials_mtoon's matcapTexture,
    // rimMultiplyTexture, outlineWidthMultiplyTexture, shadeMultiplyTexture, shadingShiftTexture,
    // uvAnimationMaskTexture and the glTF emissiveTexture and normalTexture; VRM 0.x _SphereAdd,
    // _RimTexture, _OutlineWidthTexture, _ShadeTexture, _UvAnimMaskTexture, _EmissionMap,
    // _BumpMap), keyed as render/mtoon_textures.hpp's slots ("matcap-texture",
    // "rim-multiply-texture", "outline-width-multiply-texture", "shade-multiply-texture",
    // "shading-shift-texture", "emissive-texture", "normal-texture", "uv-animation-mask-texture");
    // read at the mesh's uvs moved by the UV animation (the matcap at the view-space normal, the
    // mask and the outline width at the uvs as they are). Shared as `texture` is.
    std::map<std::string, std::shared_ptr<const Texture>> mtoon_textures;
    // Per texture, the uv transform of its glTF KHR_texture_transform (VRM 0.x: the _MainTex
    // scale and offset, ported as three-vrm ports them) as three.js applies it
    // (io/texture_transform.hpp), keyed "base-color-texture" or as mtoon_textures; absent =
    // identity. Applied to the uvs in glTF's convention (t down) after mtoon's UV animation.
    std::map<std::string, glm::mat3> uv_transforms;
    // glTF KHR_materials_unlit: drawn in its base colour (x texture x vertex colour) without
    // lighting, whatever the shading model.
    bool unlit = false;
    // Coverage (glTF baseColorFactor.a, times the texture's alpha), what it does, and the sides.
    float alpha = 1.0f;
    AlphaMode alpha_mode = AlphaMode::Opaque;
    float alpha_cutoff = 0.5f;  // MASK: kept where alpha >= cutoff (three.js alphaTest)
    FaceSides sides = FaceSides::Seen;
    // BLEND: depth written too (VRMC_materials_mtoon transparentWithZWrite; glTF BLEND writes none,
    // as three.js's GLTFLoader sets depthWrite false), and the draw order among blended materials,
    // lowest first (three.js Object3D.renderOrder, which three-vrm sets to renderQueueOffsetNumber
    // plus 19 without z-write, 0 with it, for MToon materials).
    bool blend_depth_write = false;
    int render_order = 0;
};

// All three coordinates finite (no NaN, no infinity): what the loaders, welding, normals and
// the line code accept as a point or a direction.
inline bool is_finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

struct BoundingBox {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
    glm::vec3 center() const { return 0.5f * (min + max); }
    float diagonal() const { return glm::length(max - min); }
};

// How vertex normals computed for a file without normals weight the faces around a vertex:
// by their angle there (Thürmer & Wüthrich 1998; Inkshade's default, independent of the
// triangulation), or by their area, as three.js's BufferGeometry.computeVertexNormals does (it
// sums the unnormalised cross products), for renders in three.js's convention.
enum class NormalWeighting { Angle, Area };

// The shading normals of a mesh's hard edges, stored only where a hard edge splits a vertex:
// the faces around a vertex, joined across its smooth edges, form fans; at a vertex of several
// fans ("split") each fan has its own normal, and every other vertex keeps its smooth normal
// (Mesh::normals). Memory: a bit per vertex, plus a few words per split vertex and per face
// corner there. Shading normal ids number the fans vertex by vertex (one id for a vertex of one
// fan): id(v, fan) = v + (fans beyond the first at split vertices before v) + fan.
struct ShadingSplits {
    static constexpr uint32_t kNone = ~0u;
    size_t triangle_count = 0;           // of the mesh they were made for
    std::vector<uint64_t> split;         // bit v % 64 of word v / 64: vertex v is split
    std::vector<uint32_t> rank;          // per word: split vertices before it
    std::vector<uint32_t> extra;         // per split vertex, and one more: fans beyond the first before it
    std::vector<uint32_t> corner_start;  // per split vertex, and one more: its range in corner_face/corner_fan
    std::vector<uint32_t> corner_face;   // the faces at the split vertex, ascending (a face twice
                                         // at a repeated index: its first listing counts)
    std::vector<uint32_t> corner_fan;    // the fan of each
    std::vector<glm::vec3> normals;      // fan i of split vertex `slot` at extra[slot] + slot + i

    bool empty() const { return split.empty(); }
    // Vertex v's index among the split vertices, kNone when it is not split.
    uint32_t slot(uint32_t v) const {
        const size_t word = v / 64;
        const uint64_t bit = uint64_t(1) << (v % 64);
        if (word >= split.size() || !(split[word] & bit)) return kNone;
        return rank[word] + uint32_t(std::popcount(split[word] & (bit - 1)));
    }
    // The fan of face f at split vertex `slot` (0 when f is not there).
    uint32_t fan(uint32_t slot, uint32_t f) const;
    glm::vec3 normal(uint32_t slot, uint32_t f) const { return normals[extra[slot] + slot + fan(slot, f)]; }
    // The shading normal id of face f's corner at vertex v.
    uint32_t id(uint32_t v, uint32_t f) const {
        const size_t word = v / 64;
        const uint64_t bit = uint64_t(1) << (v % 64);
        const uint64_t bits = word < split.size() ? split[word] : 0;
        const uint32_t before = word < rank.size() ? rank[word] + uint32_t(std::popcount(bits & (bit - 1))) : 0;
        return v + (before < extra.size() ? extra[before] : 0) + ((bits & bit) ? fan(before, f) : 0);
    }
    size_t memory_bytes() const;
    bool operator==(const ShadingSplits&) const = default;
};

struct Mesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::uvec3> triangles;  // indices into positions, counter-clockwise = front
    std::vector<glm::vec3> normals;     // per vertex; empty = compute (angle-weighted)
    // Hard edges (auto-smooth, geometry/auto_smooth.hpp): where they split a vertex's normal,
    // its corners shade with shading_normal(f, k) instead of normals[triangles[f][k]]
    // (ShadingSplits). load_mesh sets them for files without normals; `normals` stays the
    // smooth field that curvature and the inverted hull read.
    ShadingSplits shading_splits;
    std::vector<glm::vec3> colors;         // per vertex RGB in [0,1] replacing the material's diffuse
                                           // (glTF: COLOR_0 x baseColorFactor, linear); empty = material colour
    std::vector<glm::vec2> uvs;            // per vertex, v = 0 at the image bottom (OBJ); may be empty
    std::vector<Material> materials;       // may be empty (default material)
    std::vector<uint32_t> face_materials;  // per triangle index into materials; may be empty
    // Per triangle, the object it came from (glTF node, OBJ `o`/`g`), an index into
    // object_names; may be empty (one unnamed object). Line sets select by these names.
    std::vector<uint32_t> face_objects;
    std::vector<std::string> object_names;
    // Per triangle, its face mark (glTF _FACEMARK, OBJ smoothing group, PLY `facemark`;
    // docs/inputs.md): 0 = unmarked, 1..255; may be empty (none marked).
    std::vector<uint8_t> face_marks;
    // The file's line primitives (OBJ `l`, glTF LINES, LINE_STRIP, LINE_LOOP), one entry per
    // segment: two indices into positions, welded and moved with them. Not part of any face:
    // the renderer's surfaces ignore them; the line type `loose` draws them.
    std::vector<glm::uvec2> line_segments;
    bool welded = false;                // true when duplicate positions were merged
    std::vector<std::string> warnings;  // "FILE: problem" lines for the user (e.g. a texture not loaded)
    // The file's cameras and lights in scene order (glTF; empty for other formats), in the
    // coordinates of `positions`.
    std::vector<FileCamera> cameras;
    std::vector<FileLight> lights;
    // The file's lights that cannot be used, each "light 'NAME' PROBLEM" (a spot light whose
    // inner cone exceeds its outer one, ...): `--lights file` reports them (an error when no
    // light is left), `inkshade info` lists them; otherwise they are of no concern.
    std::vector<std::string> unusable_lights;
    FilePoseNames pose_names;  // what the file's animations, morph targets and expressions are called

    bool has_hard_edges() const {
        return !triangles.empty() && !shading_splits.empty() && shading_splits.triangle_count == triangles.size() &&
               shading_splits.rank.size() == positions.size() / 64 + 1;
    }
    // With hard edges: the shading normal id of corner k of face f (ShadingSplits), ids below
    // shading_normal_count(); and its normal. The face must index existing vertices.
    uint32_t shading_normal_id(size_t f, int k) const { return shading_splits.id(triangles[f][k], uint32_t(f)); }
    glm::vec3 shading_normal(size_t f, int k) const {
        const uint32_t v = triangles[f][k];
        const uint32_t slot = shading_splits.slot(v);
        return slot == ShadingSplits::kNone ? normals[v] : shading_splits.normal(slot, uint32_t(f));
    }
    size_t shading_normal_count() const {
        return positions.size() + (shading_splits.extra.empty() ? 0 : shading_splits.extra.back());
    }
    size_t vertex_count() const { return positions.size(); }
    size_t triangle_count() const { return triangles.size(); }
    BoundingBox bounds() const;
};

}  // namespace inkshade
