// LineExtractor: per view, the object-space layers of a style drawn in named stages, each timed
// on its own (LineTiming, stage_timer.hpp):
//   plan        check every layer, then compute the mesh-wide data their types declare they need
//               (LineTypeNeeds → MeshLineData::prepare; reported per computation) and the ray scene
//   extract     each layer's segments (world space) from its type's extractor, kept where they
//               lie on the faces its line set selects (face_selection.hpp)
//   visibility  split by visibility (ray casting, visibility.hpp), per occlusion level
//   chain       chain into polylines per level drawn (with each point's face for surface points)
//   finish      project to image pixels, drop short chains and smooth (in pixels), then stylised
//               strokes (split, widths and colours, sketchy passes, dashes; stroke_style.hpp);
//               with LineContext::surface each point's surface location (surface_points.hpp)
//   coherence   in a sequence, the stroke parameter from the previous frame and the record of
//               this frame's chains for the next (stroke_coherence.hpp)
// No type is named here: what differs between types is declared at their registration.
#include <algorithm>
#include <map>
#include <optional>
#include <utility>

#include "geometry/chaining.hpp"
#include "geometry/face_selection.hpp"
#include "geometry/line_types/mesh_line_data.hpp"
#include "geometry/line_types/object_line_registry.hpp"
#include "geometry/path_arc_length.hpp"
#include "geometry/section_cut.hpp"
#include "geometry/stage_timer.hpp"
#include "geometry/stroke_coherence.hpp"
#include "geometry/stroke_style.hpp"
#include "geometry/suggestive_contours.hpp"
#include "geometry/surface_points.hpp"
#include "geometry/visibility.hpp"
#include "geometry/visible_fills.hpp"
#include "inkshade/error.hpp"
#include "inkshade/line_drawing.hpp"

