// RayScene's construction (visibility.hpp): one Embree scene of a mesh, its buffers shared with
// the mesh where Embree allows, with the occlusion filter of occlusion_levels.cpp.
#include <algorithm>
#include <string>

#include "geometry/ray_scene_impl.hpp"
#include "geometry/triangle_vertices.hpp"
#include "inkshade/error.hpp"

namespace inkshade::geometry {

namespace {

std::string device_error_text(RTCDevice device) {
    switch (rtcGetDeviceError(device)) {
        case RTC_ERROR_NONE: return "no error";
        case RTC_ERROR_OUT_OF_MEMORY: return "out of memory";
        case RTC_ERROR_INVALID_ARGUMENT: return "invalid argument";
        case RTC_ERROR_UNSUPPORTED_CPU: return "unsupported CPU";
        default: return "error " + std::to_string(int(rtcGetDeviceError(device)));
    }
}

}  // namespace

RayScene::RayScene(const Mesh& mesh) : impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
    tolerance_ = 1e-5 * std::max(double(mesh.bounds().diagonal()), 1e-30);
    // AVX2 at most: Debian's Embree 3.13.5 loops forever inside rtcOccluded1M on its AVX-512
    // kernels (seen on an AVX-512 Xeon with the line-drawing tests; the same rays finish at once
    // with max_isa=avx2 or sse4.2). CPUs without AVX2 still get their best ISA.
    m.device = rtcNewDevice("max_isa=avx2");
    if (!m.device) throw RuntimeError("ray casting: cannot create an Embree device");
    m.scene = rtcNewScene(m.device);
    // Robust mode: watertight edge tests, so a ray through a shared edge of an occluder
    // cannot slip between its two triangles and show a hidden line through the surface.
    rtcSetSceneFlags(m.scene, RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_COMPACT);

    const size_t nv = mesh.positions.size(), nf = mesh.triangles.size();
    m.mesh = &mesh;
    m.triangles = mesh.triangles.data();
    if (std::any_of(mesh.triangles.begin(), mesh.triangles.end(),
                    [&](const glm::uvec3& t) { return !in_range(t, nv); })) {
        // Embree skips such triangles too, but a hit must never index out of range here.
        m.own_triangles = mesh.triangles;
        for (auto& t : m.own_triangles)
            if (!in_range(t, nv)) t = glm::uvec3(0);  // never hit
        m.triangles = m.own_triangles.data();
    }
    if (nv > 0 && nf > 0) {
        RTCGeometry geom = rtcNewGeometry(m.device, RTC_GEOMETRY_TYPE_TRIANGLE);
        // Embree reads the last vertex with a 16-byte load: the mesh's own array serves when
        // its capacity covers those 4 bytes (60 MB saved at 10 M triangles), else a copy.
        if (mesh.positions.capacity() > nv) {
            rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, mesh.positions.data(), 0,
                                       sizeof(glm::vec3), nv);
        } else {
            auto* v = static_cast<float*>(
                rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), nv));
            if (v) std::copy_n(&mesh.positions[0].x, 3 * nv, v);
        }
        // Indices are shared (12-byte stride, no padding needed).
        rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, m.triangles, 0, sizeof(glm::uvec3),
                                   nf);
        rtcSetGeometryOccludedFilterFunction(geom, count_crossings);
        rtcCommitGeometry(geom);
        rtcAttachGeometry(m.scene, geom);
        rtcReleaseGeometry(geom);
    }
    rtcCommitScene(m.scene);
    if (rtcGetDeviceError(m.device) != RTC_ERROR_NONE)
        throw RuntimeError("ray casting: Embree failed to build the scene (" + device_error_text(m.device) + ")");
}

RayScene::~RayScene() = default;

void reserve_embree_padding(std::vector<glm::vec3>& positions) {
    if (positions.capacity() == positions.size()) positions.reserve(positions.size() + 1);
    positions.emplace_back(0.0f);  // the 4 bytes read past the end are then initialised
    positions.pop_back();
}

}  // namespace inkshade::geometry
