// LineExtractor: per view, for each object-space line type of the style: extract segments
// (world space) → split by visibility (ray casting, visibility.hpp) → chain into polylines →
// project to image pixels → drop short chains and smooth (in pixels) → stylised strokes (split,
// widths and colours, sketchy passes, dashes; stroke_style.hpp) → one layer.
#include <algorithm>
#include <chrono>
#include <map>
#include <optional>

#include "geometry/chaining.hpp"
#include "geometry/line_types/mesh_line_data.hpp"
#include "geometry/line_types/object_line_registry.hpp"
#include "geometry/path_arc_length.hpp"
#include "geometry/stroke_coherence.hpp"
#include "geometry/stroke_style.hpp"
#include "geometry/suggestive_contours.hpp"
#include "geometry/visibility.hpp"
#include "inkshade/error.hpp"
#include "inkshade/line_drawing.hpp"

namespace inkshade {

using namespace geometry;

struct LineExtractor::Impl {
    MeshLineData data;
    std::unique_ptr<RayScene> scene;    // built on the first draw (timed there)
    std::optional<BoundingBox> bounds;  // the depth range of the stroke modifiers, on first use
    explicit Impl(const Mesh& mesh) : data(mesh) {}
    explicit Impl(Mesh&& mesh) : data(std::move(mesh)) {}
    explicit Impl(std::shared_ptr<const Mesh> mesh) : data(std::move(mesh)) {}
};

LineExtractor::LineExtractor(const Mesh& mesh) : impl_(std::make_unique<Impl>(mesh)) {}
LineExtractor::LineExtractor(Mesh&& mesh) : impl_(std::make_unique<Impl>(std::move(mesh))) {}
LineExtractor::LineExtractor(std::shared_ptr<const Mesh> mesh) : impl_(std::make_unique<Impl>(std::move(mesh))) {}
LineExtractor::~LineExtractor() = default;

void LineExtractor::release_mesh_data() {
    impl_->scene.reset();  // it reads the mesh, not the derived data: either order works
    impl_->data.release_derived();
}

std::vector<float> LineExtractor::radial_curvature(const Camera& camera) {
    MeshLineData& d = impl_->data;
    return geometry::radial_curvature(d.mesh(), d.normals(), d.curvature(), camera).kr;
}

namespace {

using Clock = std::chrono::steady_clock;

// Sums milliseconds per stage over the line types, stages in first-seen order.
class StageTimer {
public:
    explicit StageTimer(std::vector<LineTiming>* out) : out_(out) {}
    template <class F>
    auto operator()(const std::string& stage, F&& f) {
        const auto start = Clock::now();
        auto result = f();
        add(stage, std::chrono::duration<double, std::milli>(Clock::now() - start).count());
        return result;
    }
    void add(const std::string& stage, double ms) {
        if (!out_) return;
        for (auto& t : *out_)
            if (t.stage == stage) {
                t.milliseconds += ms;
                return;
            }
        out_->push_back({stage, ms});
    }

private:
    std::vector<LineTiming>* out_;
};

// World polylines → image paths; drops those shorter than min_length px, then smooths. With
// `keep_world` each path keeps the world points it was projected from (LinePath::world).
std::vector<LinePath> to_image(const std::vector<Polyline>& lines, const ImageProjection& view, float min_length_px,
                               int smooth_iterations, bool keep_world) {
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
        if (keep_world) path.world = sources[i]->points;
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

}  // namespace

LineDrawing LineExtractor::draw(const Camera& camera, int width, int height, const std::vector<LineSettings>& lines,
                                std::vector<LineTiming>* timings, StrokeSequence* sequence) {
    if (width < 1 || height < 1 || width > 16384 || height > 16384)
        throw InputError("line drawing size must be 1..16384 pixels per side, got " + std::to_string(width) + "x" +
                         std::to_string(height));
    if (timings) timings->clear();
    StageTimer timer(timings);
    LineDrawing drawing;
    drawing.width = width;
    drawing.height = height;

    // Validate every entry before any work, so bad input fails fast.
    std::vector<const LineSettings*> object_lines;
    for (const LineSettings& settings : lines) {
        const LineType& type = line_type(settings.type);  // InputError when unknown
        if (type.space != LineSpace::Object) continue;
        if (!object_line_extractor(type.name))
            throw InputError("line type '" + type.name + "' has no object-space extractor");
        object_lines.push_back(&settings);
    }
    if (object_lines.empty()) {
        if (sequence) *sequence = StrokeSequence{{}, camera, width, height};
        return drawing;
    }
    // InputError when the levels are inverted or a stroke parameter is out of bounds.
    std::vector<StrokeModifiers> modifiers;
    for (const LineSettings* settings : object_lines) {
        drawn_levels(*settings);
        modifiers.push_back(StrokeModifiers::of(*settings));
    }

    Impl& m = *impl_;
    const ImageProjection view(camera, width, height);
    ViewDepthRange depth_range;
    if (std::any_of(modifiers.begin(), modifiers.end(), [](const StrokeModifiers& s) { return s.reads_depth(); })) {
        if (!m.bounds) m.bounds = m.data.mesh().bounds();
        depth_range = ViewDepthRange::of_sphere(camera, m.bounds->center(), 0.5f * m.bounds->diagonal());
    }

    MeshLineNeeds needs;
    for (const LineSettings* settings : object_lines) {
        const MeshLineNeeds n = object_line_needs(settings->type);
        needs.adjacency |= n.adjacency;
        needs.curvature |= n.curvature;
        if (settings->type == "crease") needs.crease_angle = line_number(*settings, "angle");
        needs.intersections |= settings->type == "intersection";
    }
    // The ray scene (first view only) is built beside the curvature threads, after the
    // adjacency's serial sort and the crease classification (which drops a large adjacency):
    // the BVH and a 10 M-triangle adjacency are never held at once.
    double scene_ms = 0.0;
    m.data.prepare(needs, [&] {
        if (m.scene) return;
        const auto start = Clock::now();
        m.scene = std::make_unique<RayScene>(m.data.mesh());
        scene_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    });
    for (const auto& [stage, ms] : m.data.take_setup_timings()) timer.add(stage, ms);
    if (scene_ms > 0.0) timer.add("ray scene", scene_ms);

    std::vector<std::vector<LineSegment>> segments_per_type;
    for (const LineSettings* settings : object_lines) {
        const ExtractLineSegments extract = object_line_extractor(settings->type);
        const auto start = Clock::now();
        segments_per_type.push_back(extract(m.data, camera, *settings));
        double extract_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        // Lazy mesh-wide work done inside extract() (curvature, adjacency) is reported on its
        // own stage, not as per-view extraction.
        for (const auto& [stage, ms] : m.data.take_setup_timings()) {
            timer.add(stage, ms);
            extract_ms -= ms;
        }
        timer.add("extract", extract_ms);
    }

    // The faces around the contours, where the fold walks of their visibility test go
    // (RayScene::occlusion_levels), gathered once per view for every contour list.
    const EdgeNeighbours around = timer("visibility", [&] {
        std::vector<const std::vector<LineSegment>*> contours;
        for (size_t i = 0; i < object_lines.size(); ++i)
            if (object_lines[i]->type == "contour") contours.push_back(&segments_per_type[i]);
        return contours.empty() ? EdgeNeighbours() : contour_surroundings(m.data.mesh(), contours);
    });
    StrokeSequence next{{}, camera, width, height};
    const ProjectPoint project = [&view](const glm::vec3& p) {
        const glm::dvec3 q = view.project(p);
        return glm::vec2(float(q.x), float(q.y));
    };
    for (size_t i = 0; i < object_lines.size(); ++i) {
        const LineSettings* settings = object_lines[i];
        const std::vector<LineSegment>& segments = segments_per_type[i];
        const LevelRange levels = drawn_levels(*settings);
        VisibilityOptions options;
        options.count_levels_to = std::min(levels.max + 1, kMaxOcclusionLevel);
        options.contour = settings->type == "contour";
        options.min_length_px = line_number(*settings, "min-length");
        const VisibilitySplit split = timer("visibility", [&] {
            return split_by_visibility(*m.scene, m.data.mesh(), view, segments, options, &around);
        });
        // Chains per level: a change of level ends a chain.
        auto chained = timer("chain", [&] {
            std::vector<std::pair<int, std::vector<Polyline>>> out;
            if (levels.min == 0) out.emplace_back(0, chain_segments(split.visible));
            std::map<int, std::vector<LineSegment>> by_level;
            for (size_t k = 0; k < split.hidden.size(); ++k) {
                const int level = split.hidden_levels[k];
                if (level >= levels.min && level <= levels.max) by_level[level].push_back(split.hidden[k]);
            }
            for (const auto& [level, parts] : by_level) out.emplace_back(level, chain_segments(parts));
            return out;
        });
        LineLayer layer;
        layer.settings = *settings;
        // A sequence's frame: the layer's strokes as the previous frame left them (the i-th
        // layer when it is of this type, else the first of this type).
        const std::vector<LinePath>* previous = nullptr;
        if (sequence) {
            const auto& layers = sequence->layers;
            if (i < layers.size() && layers[i].type == settings->type) previous = &layers[i].paths;
            for (size_t k = 0; k < layers.size() && !previous; ++k)
                if (layers[k].type == settings->type) previous = &layers[k].paths;
        }
        const bool coherent = sequence && line_number(*settings, "coherence") != 0.0f;
        // Kalnins' propagation by the surface (the previous frame's points projected with this
        // camera), or the previous frame's image points as they are.
        const bool by_surface = line_number(*settings, "coherence-by") == 0.0f;
        ParameterisedLayer record{settings->type, {}};
        double coherence_ms = 0.0;
        timer("finish", [&] {
            const float min_length = line_number(*settings, "min-length");
            const int smooth = int(line_number(*settings, "smooth"));
            for (const auto& [level, polylines] : chained) {
                std::vector<LinePath> chains = to_image(polylines, view, min_length, smooth, sequence != nullptr);
                for (LinePath& p : chains) p.level = level;
                if (sequence) {
                    const auto start = Clock::now();
                    if (coherent)
                        parameterise_paths(chains, previous ? *previous : std::vector<LinePath>{},
                                           by_surface ? project : ProjectPoint());
                    // What the next frame matches: the chains with u (their arc length when the
                    // layer is not coherent, so the drift of its marks can be measured too).
                    for (const LinePath& p : chains) {
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
                        record.paths.push_back(std::move(kept));
                    }
                    coherence_ms += std::chrono::duration<double, std::milli>(Clock::now() - start).count();
                }
                for (LinePath& p : chains) p.world.clear();
                std::vector<LinePath> paths =
                    style_strokes(std::move(chains), modifiers[i], depth_range, uint32_t(i * 256 + size_t(level)));
                auto& into = level == 0 ? layer.visible : layer.hidden;
                into.insert(into.end(), std::make_move_iterator(paths.begin()), std::make_move_iterator(paths.end()));
            }
            return 0;
        });
        if (sequence) {  // reported on its own stage, not as finishing
            timer.add("finish", -coherence_ms);
            timer.add("coherence", coherence_ms);
        }
        drawing.layers.push_back(std::move(layer));
        if (sequence) next.layers.push_back(std::move(record));
    }
    if (sequence) *sequence = std::move(next);
    return drawing;
}

}  // namespace inkshade