namespace inkshade {

using namespace geometry;

namespace {

// What a drawing's paths keep of the surface they were projected from.
struct KeptSurface {
    bool world = false;    // LinePath::world (a sequence's frames)
    bool surface = false;  // LinePath::surface (LineContext::surface; the chains have faces)
};

// World polylines → image paths; drops those shorter than min_length px, then smooths.
std::vector<LinePath> to_image(const std::vector<Polyline>& lines, const ImageProjection& view, float min_length_px,
                               int smooth_iterations, KeptSurface keep) {
    std::vector<Polyline> image;  // (x, y, 0) in pixels, for drop_short and smoothing
    std::vector<std::vector<float>> depths;
    std::vector<const Polyline*> sources;
    image.reserve(lines.size());
    for (const Polyline& line : lines) {
        Polyline p;
        p.closed = line.closed;
        p.strength = line.strength;
        p.points.reserve(line.points.size());
        std::vector<float> depth;
        depth.reserve(line.points.size());
        for (const glm::vec3& q : line.points) {
            const glm::dvec3 s = view.project(q);
            p.points.emplace_back(float(s.x), float(s.y), 0.0f);
            depth.push_back(float(s.z));
        }
        if (p.strength.size() != p.points.size()) p.strength.assign(p.points.size(), 1.0f);
        if (p.points.size() < 2 || polyline_length(p) < min_length_px) continue;
        image.push_back(std::move(p));
        depths.push_back(std::move(depth));
        sources.push_back(&line);
    }
    if (smooth_iterations > 0) smooth_polylines(image, smooth_iterations);
    std::vector<LinePath> paths(image.size());
    for (size_t i = 0; i < image.size(); ++i) {
        LinePath& path = paths[i];
        path.closed = image[i].closed;
        path.points.reserve(image[i].points.size());
        for (const glm::vec3& q : image[i].points) path.points.emplace_back(q.x, q.y);
        path.depth = std::move(depths[i]);
        path.strength = std::move(image[i].strength);
        if (keep.world) path.world = sources[i]->points;
        if (keep.surface) path.surface = surface_points(*sources[i], view);
    }
    return paths;
}

// Occlusion levels a layer draws: [min-level, max-level], every level with `hidden`.
struct LevelRange {
    int min = 0, max = 0;
};

LevelRange drawn_levels(const LineSettings& settings) {
    LevelRange r{int(line_number(settings, "min-level")), int(line_number(settings, "max-level"))};
    if (line_number(settings, "hidden") != 0.0f) r.max = kMaxOcclusionLevel;
    if (r.min > r.max)
        throw InputError(settings.type + ": min-level " + std::to_string(r.min) + " is above max-level " +
                         std::to_string(r.max));
    return r;
}

// One object-space layer of a drawing, checked before any work.
struct PlannedLayer {
    const LineSettings* settings = nullptr;
    const ObjectLineType* type = nullptr;
    LevelRange levels;
    StrokeModifiers modifiers;
};

// The layers of a drawing and what they need, from their types' declared needs.
struct DrawPlan {
    std::vector<PlannedLayer> layers;
    MeshLineNeeds mesh;        // for MeshLineData::prepare
    bool reads_depth = false;  // some layer's stroke modifiers read the view's depth range
};

// Stage "plan", first half: every layer checked before any work, so bad input fails fast
// (InputError for an unknown type, inverted levels or a stroke parameter out of bounds).
DrawPlan plan_layers(const std::vector<LineSettings>& lines) {
    DrawPlan plan;
    for (const LineSettings& settings : lines) {
        const LineType& type = line_type(settings.type);  // InputError when unknown
        if (type.space != LineSpace::Object) continue;
        const ObjectLineType* object = object_line_type(type.name);
        if (!object) throw InputError("line type '" + type.name + "' has no object-space extractor");
        plan.layers.push_back({.settings = &settings, .type = object, .levels = {}, .modifiers = {}});
    }
    for (PlannedLayer& layer : plan.layers) {
        layer.levels = drawn_levels(*layer.settings);
        layer.modifiers = StrokeModifiers::of(*layer.settings);
        plan.reads_depth |= layer.modifiers.reads_depth();
        const LineTypeNeeds& needs = layer.type->needs;
        plan.mesh.adjacency |= needs.adjacency || needs.creases;
        plan.mesh.curvature |= needs.curvature;
        if (needs.creases) plan.mesh.crease_angle = line_number(*layer.settings, "angle");
        plan.mesh.intersections |= needs.intersections;
    }
    return plan;
}

// What the per-view stages of one draw share.
struct DrawView {
    ImageProjection projection;
    ViewDepthRange depth_range;
    std::vector<LineTiming>* timings;
    const StrokeSequence* sequence;  // the previous frame; null outside a sequence
    const Mesh& mesh;
    bool surface = false;  // LineContext::surface
};

// Chains per occlusion level drawn, and the same in image pixels.
using LevelChains = std::vector<std::pair<int, std::vector<Polyline>>>;
using LevelPaths = std::vector<std::pair<int, std::vector<LinePath>>>;

// Stage "chain": the layer's visible and hidden segments chained per level drawn (a change of
// level ends a chain).
LevelChains chain_levels(const VisibilitySplit& split, LevelRange levels, const DrawView& v) {
    StageTimer timer(v.timings, "chain");
    LevelChains out;
    if (levels.min == 0) out.emplace_back(0, chain_segments(split.visible, v.surface));
    std::map<int, std::vector<LineSegment>> by_level;
    for (size_t k = 0; k < split.hidden.size(); ++k) {
        const int level = split.hidden_levels[k];
        if (level >= levels.min && level <= levels.max) by_level[level].push_back(split.hidden[k]);
    }
    for (const auto& [level, parts] : by_level) out.emplace_back(level, chain_segments(parts, v.surface));
    return out;
}

// Stage "finish", first half: the chains in image pixels, short ones dropped, smoothed; in a
// sequence they keep their surface points for the coherence stage.
LevelPaths image_paths(const LevelChains& chained, const LineSettings& settings, const DrawView& v) {
    StageTimer timer(v.timings, "finish");
    const float min_length = line_number(settings, "min-length");
    const int smooth = int(line_number(settings, "smooth"));
    LevelPaths out;
    for (const auto& [level, polylines] : chained) {
        std::vector<LinePath> chains = to_image(polylines, v.projection, min_length, smooth,
                                                {.world = v.sequence != nullptr, .surface = v.surface});
        for (LinePath& p : chains) p.level = level;
        out.emplace_back(level, std::move(chains));
    }
    return out;
}

// The layer's strokes as the previous frame left them: the index-th layer when it is of this
// type, else the first of this type.
const std::vector<LinePath>* previous_paths(const StrokeSequence& sequence, size_t index, const LineSettings& line) {
    const auto same = [&](const ParameterisedLayer& l) { return l.type == line.type && l.lineset == line.lineset; };
    const auto& layers = sequence.layers;
    if (index < layers.size() && same(layers[index])) return &layers[index].paths;
    for (const ParameterisedLayer& layer : layers)
        if (same(layer)) return &layer.paths;
    return nullptr;
}

// What the next frame matches of a chain: its points and surface points with u (its arc length
// when the layer is not coherent, so the drift of its marks can be measured too).
LinePath matched_chain(const LinePath& p, bool coherent) {
    LinePath kept;
    kept.points = p.points;
    kept.world = p.world;
    kept.closed = p.closed;
    kept.level = p.level;
    if (coherent) {
        kept.u = p.u;
    } else {
        const std::vector<double> s = arc_lengths(p);
        kept.u.assign(s.begin(), s.begin() + long(p.points.size()));
    }
    return kept;
}

// Stage "coherence" (a sequence's frames): a `coherence` layer's chains take their stroke
// parameter from the previous frame's (Kalnins et al. 2003); every layer's chains are recorded
// for the next frame.
ParameterisedLayer cohere(LevelPaths& levels, const LineSettings& settings, size_t index, const DrawView& v) {
    StageTimer timer(v.timings, "coherence");
    const std::vector<LinePath>* previous = previous_paths(*v.sequence, index, settings);
    const bool coherent = line_number(settings, "coherence") != 0.0f;
    // Kalnins' propagation by the surface (the previous frame's points projected with this
    // camera), or the previous frame's image points as they are.
    const bool by_surface = line_number(settings, "coherence-by") == 0.0f;
    const ImageProjection& projection = v.projection;
    const ProjectPoint project = [&projection](const glm::vec3& p) {
        const glm::dvec3 q = projection.project(p);
        return glm::vec2(float(q.x), float(q.y));
    };
    static const std::vector<LinePath> none;  // the first frame's, or a new layer's
    ParameterisedLayer record{settings.type, {}, settings.lineset};
    for (auto& [level, chains] : levels) {
        if (coherent) parameterise_paths(chains, previous ? *previous : none, by_surface ? project : ProjectPoint());
        for (const LinePath& p : chains) record.paths.push_back(matched_chain(p, coherent));
    }
    return record;
}

// Stage "finish", second half: each level's chains as styled strokes, level 0 in the layer's
// visible paths, the others in its hidden ones.
LineLayer styled_layer(LevelPaths levels, const PlannedLayer& layer, size_t index, const DrawView& v) {
    StageTimer timer(v.timings, "finish");
    LineLayer out;
    out.settings = *layer.settings;
    for (auto& [level, chains] : levels) {
        for (LinePath& p : chains) p.world.clear();
        std::vector<LinePath> paths =
            style_strokes(std::move(chains), layer.modifiers, v.depth_range, uint32_t(index * 256 + size_t(level)));
        if (v.surface) fill_barycentrics(v.mesh, paths);
        auto& into = level == 0 ? out.visible : out.hidden;
        into.insert(into.end(), std::make_move_iterator(paths.begin()), std::make_move_iterator(paths.end()));
    }
    return out;
}

void check_size(int width, int height) {
    if (width < 1 || height < 1 || width > 16384 || height > 16384)
        throw InputError("line drawing size must be 1..16384 pixels per side, got " + std::to_string(width) + "x" +
                         std::to_string(height));
}

}  // namespace

struct LineExtractor::Impl {
    MeshLineData data;
    std::unique_ptr<RayScene> scene;    // built on the first draw (timed there)
    std::optional<BoundingBox> bounds;  // the depth range of the stroke modifiers, on first use
    // With a section plane: the mesh without the faces it removes, and its ray scene.
    std::unique_ptr<Mesh> section_mesh;
    std::unique_ptr<RayScene> section_scene;
    std::optional<SectionPlane> section_of_scene;
    // The line sets' face selections met so far, resolved on the mesh.
    std::vector<std::pair<FaceSelection, std::unique_ptr<SelectedFaces>>> selections;
    explicit Impl(const Mesh& mesh) : data(mesh) {}
    explicit Impl(Mesh&& mesh) : data(std::move(mesh)) {}
    explicit Impl(std::shared_ptr<const Mesh> mesh) : data(std::move(mesh)) {}

