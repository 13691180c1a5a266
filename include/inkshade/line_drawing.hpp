// Object-space line drawings: the vector line types of a style (contour, suggestive, crease,
// border, ridge, valley, intersection — LineSpace::Object) extracted from the mesh for one
// view, with hidden parts removed, chained into polylines in image coordinates. The same
// drawing is written as SVG (`inkshade lines`), as JSON (--lines-json) and drawn as GPU
// strokes by the renderer.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "inkshade/camera.hpp"
#include "inkshade/lines.hpp"
#include "inkshade/mesh.hpp"
#include "inkshade/section_plane.hpp"

namespace inkshade {

// Where on the mesh a point of a LinePath lies (LineContext::surface, --lines-json-detail full;
// docs/lines.md "JSON"): every point, loose lines' too, has its world position; `face` is the
// triangle of the path's piece from this point to the next (the last point of an open path: of
// the piece that ends there), so a point where two pieces meet, on the mesh edge between their
// triangles, names the one the path goes on in; -1 where the line lies on no triangle (a file's
// loose lines). `barycentric` weighs that triangle's corners (mesh.triangles[face]) to the
// world position (the world position projected on the triangle's plane), edge points included
// (one weight 0); 0 without a face.
struct SurfacePoint {
    glm::vec3 world{0.0f};
    int32_t face = -1;
    glm::vec3 barycentric{0.0f};
    // The point's clip-space w (perspective: its depth along the view axis; orthographic: 1),
    // so that a point stroke modifiers insert between two others (dashes, splits) takes the
    // surface point under it: attributes over w vary linearly in the image (perspective-correct
    // interpolation, as a GPU rasteriser does).
    float w = 1.0f;
};

namespace geometry {
class MeshLineData;  // geometry/line_types/mesh_line_data.hpp (the library's own)
}

// One polyline in image coordinates: pixels, origin at the top-left corner of the image, y
// down (SVG's convention; pixel (i, j) covers [i, i+1] x [j, j+1]). A new per-point attribute
// is listed in for_each_point_attribute too (src/geometry/path_attributes.hpp), which every
// operation on paths goes through.
struct LinePath {
    std::vector<glm::vec2> points;  // a closed path does not repeat its first point
    std::vector<float> depth;       // per point: window depth in [0, 1] as in the GL depth buffer
    std::vector<float> strength;    // per point in [0, 1]: fading and taper (1 = full stroke)
    // Per point, filled in by the layer's stroke modifiers (docs/lines.md, "Stylised strokes")
    // when it has any, else empty: the stroke width in pixels (strength already applied when
    // the layer tapers) and the stroke colour (linear 0..1, as the layer's `color`).
    std::vector<float> width;
    std::vector<glm::vec3> color;
    // Per point, the stroke parameter in pixels that dashes, the brush texture, width noise and
    // sketch jitter read, set on the layers of a sequence drawn with `coherence` (docs/lines.md,
    // "Temporal coherence"): u = offset + arc length. Empty: the arc length from the path's start.
    std::vector<float> u;
    // Per point, the surface point it was projected from (world space): kept in a
    // StrokeSequence's paths, for the next frame to project; empty in a drawing's.
    std::vector<glm::vec3> world;
    // Per point, where on the mesh it was projected from: filled when the draw's
    // LineContext::surface asks, else empty. Image smoothing (`smooth`) and sketch jitter move
    // the image point, not this.
    std::vector<SurfacePoint> surface;
    bool closed = false;
    // Occlusion level (quantitative invisibility, Appel 1967): how many surfaces lie between
    // the viewer and this path; 0 = visible.
    int level = 0;
};

struct LineLayer {
    LineSettings settings;  // the line type, its parameters and its line set
    std::vector<LinePath> visible;
    std::vector<LinePath> hidden;  // only when the type's "hidden" parameter asks for them
};

// Where the faces of one material are visible in the image (LineExtractor::fills): the SVG's
// fills under the strokes.
struct FillRegion {
    uint32_t material = 0;                      // index into the mesh's materials
    glm::vec3 color{1.0f};                      // its diffuse colour; without materials the style's base colour
    std::vector<std::vector<glm::vec2>> rings;  // pixels; outlines and holes, filled even-odd
};

struct LineDrawing {
    int width = 0, height = 0;  // image size in pixels (the SVG viewBox)
    glm::vec2 paper_mm{0.0f};   // a drawing sheet's size in mm (the SVG's size); 0: none
    // One per object-space line type of each line set, in the style's order.
    std::vector<LineLayer> layers;
    std::vector<FillRegion> fills;  // under the strokes (--svg-fill); empty: none
};

// One layer's strokes of a frame as the next frame of a sequence matches them: the chains (before
// splitting, passes and dashes) with their surface points and stroke parameter u.
struct ParameterisedLayer {
    std::string type;             // the line type
    std::vector<LinePath> paths;  // points, world, u, closed, level
    std::string lineset;          // its line set's name
};

// The state a caller keeps over the frames of one sequence (a turntable, an orbit, an animation)
// and passes to every draw in order. Each draw gives the strokes of its `coherence` layers a
// parameter u voted by the previous frame's (Kalnins et al. 2003, "Coherent Stylized
// Silhouettes"), so dashes, brushes and noise stay on the surface instead of restarting at each
// chain's start, then leaves its own strokes here. Default: empty (the first frame).
struct StrokeSequence {
    std::vector<ParameterisedLayer> layers;
    Camera camera;  // the frame's camera and image size, for measuring the drift of marks
    int width = 0, height = 0;
    void reset() { *this = StrokeSequence(); }
};

// What a drawing's lines see besides the camera: the key light that `light-contour` follows and
// the section plane that `clip-boundary` draws (docs/lines.md).
struct LineContext {
    std::optional<Light> light;  // unset: default_light of the mesh's bounds for the camera
    std::optional<SectionPlane> section;
    bool surface = false;  // fill each path's LinePath::surface (costs nothing when false)
};

struct LineTiming {
    std::string stage;  // "normals+curvature", "extract", "visibility", "chain", ...
    double milliseconds = 0.0;
};

// Keeps what depends on the mesh only (normals, adjacency, curvature, the ray-casting scene),
// so new views of one mesh cost only the per-view work (an adjacency over 64 MiB, about 2.6 M
// triangles, is dropped once creases are classified: only a new crease angle rebuilds it).
// Pipeline, visibility method and its tolerance: docs/lines.md. One extractor is not safe to
// use from two threads at once.
class LineExtractor {
public:
    // Copies positions, triangles and normals (the mesh's when sane, else angle-weighted), so
    // `mesh` may go away; mesh-wide data is computed on the first draw that needs it.
    explicit LineExtractor(const Mesh& mesh);
    // Takes positions, triangles and normals from `mesh` instead of copying them.
    explicit LineExtractor(Mesh&& mesh);
    // Shares `mesh` (no copy), which must stay unchanged in positions, triangles and normals
    // while the extractor lives; its normals must be unit already (ensure_vertex_normals),
    // else the extractor makes its own copy as the const Mesh& constructor does.
    explicit LineExtractor(std::shared_ptr<const Mesh> mesh);
    ~LineExtractor();
    LineExtractor(const LineExtractor&) = delete;
    LineExtractor& operator=(const LineExtractor&) = delete;

