// The camera file beside an image (OUT.camera.json, docs/aov.md): enough to turn the depth AOV
// back into 3-D points, in OpenCV's pinhole convention (K in pixels) and OpenGL's (the view
// and projection matrices the renderer used).
#include <charconv>
#include <cmath>
#include <string>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "inkshade/aov.hpp"
#include "inkshade/version.hpp"
#include "io/json_number.hpp"

namespace inkshade {

namespace {

using Json = nlohmann::ordered_json;

Json number(double v) { return io::shortest_number(v); }

Json vec3(const glm::dvec3& v) { return Json::array({number(v.x), number(v.y), number(v.z)}); }

// Rows (glm stores columns): y = M x.
template <class M>
Json rows(const M& m, int n) {
    Json out = Json::array();
    for (int r = 0; r < n; ++r) {
        Json row = Json::array();
        for (int c = 0; c < n; ++c) row.push_back(number(double(m[c][r])));
        out.push_back(row);
    }
    return out;
}

// Matrices one row a line, the rest as dump(2) would.
std::string pretty(const Json& j) {
    std::string out = "{\n";
    size_t n = 0;
    for (const auto& [key, value] : j.items()) {
        out += "  " + Json(key).dump() + ": ";
        if (value.is_array() && !value.empty() && value[0].is_array()) {
            out += "[\n";
            for (size_t r = 0; r < value.size(); ++r)
                out += "    " + value[r].dump() + (r + 1 < value.size() ? ",\n" : "\n");
            out += "  ]";
        } else if (value.is_object()) {
            out += value.dump();
        } else {
            out += value.dump();
        }
        out += ++n < j.size() ? ",\n" : "\n";
    }
    return out + "}\n";
}

Json field_scales_json(const FieldScales& f) {
    Json out = Json::object();
    if (f.feature_size > 0.0f) out["feature_size"] = number(f.feature_size);
    if (!f.p90.empty()) {
        Json p90 = Json::object();
        for (const auto& [name, value] : f.p90) p90[name] = number(value);
        out["p90"] = p90;
    }
    if (!f.shading_sigmas.empty()) {
        Json sigmas = Json::array();
        for (float s : f.shading_sigmas) sigmas.push_back(number(s));
        out["shading_sigmas"] = sigmas;
    }
    return out;
}

}  // namespace

std::string format_field_scales(const FieldScales& scales) { return field_scales_json(scales).dump(); }

std::string format_camera_json(const CameraRecord& r) {
    const Camera& c = r.camera;
    const double w = r.width, h = r.height;
    // OpenGL camera space: x right, y up, looking down -z (Camera::view). OpenCV's: x right,
    // y down, z forward, so the two differ by diag(1, -1, -1).
    const glm::dmat4 view(c.view());
    const glm::dmat4 flip(glm::dvec4(1, 0, 0, 0), glm::dvec4(0, -1, 0, 0), glm::dvec4(0, 0, -1, 0),
                          glm::dvec4(0, 0, 0, 1));
    const glm::dmat4 view_cv = flip * view;
    // Pixels per unit of the image plane at distance 1 (perspective) or per world unit (ortho);
    // square pixels, so fx = fy.
    const double f =
        c.orthographic ? h / double(c.ortho_height) : 0.5 * h / std::tan(0.5 * glm::radians(double(c.fov_degrees)));
    const glm::dmat3 k(glm::dvec3(f, 0, 0), glm::dvec3(0, f, 0), glm::dvec3(0.5 * w, 0.5 * h, 1));

    Json j;
    j["inkshade"] = kVersion;
    j["image"] = {{"width", r.width}, {"height", r.height}};
    j["projection"] = c.orthographic ? "orthographic" : "perspective";
    j["K"] = rows(k, 3);
    if (c.orthographic) {
        j["ortho_height"] = number(c.ortho_height);
        j["ortho_width"] = number(double(c.ortho_height) * w / h);
    } else {
        j["fov_y_degrees"] = number(c.fov_degrees);
        j["fov_x_degrees"] = number(glm::degrees(2.0 * std::atan(0.5 * w / f)));
    }
    j["near"] = number(c.near_plane);
    j["far"] = number(c.far_plane);
    j["world_to_camera"] = rows(view, 4);
    j["world_to_camera_opencv"] = rows(view_cv, 4);
    j["camera_to_world"] = rows(glm::inverse(view), 4);
    j["projection_matrix"] = rows(glm::dmat4(c.projection(float(w / h))), 4);
    j["eye"] = vec3(c.eye);
    j["target"] = vec3(c.target);
    j["up"] = vec3(c.up);
    j["up_axis"] = up_axis_name(r.up_axis);
    j["model_bounds"] = {{"min", vec3(r.bounds.min)}, {"max", vec3(r.bounds.max)}};
    if (!r.fields.empty()) j["fields"] = field_scales_json(r.fields);
    j["conventions"] = {
        {"pixel", "(u, v) = (column + 0.5, row + 0.5), row 0 at the top"},
        {"depth", "distance along the view axis (-z in world_to_camera's space), 0 = background"},
        {"normal", "unit, world_to_camera's space: x right, y up, z towards the viewer"},
    };
    return pretty(j);
}

}  // namespace inkshade