    ViewDepthRange depth_range(const Camera& camera, bool reads_depth);
    const SelectedFaces* selected(const FaceSelection& faces);
    double report_setup(std::vector<LineTiming>* timings);
    void prepare(const MeshLineNeeds& needs, std::vector<LineTiming>* timings);
    const RayScene& ray_scene(const std::optional<SectionPlane>& section, std::vector<LineTiming>* timings);
    std::vector<std::vector<LineSegment>> extract(const DrawPlan& plan, const Camera& camera,
                                                  const LineContext& context, std::vector<LineTiming>* timings);
    EdgeNeighbours fold_surroundings(const DrawPlan& plan, const std::vector<std::vector<LineSegment>>& segments,
                                     std::vector<LineTiming>* timings);
    VisibilitySplit visibility(const PlannedLayer& layer, const std::vector<LineSegment>& segments,
                               const RayScene& rays, const EdgeNeighbours& around, const DrawView& v);
};

ViewDepthRange LineExtractor::Impl::depth_range(const Camera& camera, bool reads_depth) {
    if (!reads_depth) return {};
    if (!bounds) bounds = data.mesh().bounds();
    return ViewDepthRange::of_sphere(camera, bounds->center(), 0.5f * bounds->diagonal());
}

// The faces a line set selects, resolved on first use; null when it selects every face.
const SelectedFaces* LineExtractor::Impl::selected(const FaceSelection& faces) {
    if (faces.everything()) return nullptr;
    for (const auto& [selection, resolved] : selections)
        if (selection == faces) return resolved.get();
    selections.emplace_back(faces, std::make_unique<SelectedFaces>(data.mesh(), faces));
    return selections.back().second.get();
}

// The lazy mesh-wide work since the last call, each computation on its own stage; returns its
// milliseconds.
double LineExtractor::Impl::report_setup(std::vector<LineTiming>* timings) {
    double total = 0.0;
    for (const auto& [stage, ms] : data.take_setup_timings()) {
        add_timing(timings, stage, ms);
        total += ms;
    }
    return total;
}

// Stage "plan", second half: what the layers need and is not cached yet, and the ray scene.
void LineExtractor::Impl::prepare(const MeshLineNeeds& needs, std::vector<LineTiming>* timings) {
    // The ray scene (first view only) is built beside the curvature threads, after the
    // adjacency's serial sort and the crease classification (which drops a large adjacency):
    // the BVH and a 10 M-triangle adjacency are never held at once. Reported after the rest.
    std::vector<LineTiming> scene_timing;
    data.prepare(needs, [&] {
        if (scene) return;
        StageTimer timer(&scene_timing, "ray scene");
        scene = std::make_unique<RayScene>(data.mesh());
    });
    report_setup(timings);
    for (const LineTiming& t : scene_timing) add_timing(timings, t.stage, t.milliseconds);
}

// The rays' scene: the mesh's, or with a section plane the mesh without the faces it removes
// (section_cut.hpp; built when the plane changes, stage "section scene").
const RayScene& LineExtractor::Impl::ray_scene(const std::optional<SectionPlane>& section,
                                               std::vector<LineTiming>* timings) {
    if (!section) return *scene;
    const bool same =
        section_of_scene && section_of_scene->point == section->point && section_of_scene->normal == section->normal;
    if (!same) {
        StageTimer timer(timings, "section scene");
        section_scene.reset();
        section_mesh = std::make_unique<Mesh>(section_ray_mesh(data.mesh(), *section, scene->tolerance()));
        section_scene = std::make_unique<RayScene>(*section_mesh);
        section_of_scene = section;
    }
    return *section_scene;
}

// Stage "extract": each layer's segments from its type's extractor, cut to the section plane's
// kept side and to its line set's faces.
std::vector<std::vector<LineSegment>> LineExtractor::Impl::extract(const DrawPlan& plan, const Camera& camera,
                                                                   const LineContext& context,
                                                                   std::vector<LineTiming>* timings) {
    if (!context.light && !bounds) bounds = data.mesh().bounds();
    const Light light = context.light ? *context.light : default_light(*bounds, camera);
    const LineView view{
        .camera = camera, .light = light, .section = context.section, .scene = ray_scene(context.section, timings)};
    std::vector<std::vector<LineSegment>> segments;
    segments.reserve(plan.layers.size());
    for (const PlannedLayer& layer : plan.layers) {
        StageTimer timer(timings, "extract");
        segments.push_back(layer.type->extract(data, view, *layer.settings));
        if (context.section) clip_to_section(segments.back(), *context.section, scene->tolerance());
        if (const SelectedFaces* faces = selected(layer.settings->faces)) faces->filter(segments.back());
        // Lazy mesh-wide work done inside (curvature, ridges, hatching) is reported on its own
        // stage, not as per-view extraction.
        timer.exclude(report_setup(timings));
    }
    return segments;
}

// Stage "visibility", once per view: the faces around the segments of every layer whose type
// declares contour_folds, where the fold walks of their visibility test go
// (RayScene::occlusion_levels), gathered in one scan for all of them.
EdgeNeighbours LineExtractor::Impl::fold_surroundings(const DrawPlan& plan,
                                                      const std::vector<std::vector<LineSegment>>& segments,
                                                      std::vector<LineTiming>* timings) {
    StageTimer timer(timings, "visibility");
    std::vector<const std::vector<LineSegment>*> contours;
    for (size_t i = 0; i < plan.layers.size(); ++i)
        if (plan.layers[i].type->needs.contour_folds) contours.push_back(&segments[i]);
    return contours.empty() ? EdgeNeighbours() : contour_surroundings(data.mesh(), contours);
}

// Stage "visibility", per layer: its segments split into visible and hidden parts with their
// occlusion levels, counted as deep as the layer draws.
VisibilitySplit LineExtractor::Impl::visibility(const PlannedLayer& layer, const std::vector<LineSegment>& segments,
                                                const RayScene& rays, const EdgeNeighbours& around, const DrawView& v) {
    StageTimer timer(v.timings, "visibility");
    VisibilityOptions options;
    options.count_levels_to = std::min(layer.levels.max + 1, kMaxOcclusionLevel);
    options.contour = layer.type->needs.contour_folds;
    options.own_slope = layer.type->needs.own_slope;
    options.min_length_px = line_number(*layer.settings, "min-length");
    return split_by_visibility(rays, data.mesh(), v.projection, segments, options, &around);
}

LineExtractor::LineExtractor(const Mesh& mesh) : impl_(std::make_unique<Impl>(mesh)) {}
LineExtractor::LineExtractor(Mesh&& mesh) : impl_(std::make_unique<Impl>(std::move(mesh))) {}
LineExtractor::LineExtractor(std::shared_ptr<const Mesh> mesh) : impl_(std::make_unique<Impl>(std::move(mesh))) {}
LineExtractor::~LineExtractor() = default;

const BoundingBox& LineExtractor::bounds() {
    if (!impl_->bounds) impl_->bounds = impl_->data.mesh().bounds();
    return *impl_->bounds;
}

std::vector<FillRegion> LineExtractor::fills(const Camera& camera, int width, int height, const LineContext& context,
                                             glm::vec3 base_color) {
    return geometry::visible_fills(impl_->data.mesh(), camera, width, height, context.section, base_color);
}

void LineExtractor::release_mesh_data() {
    impl_->scene.reset();  // it reads the mesh, not the derived data: either order works
    impl_->section_scene.reset();
    impl_->section_mesh.reset();
    impl_->section_of_scene.reset();
    impl_->selections.clear();
    impl_->data.release_derived();
}

MeshLineData& LineExtractor::mesh_data() { return impl_->data; }

std::vector<float> LineExtractor::radial_curvature(const Camera& camera) {
    MeshLineData& d = impl_->data;
    return geometry::radial_curvature(d.mesh(), d.normals(), d.curvature(), camera).kr;
}

LineDrawing LineExtractor::draw(const Camera& camera, int width, int height, const std::vector<LineSettings>& lines,
                                std::vector<LineTiming>* timings, StrokeSequence* sequence,
                                const LineContext& context) {
    check_size(width, height);
    if (timings) timings->clear();
    const DrawPlan plan = plan_layers(lines);
    LineDrawing drawing;
    drawing.width = width;
    drawing.height = height;
    StrokeSequence next{{}, camera, width, height};
    if (plan.layers.empty()) {
        if (sequence) *sequence = std::move(next);
        return drawing;
    }
    Impl& m = *impl_;
    const DrawView view{ImageProjection(camera, width, height),
                        m.depth_range(camera, plan.reads_depth),
                        timings,
                        sequence,
                        m.data.mesh(),
                        context.surface};
    m.prepare(plan.mesh, timings);
    const std::vector<std::vector<LineSegment>> segments = m.extract(plan, camera, context, timings);
    const EdgeNeighbours around = m.fold_surroundings(plan, segments, timings);
    for (size_t i = 0; i < plan.layers.size(); ++i) {
        const PlannedLayer& layer = plan.layers[i];
        const VisibilitySplit split =
            m.visibility(layer, segments[i], m.ray_scene(context.section, timings), around, view);
        LevelPaths paths = image_paths(chain_levels(split, layer.levels, view), *layer.settings, view);
        if (sequence) next.layers.push_back(cohere(paths, *layer.settings, i, view));
        drawing.layers.push_back(styled_layer(std::move(paths), layer, i, view));
    }
    if (sequence) *sequence = std::move(next);
    return drawing;
}

}  // namespace inkshade
