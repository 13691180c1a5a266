#include "geometry/line_types/mesh_line_data.hpp"

#include <chrono>
#include <utility>

#include <tbb/parallel_invoke.h>

#include "geometry/connected_objects.hpp"
#include "geometry/feature_size.hpp"
#include "geometry/intersection_lines.hpp"
#include "geometry/multiscale_normals.hpp"
#include "geometry/normals.hpp"
#include "geometry/visibility.hpp"

namespace inkshade::geometry {

namespace {

template <class F>
auto timed(std::vector<std::pair<std::string, double>>& log, const char* stage, F&& f) {
    const auto start = std::chrono::steady_clock::now();
    auto result = f();
    log.emplace_back(stage,
                     std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    return result;
}

// The material names (line sets select by them) and diffuse colours (the SVG's fills);
// textures and other parameters are not read here.
std::vector<Material> material_names(const std::vector<Material>& materials) {
    std::vector<Material> names(materials.size());
    for (size_t i = 0; i < materials.size(); ++i) {
        names[i].name = materials[i].name;
        names[i].diffuse = materials[i].diffuse;
    }
    return names;
}

// What line sets select faces by (face_selection.hpp), moved or copied from `from`.
template <class M>
void take_selection_fields(Mesh& to, M&& from) {
    to.materials = material_names(from.materials);
    to.face_objects = std::forward<M>(from).face_objects;
    to.object_names = std::forward<M>(from).object_names;
    to.face_marks = std::forward<M>(from).face_marks;
}

// Positions (padded for Embree), triangles, unit normals, hard-edge shading normals, face
// materials, loose line segments and what line sets select by, of `mesh`, nothing else.
std::shared_ptr<const Mesh> line_mesh(std::vector<glm::vec3> positions, const Mesh& mesh) {
    auto m = std::make_shared<Mesh>();
    m->positions = std::move(positions);
    reserve_embree_padding(m->positions);
    m->triangles = mesh.triangles;
    m->normals = mesh.normals;
    m->shading_splits = mesh.shading_splits;
    m->face_materials = mesh.face_materials;
    take_selection_fields(*m, mesh);
    m->line_segments = mesh.line_segments;
    ensure_vertex_normals(*m);
    return m;
}

std::vector<glm::vec3> padded_copy(const std::vector<glm::vec3>& positions) {
    std::vector<glm::vec3> copy;
    copy.reserve(positions.size() + 1);  // so that reserve_embree_padding does not reallocate
    copy = positions;
    return copy;
}

}  // namespace

MeshLineData::MeshLineData(const Mesh& mesh) : mesh_(line_mesh(padded_copy(mesh.positions), mesh)) {}

MeshLineData::MeshLineData(Mesh&& mesh) {
    Mesh lines;  // positions, triangles and normals moved, not copied
    lines.positions = std::move(mesh.positions);
    lines.triangles = std::move(mesh.triangles);
    lines.normals = std::move(mesh.normals);
    lines.shading_splits = std::move(mesh.shading_splits);
    lines.face_materials = std::move(mesh.face_materials);  // material-boundary
    take_selection_fields(lines, std::move(mesh));
    lines.line_segments = std::move(mesh.line_segments);    // loose
    mesh = Mesh();  // colours, uvs and the materials themselves are not needed here
    reserve_embree_padding(lines.positions);
    ensure_vertex_normals(lines);
    mesh_ = std::make_shared<const Mesh>(std::move(lines));
}

MeshLineData::MeshLineData(std::shared_ptr<const Mesh> mesh) {
    if (normals_are_sane(*mesh))
        mesh_ = std::move(mesh);
    else
        mesh_ = line_mesh(padded_copy(mesh->positions), *mesh);
}

void MeshLineData::release_derived() {
    adjacency_.reset();
    curvature_.reset();
    creases_.reset();
    ridges_.reset();
    intersections_.reset();
    hard_edges_.reset();
    hatching_.reset();
    face_objects_.reset();
    smoothed_normals_.reset();
}

const std::vector<std::vector<glm::vec3>>& MeshLineData::smoothed_normals(const std::vector<float>& sigmas) {
    if (!smoothed_normals_ || smoothing_sigmas_ != sigmas) {
        smoothed_normals_ =
            timed(setup_timings_, "smoothed normals", [&] { return multiscale_normals(*mesh_, normals(), sigmas); });
        smoothing_sigmas_ = sigmas;
    }
    return *smoothed_normals_;
}

const std::vector<uint32_t>& MeshLineData::face_objects() {
    if (!face_objects_)
        face_objects_ = timed(setup_timings_, "objects", [&] { return geometry::face_objects(*mesh_); });
    return *face_objects_;
}

void MeshLineData::prepare(MeshLineNeeds needs, const std::function<void()>& then) {
    // Each task logs into its own list; the two are merged afterwards in a fixed order.
    TimingLog adjacency_log, curvature_log, intersection_log;
    auto adjacency_side = [&] {
        if (needs.adjacency) creases(needs.crease_angle, adjacency_log);
        if (then) then();
    };
    auto curvature_side = [&] {
        if (needs.curvature && !curvature_) curvature(curvature_log);
    };
    if (needs.intersections && !intersections_ && mesh_->triangles.size() <= kOverlapTriangles) {
        tbb::parallel_invoke(adjacency_side, curvature_side, [&] { intersections(intersection_log); });
    } else if (needs.curvature && !curvature_) {
        tbb::parallel_invoke(adjacency_side, curvature_side);
    } else {
        adjacency_side();
    }
    for (auto* log : {&curvature_log, &adjacency_log, &intersection_log})
        setup_timings_.insert(setup_timings_.end(), log->begin(), log->end());
}

const EdgeAdjacency& MeshLineData::adjacency() { return adjacency(setup_timings_); }
const Curvature& MeshLineData::curvature() { return curvature(setup_timings_); }
const CreaseLines& MeshLineData::creases(float angle_degrees) { return creases(angle_degrees, setup_timings_); }

const EdgeAdjacency& MeshLineData::adjacency(TimingLog& log) {
    if (!adjacency_) adjacency_ = timed(log, "adjacency", [&] { return build_edge_adjacency(*mesh_); });
    return *adjacency_;
}

const Curvature& MeshLineData::curvature(TimingLog& log) {
    if (!curvature_) {
        curvature_ = timed(log, "curvature", [&] { return compute_curvature(*mesh_, mesh_->normals); });
        feature_size_ = line_feature_size(*mesh_, *curvature_);
    }
    return *curvature_;
}

float MeshLineData::feature_size() {
    curvature();
    return feature_size_;
}

const CreaseLines& MeshLineData::creases(float angle_degrees, TimingLog& log) {
    if (!creases_ || crease_angle_ != angle_degrees) {
        const EdgeAdjacency& adj = adjacency(log);
        creases_ = timed(log, "creases",
                         [&] { return extract_creases(*mesh_, adj, CreaseOptions{.angle_degrees = angle_degrees}); });
        crease_angle_ = angle_degrees;
        if (adj.memory_bytes() > kKeepAdjacencyBytes) adjacency_.reset();
    }
    return *creases_;
}

const HardEdgeTable& MeshLineData::hard_edges() {
    if (!hard_edges_) hard_edges_ = timed(setup_timings_, "hard edges", [&] { return hard_edge_table(*mesh_); });
    return *hard_edges_;
}

const std::vector<LineSegment>& MeshLineData::borders() {
    return creases_ ? creases_->borders : creases(CreaseOptions{}.angle_degrees).borders;
}

const RidgeLines& MeshLineData::ridges(const RidgeOptions& options) {
    if (!ridges_ || ridge_options_.threshold != options.threshold ||
        ridge_options_.feature_size != options.feature_size) {
        const Curvature& k = curvature();
        RidgeOptions given = options;
        if (!(given.feature_size > 0.0f)) given.feature_size = feature_size_;
        ridges_ = timed(setup_timings_, "ridges", [&] { return extract_ridges(*mesh_, k, given); });
        ridge_options_ = options;
    }
    return *ridges_;
}

const std::vector<LineSegment>& MeshLineData::intersections() { return intersections(setup_timings_); }

const std::vector<LineSegment>& MeshLineData::intersections(TimingLog& log) {
    if (!intersections_) intersections_ = timed(log, "intersections", [&] { return extract_intersections(*mesh_); });
    return *intersections_;
}

const Hatching& MeshLineData::hatching(const HatchOptions& o) {
    const HatchOptions& k = hatch_options_;
    if (!hatching_ || k.spacing != o.spacing || k.density != o.density || k.levels != o.levels || k.cross != o.cross ||
        k.smoothing != o.smoothing || k.seed != o.seed) {
        const Curvature& curv = curvature();
        const EdgeAdjacency& adj = adjacency();
        hatching_ =
            timed(setup_timings_, "hatching", [&] { return trace_hatching(*mesh_, mesh_->normals, curv, adj, o); });
        hatch_options_ = o;
        if (adj.memory_bytes() > kKeepAdjacencyBytes) adjacency_.reset();
    }
    return *hatching_;
}

std::vector<std::pair<std::string, double>> MeshLineData::take_setup_timings() {
    return std::exchange(setup_timings_, {});
}

}  // namespace inkshade::geometry