    // The drawing of the object-space line types among `lines` (image-space types are skipped)
    // seen by `camera` in a width x height image, one layer per entry in the order of `lines`,
    // each drawn where it lies on the faces its line set selects (LineSettings::faces).
    // Throws InputError for a bad size or an unknown type. `timings` receives milliseconds
    // per stage summed over the types: per view "extract", "visibility", "chain", "finish";
    // on the draw that computes them, the once-per-mesh "ray scene", "curvature", ...
    // With `sequence`, the drawing is the next frame of that sequence: layers with `coherence`
    // take their stroke parameter from its previous frame, and the frame's strokes replace it.
    // `context` gives the light and section plane of the types that read them.
    LineDrawing draw(const Camera& camera, int width, int height, const std::vector<LineSettings>& lines,
                     std::vector<LineTiming>* timings = nullptr, StrokeSequence* sequence = nullptr,
                     const LineContext& context = {});

    // Where each material's faces are visible in this view, exactly (hidden-surface removal by
    // polygon clipping, geometry/visible_fills.hpp), cut by the context's section plane; the
    // SVG writer fills them under the strokes (--svg-fill). `base_color` without materials.
    std::vector<FillRegion> fills(const Camera& camera, int width, int height, const LineContext& context,
                                  glm::vec3 base_color);

