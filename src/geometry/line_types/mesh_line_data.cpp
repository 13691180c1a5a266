#include "geometry/line_types/mesh_line_data.hpp"

#include <chrono>
#include <utility>

#include <tbb/parallel_invoke.h>

#include "geometry/normals.hpp"

namespace inkshade::geometry {

namespace {

template <class F>
auto timed(std::vector<std::pair<std::string, double>>& log, const char* stage, F&& f) {
    const auto start = std::chrono::steady_clock::now();
    auto result = f();
    log.emplace_back(stage, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    return result;
}

}  // namespace

MeshLineData::MeshLineData(const Mesh& mesh) {
    mesh_.positions = mesh.positions;
    mesh_.triangles = mesh.triangles;
    mesh_.normals = mesh.normals;
    ensure_vertex_normals(mesh_);
}

MeshLineData::MeshLineData(Mesh&& mesh) {
    mesh_.positions = std::move(mesh.positions);
    mesh_.triangles = std::move(mesh.triangles);
    mesh_.normals = std::move(mesh.normals);
    mesh = Mesh();  // colours, uvs and materials are not needed here
    ensure_vertex_normals(mesh_);
}

void MeshLineData::prepare(MeshLineNeeds needs) {
    if (needs.adjacency && !adjacency_ && needs.curvature && !curvature_) {
        // Each task logs into its own list; the two are merged afterwards.
        std::vector<std::pair<std::string, double>> adjacency_log, curvature_log;
        tbb::parallel_invoke(
            [&] { adjacency_ = timed(adjacency_log, "adjacency", [&] { return build_edge_adjacency(mesh_); }); },
            [&] {
                curvature_ = timed(curvature_log, "curvature", [&] { return compute_curvature(mesh_, mesh_.normals); });
            });
        for (auto* log : {&curvature_log, &adjacency_log})
            setup_timings_.insert(setup_timings_.end(), log->begin(), log->end());
        return;
    }
    if (needs.adjacency) adjacency();
    if (needs.curvature) curvature();
}

const EdgeAdjacency& MeshLineData::adjacency() {
    if (!adjacency_) adjacency_ = timed(setup_timings_, "adjacency", [&] { return build_edge_adjacency(mesh_); });
    return *adjacency_;
}

const Curvature& MeshLineData::curvature() {
    if (!curvature_)
        curvature_ = timed(setup_timings_, "curvature", [&] { return compute_curvature(mesh_, mesh_.normals); });
    return *curvature_;
}

const CreaseLines& MeshLineData::creases(float angle_degrees) {
    if (!creases_ || crease_angle_ != angle_degrees) {
        const EdgeAdjacency& adj = adjacency();
        creases_ = timed(setup_timings_, "creases",
                         [&] { return extract_creases(mesh_, adj, CreaseOptions{.angle_degrees = angle_degrees}); });
        crease_angle_ = angle_degrees;
    }
    return *creases_;
}

const std::vector<LineSegment>& MeshLineData::borders() {
    return creases_ ? creases_->borders : creases(CreaseOptions{}.angle_degrees).borders;
}

const RidgeLines& MeshLineData::ridges(const RidgeOptions& options) {
    if (!ridges_ || ridge_options_.threshold != options.threshold ||
        ridge_options_.feature_size != options.feature_size) {
        const Curvature& k = curvature();
        ridges_ = timed(setup_timings_, "ridges", [&] { return extract_ridges(mesh_, k, options); });
        ridge_options_ = options;
    }
    return *ridges_;
}

std::vector<std::pair<std::string, double>> MeshLineData::take_setup_timings() {
    return std::exchange(setup_timings_, {});
}

}  // namespace inkshade::geometry
