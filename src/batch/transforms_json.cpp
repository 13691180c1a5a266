// transforms.json (batch/transforms_json.hpp), in the layout of instant-ngp's and nerfstudio's
// datasets (nerfstudio's "Data conventions"): camera-to-world matrices in OpenGL's camera frame
// (x right, y up, looking down -z) and pinhole intrinsics in pixels.
#include "batch/transforms_json.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "batch/metadata.hpp"
#include "inkshade/error.hpp"
#include "io/atomic_file.hpp"
#include "io/json_number.hpp"

namespace inkshade::batch {

namespace {

using Json = nlohmann::ordered_json;

Json number(double v) { return io::shortest_number(v); }

// A float the metadata wrote as its shortest text, as the float it was (the text parsed as a
// double is the nearest double to the text, not the float: 0.1f is 0.100000001490116...).
double stored_float(const Json& value) { return double(float(value.get<double>())); }

// The metadata's 4 rows (camera.view_matrix) as a matrix.
glm::dmat4 matrix_rows(const Json& rows) {
    glm::dmat4 m(0.0);
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) m[c][r] = stored_float(rows.at(size_t(r)).at(size_t(c)));
    return m;
}

Json rows(const glm::dmat4& m) {
    Json out = Json::array();
    for (int r = 0; r < 4; ++r)
        out.push_back(Json::array({number(m[0][r]), number(m[1][r]), number(m[2][r]), number(m[3][r])}));
    return out;
}

// A frame's intrinsics from its metadata, K as the camera file (docs/aov.md) writes it: fx = fy,
// the principal point at the image centre. Perspective adds the fields of view in radians;
// orthographic gives pixels per world unit as the focal length and says so.
Json intrinsics(const Json& meta) {
    const Json& cam = meta.at("camera");
    const double w = meta.at("image").at("width").get<double>(), h = meta.at("image").at("height").get<double>();
    const bool ortho = cam.at("orthographic").get<bool>();
    Json j = Json::object();
    if (ortho) {
        const double f = h / stored_float(cam.at("ortho_height"));
        j["orthographic"] = true;
        j["ortho_width"] = number(w / f);
        j["ortho_height"] = number(h / f);
        j["fl_x"] = number(f);
        j["fl_y"] = number(f);
    } else {
        const double f = 0.5 * h / std::tan(0.5 * glm::radians(stored_float(cam.at("fov_degrees"))));
        j["camera_angle_x"] = number(2.0 * std::atan(0.5 * w / f));
        j["camera_angle_y"] = number(2.0 * std::atan(0.5 * h / f));
        j["fl_x"] = number(f);
        j["fl_y"] = number(f);
    }
    j["cx"] = number(0.5 * w);
    j["cy"] = number(0.5 * h);
    j["w"] = int(w);
    j["h"] = int(h);
    return j;
}

std::string read_text(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace

std::string format_transforms_json(const std::vector<std::pair<std::string, std::string>>& frames) {
    std::vector<Json> metas, own;
    for (const auto& [file, text] : frames) {
        metas.push_back(Json::parse(text, nullptr, /*allow_exceptions=*/false));
        if (!metas.back().is_object() || !metas.back().contains("camera"))
            throw InputError(file + ": the job's metadata has no camera");
        own.push_back(intrinsics(metas.back()));
    }
    const bool shared = !own.empty() && std::all_of(own.begin(), own.end(), [&](const Json& i) {
        return i == own.front() && !i.contains("orthographic");
    });
    Json j = Json::object();
    if (shared) j.update(own.front());
    // nerfstudio's name for a pinhole camera; no distortion coefficients (all zero).
    j["camera_model"] = "OPENCV";
    j["frames"] = Json::array();
    for (size_t i = 0; i < frames.size(); ++i) {
        // The view matrix is rigid: its inverse is camera-to-world, the pose the json stores.
        const glm::dmat4 view = matrix_rows(metas[i].at("camera").at("view_matrix"));
        Json frame = Json::object();
        frame["file_path"] = frames[i].first;
        frame["transform_matrix"] = rows(glm::inverse(view));
        if (!shared) frame.update(own[i]);
        j["frames"].push_back(frame);
    }
    return j.dump(2) + "\n";
}

void write_transforms_json(const std::string& output_dir, const std::vector<BatchJob>& jobs,
                           const std::vector<std::string>& hashes) {
    std::map<std::filesystem::path, std::vector<std::pair<std::string, std::string>>> directories;
    std::vector<std::filesystem::path> order;
    for (size_t i = 0; i < jobs.size(); ++i) {
        if (!jobs[i].outputs.png) continue;
        const std::filesystem::path image = job_file(output_dir, jobs[i], ".png");
        auto [it, fresh] = directories.try_emplace(image.parent_path());
        if (fresh) order.push_back(image.parent_path());
        if (hashes[i].empty() || !job_complete(output_dir, jobs[i], hashes[i])) continue;
        it->second.emplace_back(image.filename().string(), read_text(job_file(output_dir, jobs[i], ".json")));
    }
    for (const std::filesystem::path& dir : order)
        if (!directories[dir].empty())
            io::write_file_atomic((dir / "transforms.json").string(), format_transforms_json(directories[dir]));
}

}  // namespace inkshade::batch