    // Radial curvature κr per mesh vertex for this view (1/world length; DeCarlo et al. 2003:
    // the normal curvature along the view vector projected onto the tangent plane), as the
    // `kr` debug view shows it. Curvature is computed on the first call and kept.
    std::vector<float> radial_curvature(const Camera& camera);

    // The mesh-wide data the object-space lines extract from (positions, normals, curvature,
    // feature size; geometry/line_types/mesh_line_data.hpp), computed on first use and kept:
    // the surface-field AOVs read it (render/field_vertices.hpp).
    geometry::MeshLineData& mesh_data();

    // Frees the mesh-wide data (curvature, adjacency, creases, the ray scene: about 700 MB at
    // 10 M triangles); the next draw computes again what it needs.
    void release_mesh_data();

    // The mesh's bounding box (computed once), e.g. for the default light.
    const BoundingBox& bounds();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

struct SvgOptions {
    // Paths as the polylines' points ("M x y L x y ..."), as before Bézier output; by default
    // each polyline is fitted with cubic Béziers within max_error_px (Schneider 1990).
    bool polylines = false;
    double max_error_px = 0.2;  // the fit's distance; with the 1/100 px rounding under 0.25 px
};

// SVG 1.1 text: viewBox = image size, one <g> layer per line type (id and inkscape:label),
// each stroke a <path> with its colour, opacity and width (a stroke whose width varies along
// it: a filled outline); hidden lines in their own dashed layer. `background` with alpha 0
// writes no background rectangle. Layout: docs/lines.md.
std::string format_svg(const LineDrawing& drawing, glm::vec4 background, const SvgOptions& options = {});
// Writes format_svg atomically (temporary file + rename). Throws RuntimeError on failure.
void write_svg(const std::string& path, const LineDrawing& drawing, glm::vec4 background,
               const SvgOptions& options = {});

// The unit tangent at each point of `path` in image coordinates: the central difference of its
// neighbours (one-sided at an open path's ends; across the closing piece of a loop), skipping
// repeated points; (1, 0) for a path of one point or of one repeated point.
std::vector<glm::vec2> path_tangents(const LinePath& path);
// The unit normal of a tangent: turned +90 degrees in image coordinates (x right, y down),
// (-t.y, t.x), which is the right-hand side of the direction of travel as the image shows it.
inline glm::vec2 path_normal(glm::vec2 tangent) { return {-tangent.y, tangent.x}; }

// How much of each point --lines-json writes (--lines-json-detail; docs/lines.md "JSON").
enum class LinesJsonDetail {
    Basic,  // points, depth, strength (width and color when set)
    Full,   // also world, face, barycentric (from LinePath::surface), tangent and normal
};

// JSON for scripting: image size and, per layer, its type, parameters and polylines (points,
// depth, strength, closed, hidden; width and color per point when the layer's stroke
// modifiers set them; with Full, each point's surface location, tangent and normal).
std::string format_lines_json(const LineDrawing& drawing, LinesJsonDetail detail = LinesJsonDetail::Basic);

}  // namespace inkshade
