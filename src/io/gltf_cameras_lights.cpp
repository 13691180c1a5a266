#include "io/gltf_cameras_lights.hpp"

#include <fstream>  // as in gltf_reader.cpp: tiny_gltf.h needs it with TINYGLTF_NO_FS

#include "io/tiny_gltf_config.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace inkshade::io {

namespace {

constexpr double kPi = 3.14159265358979323846;

// One-line, printable text of a name from the file.
std::string printable(const std::string& s) {
    std::string out;
    for (char c : s) {
        out += (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) ? '?' : c;
        if (out.size() >= 80) return out + "...";
    }
    return out;
}

// Finite in single precision, where the camera math runs (1e300 is a finite double).
bool finite(double x) { return std::isfinite(float(x)); }

// Positive in single precision, not a denormal that a projection would divide by.
bool positive(double x) { return finite(x) && float(x) >= 1e-30f; }

// A number from the file as a message shows it: 0.5, 9, 1e+30.
std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

// The node's placement with the scale taken out of its transform (section 3.10.1: "the view
// matrix is derived from the global transform of the node containing the camera with the
// scaling ignored"; the lights extension does the same).
NodePlacement placement(const glm::dmat4& m) {
    auto unit = [](const glm::dvec3& v, const glm::dvec3& fallback) {
        const double len = glm::length(v);
        return len > 0.0 && std::isfinite(len) ? glm::vec3(v / len) : glm::vec3(fallback);
    };
    NodePlacement p;
    p.position = glm::vec3(m[3]);
    p.forward = unit(-glm::dvec3(m[2]), {0.0, 0.0, -1.0});
    // Up made perpendicular to forward (a sheared transform leaves them at an angle).
    const glm::dvec3 f(p.forward), u = glm::dvec3(m[1]);
    p.up = unit(u - glm::dot(u, f) * f, {0.0, 1.0, 0.0});
    return p;
}

// A position the camera math can use: finite and within the bounds load_mesh puts on vertices.
bool usable(const NodePlacement& p) {
    for (int i = 0; i < 3; ++i)
        if (!(std::abs(p.position[i]) <= 1e15f)) return false;
    return true;
}

std::string label(const std::string& own, const std::string& node_name, const char* kind, size_t index) {
    if (!own.empty()) return printable(own);
    if (!node_name.empty()) return printable(node_name);
    return std::string(kind) + " " + std::to_string(index);
}

}  // namespace

void add_gltf_cameras(const tinygltf::Model& model, const std::vector<PlacedNode>& nodes, const std::string& path,
                      Mesh& mesh) {
    for (const PlacedNode& placed : nodes) {
        const tinygltf::Node& node = model.nodes[size_t(placed.node)];
        if (node.camera < 0) continue;
        const std::string where = "node " + std::to_string(placed.node);
        if (size_t(node.camera) >= model.cameras.size()) {
            mesh.warnings.push_back(path + ": " + where + " refers to camera " + std::to_string(node.camera) +
                                    " but the file has " + std::to_string(model.cameras.size()) + "; ignored");
            continue;
        }
        const tinygltf::Camera& g = model.cameras[size_t(node.camera)];
        FileCamera c;
        c.name = label(g.name, node.name, "camera", size_t(node.camera));
        c.placement = placement(placed.transform);
        const auto skip = [&](const std::string& problem) {
            mesh.warnings.push_back(path + ": camera '" + c.name + "' " + problem + "; ignored");
        };
        if (!usable(c.placement)) {
            skip("is placed out of range (beyond 1e15)");
            continue;
        }
        if (g.type == "perspective") {
            const tinygltf::PerspectiveCamera& p = g.perspective;
            // Section 3.10.2: yfov > 0 (below pi for a projection), znear > 0, zfar > znear when
            // given (tinygltf: 0 = not given).
            if (!(finite(p.yfov) && p.yfov > 0.0 && p.yfov < kPi)) {
                skip("has yfov " + num(p.yfov) + " (radians in (0, pi))");
                continue;
            }
            if (!positive(p.znear)) {
                skip("has znear " + num(p.znear) + " (must be positive)");
                continue;
            }
            if (p.zfar != 0.0 && !(finite(p.zfar) && float(p.zfar) > float(p.znear))) {
                skip("has zfar " + num(p.zfar) + " (must be greater than znear)");
                continue;
            }
            c.yfov_degrees = float(p.yfov * 180.0 / kPi);
            c.znear = float(p.znear);
            if (p.zfar != 0.0) c.zfar = float(p.zfar);
            if (positive(p.aspectRatio)) c.aspect_ratio = float(p.aspectRatio);
        } else if (g.type == "orthographic") {
            const tinygltf::OrthographicCamera& o = g.orthographic;
            // Section 3.10.3: xmag and ymag not zero (negative ones are read as their size),
            // zfar > znear >= 0.
            if (!(positive(std::abs(o.xmag)) && positive(std::abs(o.ymag)))) {
                skip("has xmag " + num(o.xmag) + ", ymag " + num(o.ymag) + " (must not be zero)");
                continue;
            }
            if (!(finite(o.znear) && finite(o.zfar) && o.znear >= 0.0 && float(o.zfar) > float(o.znear))) {
                skip("has znear " + num(o.znear) + ", zfar " + num(o.zfar) + " (need 0 <= znear < zfar)");
                continue;
            }
            c.orthographic = true;
            c.xmag = float(std::abs(o.xmag));
            c.ymag = float(std::abs(o.ymag));
            c.znear = float(o.znear);
            c.zfar = float(o.zfar);
        } else {
            skip("has type '" + printable(g.type) + "' (perspective or orthographic)");
            continue;
        }
        mesh.cameras.push_back(std::move(c));
    }
}

