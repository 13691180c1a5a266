// View lists of batch jobs (parse_views, inkshade/batch.hpp): orbits, turntables, view sets on
// the sphere (Fibonacci, icosphere, seeded random), single azimuth/elevation views and explicit
// cameras, each with a stable file-name part.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <set>

#include "batch/jobs.hpp"
#include "batch/sphere_directions.hpp"
#include "inkshade/error.hpp"
#include "io/text_scanner.hpp"

namespace inkshade {

namespace {

constexpr int kMaxViewsPerItem = 3600;
constexpr int kMaxIcoLevel = 4;               // 2562 views; level 5 would be 10242
constexpr float kTurntableElevation = 20.0f;  // the auto-framing default (kDefaultElevation)

const char* kGrammar =
    "orbit:AxE (or orbitAxE), turntable:N[:EL], fibonacci:N, ico:LEVEL, random:N:SEED[:roll=DEG][:dist=LO-HI], "
    "AZ:EL[:DIST], camera=NAME or eye=X,Y,Z [target=X,Y,Z] [up=X,Y,Z] [name=NAME]";
const char* kRandomGrammar = "expected random:N:SEED[:roll=DEG][:dist=LO-HI], e.g. random:100:7:roll=15:dist=2-3";

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
        const std::string rest = item.substr(item.starts_with("orbit:") ? 6 : 5);
        const size_t x = rest.find('x');
        int a = 0, e = 0;
        if (x == std::string::npos || !integer(std::string_view(rest).substr(0, x), a) ||
            !integer(std::string_view(rest).substr(x + 1), e))
            bad(item, "expected orbit:AxE or orbitAxE, e.g. orbit:8x3");
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

// View i of a set on the sphere: its direction as azimuth and elevation (auto-framed distance),
// named PREFIX_III with the index zero-padded to the digits of the set's last index (at least 3).
BatchView sphere_view(const glm::dvec3& direction, const std::string& prefix, int i, int n) {
    const glm::dvec2 ae = batch::azimuth_elevation(direction);
    BatchView v;
    v.camera.azimuth_degrees = float(ae.x);
    v.camera.elevation_degrees = float(ae.y);
    const int width = std::max<int>(3, int(std::to_string(n - 1).size()));
    char index[32];
    std::snprintf(index, sizeof index, "%0*d", width, i);
    v.name = prefix + "_" + index;
    return v;
}

// "A-B" with 0 < A <= B: the random set's distance range.
bool distance_range(std::string_view text, float& lo, float& hi) {
    const size_t dash = text.find('-', 1);
    return dash != std::string_view::npos && number(text.substr(0, dash), lo) && number(text.substr(dash + 1), hi) &&
           lo > 0.0f && lo <= hi;
}

// random:N:SEED[:roll=DEG][:dist=LO-HI]. Each view takes four draws of SplitMix64(SEED), so its
// direction does not depend on the options: u1, u2 its direction (uniform_direction), u3 its
// roll DEG (2 u3 - 1), u4 its distance LO + (HI - LO) u4.
void parse_random_item(const std::string& item, std::vector<BatchView>& out) {
    const std::vector<std::string> parts = batch::split_list(item, ":");
    int n = 0;
    uint64_t seed = 0;
    if (parts.size() < 3 || parts.size() > 5 || item.find("::") != std::string::npos || parts[0] != "random" ||
        !integer(parts[1], n))
        bad(item, kRandomGrammar);
    const auto [ptr, ec] = std::from_chars(parts[2].data(), parts[2].data() + parts[2].size(), seed);
    if (ec != std::errc() || ptr != parts[2].data() + parts[2].size()) bad(item, "SEED must be an integer 0..2^64-1");
    check_count(item, n, kMaxViewsPerItem);
    std::optional<float> roll;
    std::optional<std::pair<float, float>> dist;
    for (size_t k = 3; k < parts.size(); ++k) {
        float a = 0, b = 0;
        if (parts[k].starts_with("roll=") && !roll && number(std::string_view(parts[k]).substr(5), a)) {
            if (!(a >= 0.0f && a <= 180.0f)) bad(item, "roll must be in 0..180 degrees");
            roll = a;
        } else if (parts[k].starts_with("dist=") && !dist) {
            if (!distance_range(std::string_view(parts[k]).substr(5), a, b))
                bad(item, "dist must be LO-HI with 0 < LO <= HI (world units), e.g. dist=2-3");
            dist = std::pair(a, b);
        } else {
            bad(item, kRandomGrammar);
        }
    }
    batch::SplitMix64 random(seed);
    for (int i = 0; i < n; ++i) {
        BatchView v = sphere_view(batch::uniform_direction(random), "rnd" + std::to_string(seed), i, n);
        const double u3 = random.uniform(), u4 = random.uniform();
        if (roll) v.roll_degrees = float(double(*roll) * (2.0 * u3 - 1.0));
        if (dist) v.camera.distance = float(double(dist->first) + double(dist->second - dist->first) * u4);
        out.push_back(std::move(v));
    }
}

// fibonacci:N, ico:LEVEL or random:...; false for an item of another kind.
bool parse_sphere_item(const std::string& item, std::vector<BatchView>& out) {
    if (item.starts_with("random")) {
        parse_random_item(item, out);
        return true;
    }
    const bool fibonacci = item.starts_with("fibonacci");
    if (!fibonacci && !item.starts_with("ico")) return false;
    const std::vector<std::string> parts = batch::split_list(item, ":");
    int n = 0;
    if (parts.size() != 2 || parts[0] != (fibonacci ? "fibonacci" : "ico") || !integer(parts[1], n))
        bad(item, fibonacci ? "expected fibonacci:N, e.g. fibonacci:100" : "expected ico:LEVEL, e.g. ico:2");
    if (fibonacci) check_count(item, n, kMaxViewsPerItem);
    if (!fibonacci && (n < 0 || n > kMaxIcoLevel))
        bad(item, "LEVEL must be in 0.." + std::to_string(kMaxIcoLevel) + " (10 x 4^LEVEL + 2 views)");
    const std::vector<glm::dvec3> directions =
        fibonacci ? batch::fibonacci_directions(n) : batch::icosphere_directions(n);
    const std::string prefix = (fibonacci ? "fib" : "ico") + std::to_string(n);
    for (size_t i = 0; i < directions.size(); ++i)
        out.push_back(sphere_view(directions[i], prefix, int(i), int(directions.size())));
    return true;
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
            if (parse_sphere_item(item, views)) continue;
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
