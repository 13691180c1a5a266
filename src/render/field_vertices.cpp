// The `fields` pass: the per-vertex values of the surface-field AOVs for this view
// (render/field_vertices.hpp), before the GL upload (it reads MeshLineData, which
// MeshUse::OneFrame frees then); the aov pass interpolates them per pixel.
#include "render/field_vertices.hpp"

#include <cmath>

#include "geometry/line_types/mesh_line_data.hpp"
#include "geometry/suggestive_contours.hpp"
#include "render/frame.hpp"

namespace inkshade::render {

std::vector<float> shading_sigmas(float edge_length) {
    std::vector<float> out;
    for (int s = 0; s < kShadingScales; ++s) out.push_back(std::ldexp(0.4f * edge_length, s));
    return out;
}

namespace {

bool wants_curvature(AovSet want) {
    for (Aov a : {Aov::Kr, Aov::Dwkr, Aov::K1, Aov::K2, Aov::Pdir1, Aov::Pdir2})
        if (want.contains(a)) return true;
    return false;
}

class FieldsPass final : public Pass {
public:
    void run(Frame& frame) override {
        const AovSet want = frame.options.aovs.fields();
        geometry::MeshLineData& data = frame.line_extractor.mesh_data();
        FieldVertices& f = frame.field_vertices.emplace();
        f.normals = data.normals();
        if (wants_curvature(want)) {
            const geometry::Curvature& c = data.curvature();
            f.scales.feature_size = data.feature_size();
            if (want.contains(Aov::Kr) || want.contains(Aov::Dwkr)) {
                geometry::RadialCurvature r = geometry::radial_curvature(data.mesh(), data.normals(), c, frame.camera);
                f.kr = std::move(r.kr);
                f.dwkr = std::move(r.dw_kr);
            }
            if (want.contains(Aov::K1) || want.contains(Aov::K2)) {
                f.k1 = c.k1;
                f.k2 = c.k2;
            }
            if (want.contains(Aov::Pdir1) || want.contains(Aov::Pdir2)) {
                f.pdir1 = c.pdir1;
                f.pdir2 = c.pdir2;
            }
        }
        if (want.contains(Aov::ShadingScales)) {
            f.scales.shading_sigmas = shading_sigmas(frame.edge_length);
            f.smoothed = data.smoothed_normals(f.scales.shading_sigmas);
        }
    }
};

// Runs when the frame asks for a surface field; the aov pass reads what it computes.
const PassRegistration fields_pass{{
    .name = "fields",
    .stage = Stage::Attributes,
    .plan = [](const Frame& frame) -> std::optional<PassIo> {
        if (!frame.aovs || frame.options.aovs.fields().empty()) return std::nullopt;
        return PassIo{.reads = {Resource::MeshLineData}, .writes = {Resource::ViewAttributes}};
    },
    .create = create_pass<FieldsPass>,
}};

}  // namespace

}  // namespace inkshade::render