void add_gltf_lights(const tinygltf::Model& model, const std::vector<PlacedNode>& nodes, const std::string& path,
                     Mesh& mesh) {
    for (const PlacedNode& placed : nodes) {
        const tinygltf::Node& node = model.nodes[size_t(placed.node)];
        const auto ext = node.extensions.find("KHR_lights_punctual");
        if (ext == node.extensions.end() || !ext->second.IsObject() || !ext->second.Has("light")) continue;
        const tinygltf::Value& index_value = ext->second.Get("light");
        const double index = index_value.IsNumber() ? index_value.GetNumberAsDouble() : -1.0;
        const std::string where = "node " + std::to_string(placed.node);
        if (!(index >= 0.0 && index < double(model.lights.size()) && index == std::floor(index))) {
            mesh.warnings.push_back(path + ": " + where + " refers to light " +
                                    (index_value.IsNumber() ? num(index) : std::string("(not a number)")) +
                                    " but the file has " + std::to_string(model.lights.size()) + "; ignored");
            continue;
        }
        const tinygltf::Light& g = model.lights[size_t(index)];
        FileLight l;
        l.name = label(g.name, node.name, "light", size_t(index));
        l.placement = placement(placed.transform);
        const auto skip = [&](const std::string& problem) { mesh.unusable_lights.push_back("light '" + l.name + "' " + problem); };
        if (!usable(l.placement)) {
            skip("is placed out of range (beyond 1e15)");
            continue;
        }
        if (g.type == "directional") {
            l.type = FileLightType::Directional;
        } else if (g.type == "point") {
            l.type = FileLightType::Point;
        } else if (g.type == "spot") {
            l.type = FileLightType::Spot;
        } else {
            skip("has type '" + printable(g.type) + "' (directional, point or spot)");
            continue;
        }
        if (!g.color.empty()) {
            bool good = g.color.size() == 3;
            for (size_t k = 0; good && k < 3; ++k) good = finite(g.color[k]) && g.color[k] >= 0.0;
            if (!good) {
                skip("has a bad color (3 numbers, linear RGB, none negative)");
                continue;
            }
            l.color = glm::vec3(float(g.color[0]), float(g.color[1]), float(g.color[2]));
        }
        if (!(finite(g.intensity) && g.intensity >= 0.0 && g.intensity < 1e30)) {
            skip("has intensity " + num(g.intensity) + " (must not be negative)");
            continue;
        }
        l.intensity = float(g.intensity);
        if (l.type != FileLightType::Directional && g.range != 0.0) {  // tinygltf: 0 = not given
            if (!positive(g.range)) {
                skip("has range " + num(g.range) + " (must be positive)");
                continue;
            }
            l.range = float(g.range);
        }
        if (l.type == FileLightType::Spot) {
            // The extension: 0 <= inner < outer <= pi/2.
            const double inner = g.spot.innerConeAngle, outer = g.spot.outerConeAngle;
            if (!(finite(inner) && finite(outer) && inner >= 0.0 && inner < outer && outer <= kPi / 2 + 1e-6)) {
                skip("has cone angles " + num(inner) + ", " + num(outer) + " (need 0 <= inner < outer <= pi/2)");
                continue;
            }
            l.inner_cone_angle = float(inner);
            l.outer_cone_angle = float(std::min(outer, kPi / 2));
        }
        mesh.lights.push_back(std::move(l));
    }
}

}  // namespace inkshade::io
