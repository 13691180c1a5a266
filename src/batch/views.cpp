// View lists of batch jobs (parse_views, inkshade/batch.hpp): orbits, turntables, single
// azimuth/elevation views and explicit cameras, each with a stable file-name part.
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <set>

#include "batch/jobs.hpp"
#include "inkshade/error.hpp"
#include "io/text_scanner.hpp"

namespace inkshade {

namespace {

constexpr int kMaxViewsPerItem = 3600;
constexpr float kTurntableElevation = 20.0f;  // the auto-framing default (kDefaultElevation)

const char* kGrammar =
    "orbitAxE, turntable:N[:EL], AZ:EL[:DIST], camera=NAME or eye=X,Y,Z [target=X,Y,Z] [up=X,Y,Z] [name=NAME]";

[[noreturn]] void bad(const std::string& item, const std::string& why) {
    throw InputError("view " + io::quote_token(item) + ": " + why);
}

bool number(std::string_view text, float& out) {
    double v = 0;
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || ec != std::errc() || ptr != text.data() + text.size() || !std::isfinite(v)) return false;
    out = float(v);
    return true;
}

bool integer(std::string_view text, int& out) {
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
    return !text.empty() && ec == std::errc() && ptr == text.data() + text.size();
}

// Degrees in a file name: the integer part zero-padded to `width` digits, up to three decimals
// without trailing zeros: 45 -> "045", 22.5 -> "022.5", -15 -> "-15".
std::string degrees_name(float value, int width) {
    const long long thousandths = std::llround(double(value) * 1000.0);
    const long long whole = std::llabs(thousandths) / 1000, frac = std::llabs(thousandths) % 1000;
    char buf[64];
    std::snprintf(buf, sizeof buf, "%s%0*lld", thousandths < 0 ? "-" : "", width, whole);
    std::string s = buf;
    if (frac != 0) {
        std::snprintf(buf, sizeof buf, ".%03lld", frac);
        std::string f = buf;
        while (f.back() == '0') f.pop_back();
        s += f;
    }
    return s;
}

BatchView orbit_view(float azimuth, float elevation, std::optional<float> distance) {
    BatchView v;
    v.camera.azimuth_degrees = azimuth;
    v.camera.elevation_degrees = elevation;
    v.camera.distance = distance;
    v.name = "az" + degrees_name(azimuth, 3) + "_el" + degrees_name(elevation, 2);
    if (distance) v.name += "_d" + degrees_name(*distance, 1);
    return v;
}

void check_elevation(const std::string& item, float elevation) {
    if (!(elevation >= -90.0f && elevation <= 90.0f)) bad(item, "elevation must be in -90..90 degrees");
}

void check_count(const std::string& item, int n, int max) {
    if (n < 1 || n > max) bad(item, "count must be in 1.." + std::to_string(max));
}

// orbitAxE, turntable:N[:EL] or AZ:EL[:DIST].
void parse_orbit_item(const std::string& item, std::vector<BatchView>& out) {
    if (item.starts_with("orbit")) {
        const std::string rest = item.substr(5);
        const size_t x = rest.find('x');
        int a = 0, e = 0;
        if (x == std::string::npos || !integer(std::string_view(rest).substr(0, x), a) ||
            !integer(std::string_view(rest).substr(x + 1), e))
            bad(item, "expected orbitAxE, e.g. orbit8x3");
        check_count(item, a, kMaxViewsPerItem);
        check_count(item, e, 90);
        for (int k = 0; k < e; ++k)
            for (int i = 0; i < a; ++i)
                out.push_back(orbit_view(360.0f * float(i) / float(a), 90.0f * float(k) / float(e), {}));
        return;
    }
    const std::vector<std::string> parts = batch::split_list(item, ":");
    if (item.starts_with("turntable")) {
        int n = 0;
        float elevation = kTurntableElevation;
        if (parts.size() < 2 || parts.size() > 3 || parts[0] != "turntable" || !integer(parts[1], n) ||
            (parts.size() == 3 && !number(parts[2], elevation)))
            bad(item, "expected turntable:N or turntable:N:EL, e.g. turntable:36");
        check_count(item, n, kMaxViewsPerItem);
        check_elevation(item, elevation);
        for (int i = 0; i < n; ++i) out.push_back(orbit_view(360.0f * float(i) / float(n), elevation, {}));
        return;
    }
    float az = 0, el = 0, dist = 0;
    if (parts.size() < 2 || parts.size() > 3 || item.find("::") != std::string::npos || !number(parts[0], az) ||
        !number(parts[1], el) || (parts.size() == 3 && !number(parts[2], dist)))
        bad(item, std::string("expected ") + kGrammar);
    check_elevation(item, el);
    if (parts.size() == 3 && !(dist > 0.0f)) bad(item, "distance must be positive");
    out.push_back(orbit_view(az, el, parts.size() == 3 ? std::optional<float>(dist) : std::nullopt));
}

glm::vec3 vec3_value(const std::string& item, const std::string& key, const std::string& text) {
    const std::vector<std::string> parts = batch::split_list(text, ",");
    glm::vec3 v(0.0f);
    if (parts.size() != 3 || text.find(",,") != std::string::npos) bad(item, key + ": expected X,Y,Z");
    for (int i = 0; i < 3; ++i)
        if (!number(parts[i], v[i])) bad(item, key + ": expected X,Y,Z");
    return v;
}

// eye=X,Y,Z [target=X,Y,Z] [up=X,Y,Z] [name=NAME]
BatchView parse_camera_item(const std::string& item, int index) {
    BatchView v;
    v.name = "cam" + std::to_string(index);
    std::set<std::string> seen;
    for (const std::string& token : batch::split_list(item, " \t")) {
        const size_t eq = token.find('=');
        const std::string key = token.substr(0, eq), value = eq == std::string::npos ? "" : token.substr(eq + 1);
        if (eq == std::string::npos || value.empty()) bad(item, "expected KEY=VALUE, got " + io::quote_token(token));
        if (!seen.insert(key).second) bad(item, key + " is given twice");
        if (key == "eye")
            v.camera.eye = vec3_value(item, key, value);
        else if (key == "target")
            v.camera.target = vec3_value(item, key, value);
        else if (key == "up") {
            v.camera.up = vec3_value(item, key, value);
            if (glm::length(*v.camera.up) == 0.0f) bad(item, "up must not be zero");
        } else if (key == "name") {
            for (char c : value)
                if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.' || c == '='))
                    bad(item, "name may hold letters, digits and - _ . = only");
            v.name = value;
        } else {
            bad(item, "unknown key " + io::quote_token(key) + " (eye, target, up, name)");
        }
    }
    if (!v.camera.eye) bad(item, "an explicit camera needs eye=X,Y,Z");
    if (v.camera.target && glm::length(*v.camera.eye - *v.camera.target) == 0.0f)
        bad(item, "eye and target are the same point");
    return v;
}

// camera=NAME: the model file's camera, named camera-NAME in stems.
BatchView file_camera_view(const std::string& item) {
    BatchView v;
    v.file_camera = item.substr(7);
    if (v.file_camera.empty()) bad(item, "expected camera=NAME or camera=INDEX");
    v.name = "camera-";
    for (char c : v.file_camera)
        v.name += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.' ? c : '_';
    return v;
}

}  // namespace

std::vector<BatchView> parse_views(const std::string& text) {
    std::vector<BatchView> views;
    int cameras = 0;
    for (const std::string& chunk : batch::split_list(text, ";")) {
        if (chunk.starts_with("eye=")) {
            views.push_back(parse_camera_item(chunk, ++cameras));
            continue;
        }
        for (const std::string& item : batch::split_list(chunk, ",")) {
            if (item.starts_with("camera=")) {
                views.push_back(file_camera_view(item));
                continue;
            }
            if (item.find('=') != std::string::npos)
                bad(item, "an explicit camera starts with eye= and is separated from other views by ';'");
            parse_orbit_item(item, views);
        }
    }
    if (views.empty()) throw InputError(std::string("no view given (") + kGrammar + ")");
    std::set<std::string> names;
    for (const BatchView& v : views)
        if (!names.insert(v.name).second) throw InputError("view " + v.name + " is listed twice");
    return views;
}

}  // namespace inkshade
