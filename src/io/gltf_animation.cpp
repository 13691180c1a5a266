#include "io/gltf_animation.hpp"

#include <fstream>  // as in gltf_reader.cpp: tiny_gltf.h needs it with TINYGLTF_NO_FS

#include "io/tiny_gltf_config.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "inkshade/error.hpp"
#include "io/gltf_names.hpp"

namespace inkshade::io {

namespace {

// The key k with times[k] <= t < times[k + 1] (times has at least two keys, t inside them).
size_t key_before(const std::vector<float>& times, double t) {
    const auto after = std::upper_bound(times.begin(), times.end(), t, [](double a, float b) { return a < b; });
    return std::min(size_t(after - times.begin()), times.size() - 1) - 1;
}

glm::dquat normalized(glm::dquat q) {
    const double len = glm::length(q);
    return len > 0.0 ? q / len : glm::dquat(1.0, 0.0, 0.0, 0.0);
}

// Spherical interpolation along the shorter arc; nearly parallel quaternions interpolate
// linearly (the angle's sine would be ~0).
glm::dquat slerp(glm::dquat a, glm::dquat b, double s) {
    double cosine = glm::dot(a, b);
    if (cosine < 0.0) {
        b = -b;
        cosine = -cosine;
    }
    if (cosine > 1.0 - 1e-9) return normalized(a * (1.0 - s) + b * s);
    const double angle = std::acos(std::min(cosine, 1.0));
    const double sine = std::sin(angle);
    return normalized(a * (std::sin((1.0 - s) * angle) / sine) + b * (std::sin(s * angle) / sine));
}

Interpolation interpolation_of(const std::string& text, const std::string& where, const GltfFloatReader& reader) {
    if (text.empty() || text == "LINEAR") return Interpolation::Linear;
    if (text == "STEP") return Interpolation::Step;
    if (text != "CUBICSPLINE") reader.fail(where + " has unknown interpolation '" + printable_name(text) + "'");
    return Interpolation::CubicSpline;
}

// Morph targets of the mesh a node instances (0 without a mesh).
size_t target_count(const tinygltf::Model& model, int node) {
    const int mesh = model.nodes[size_t(node)].mesh;
    if (mesh < 0 || size_t(mesh) >= model.meshes.size() || model.meshes[size_t(mesh)].primitives.empty()) return 0;
    return model.meshes[size_t(mesh)].primitives[0].targets.size();
}

}  // namespace

std::vector<double> sample_keyframes(const std::vector<float>& times, const std::vector<float>& values,
                                     size_t components, Interpolation interpolation, double t, bool quaternion) {
    const size_t n = times.size(), c = components;
    const bool cubic = interpolation == Interpolation::CubicSpline;
    // The value of key k (component i): for CubicSpline the middle of in-tangent, value, out-tangent.
    auto value = [&](size_t k, size_t i) { return double(values[(cubic ? 3 * k + 1 : k) * c + i]); };
    std::vector<double> out(c);
    auto hold = [&](size_t k) {
        for (size_t i = 0; i < c; ++i) out[i] = value(k, i);
    };
    if (n == 0) return out;
    if (n == 1 || t <= times.front()) {
        hold(0);
    } else if (t >= times.back()) {
        hold(n - 1);
    } else {
        const size_t k = key_before(times, t);
        const double dt = double(times[k + 1]) - double(times[k]);
        const double s = dt > 0.0 ? (t - double(times[k])) / dt : 0.0;
        if (interpolation == Interpolation::Step) {
            hold(k);
        } else if (interpolation == Interpolation::Linear && quaternion) {
            const glm::dquat a(value(k, 3), value(k, 0), value(k, 1), value(k, 2));
            const glm::dquat b(value(k + 1, 3), value(k + 1, 0), value(k + 1, 1), value(k + 1, 2));
            const glm::dquat q = slerp(a, b, s);
            return {q.x, q.y, q.z, q.w};
        } else if (interpolation == Interpolation::Linear) {
            for (size_t i = 0; i < c; ++i) out[i] = value(k, i) + s * (value(k + 1, i) - value(k, i));
        } else {
            // glTF 2.0 Appendix C: the cubic Hermite spline through the two values, with the
            // first key's out-tangent and the second's in-tangent scaled by the keys' distance.
            const double s2 = s * s, s3 = s2 * s;
            for (size_t i = 0; i < c; ++i) {
                const double out_tangent = values[(3 * k + 2) * c + i], in_tangent = values[(3 * (k + 1)) * c + i];
                out[i] = (2 * s3 - 3 * s2 + 1) * value(k, i) + (s3 - 2 * s2 + s) * dt * out_tangent +
                         (-2 * s3 + 3 * s2) * value(k + 1, i) + (s3 - s2) * dt * in_tangent;
            }
        }
    }
    if (quaternion && c == 4) {
        const glm::dquat q = normalized(glm::dquat(out[3], out[0], out[1], out[2]));
        out = {q.x, q.y, q.z, q.w};
    }
    return out;
}

int find_gltf_animation(const tinygltf::Model& model, const std::string& name, const std::string& path) {
    std::vector<std::string> names;
    for (const tinygltf::Animation& a : model.animations) names.push_back(a.name);
    const int found = find_name(names, name);
    if (found >= 0) return found;
    const bool digits = !name.empty() && name.size() < 10 &&
                        std::all_of(name.begin(), name.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (digits && std::stoul(name) < names.size()) return int(std::stoul(name));
    if (names.empty()) throw InputError(path, "no animation '" + printable_name(name) + "': the file has none");
    throw InputError(path, unknown_name("animation", name, names, true));
}

std::vector<AnimatedNode> sample_gltf_animation(const tinygltf::Model& model, int index, double time,
                                                const GltfFloatReader& reader) {
    const tinygltf::Animation& animation = model.animations.at(size_t(index));
    const std::string what = "animation " + std::to_string(index);
    struct Track {
        int node;
        std::string path;
        Interpolation interpolation;
        std::vector<float> times, values;
        size_t components;
    };
    std::vector<Track> tracks;
    double start = std::numeric_limits<double>::infinity(), end = -start;
    for (size_t i = 0; i < animation.channels.size(); ++i) {
        const tinygltf::AnimationChannel& channel = animation.channels[i];
        const std::string where = what + " channel " + std::to_string(i);
        const std::string& path = channel.target_path;
        if (path != "translation" && path != "rotation" && path != "scale" && path != "weights")
            continue;                           // e.g. KHR_animation_pointer's "pointer": nothing Inkshade poses
        if (channel.target_node < 0) continue;  // section 3.11: an extension may target something else
        if (size_t(channel.target_node) >= model.nodes.size())
            reader.fail(where + " targets node " + std::to_string(channel.target_node) + " but the file has " +
                        std::to_string(model.nodes.size()));
        if (channel.sampler < 0 || size_t(channel.sampler) >= animation.samplers.size())
            reader.fail(where + " refers to sampler " + std::to_string(channel.sampler) + " but the animation has " +
                        std::to_string(animation.samplers.size()));
        const tinygltf::AnimationSampler& sampler = animation.samplers[size_t(channel.sampler)];
        const std::string sampler_name = what + " sampler " + std::to_string(channel.sampler);
        Track track{
            channel.target_node, path, interpolation_of(sampler.interpolation, sampler_name, reader), {}, {}, 0};
        int components = 0;
        track.times = reader.floats(sampler.input, "input of " + sampler_name, {1}, components);
        if (track.times.empty()) reader.fail("input of " + sampler_name + " has no keyframes");
        if (!std::is_sorted(track.times.begin(), track.times.end()))
            reader.fail("input of " + sampler_name + ": keyframe times must increase");
        const std::string output = "output of " + sampler_name;
        if (path == "rotation")
            track.values = reader.floats(sampler.output, output, {4}, components);
        else if (path == "weights")
            track.values = reader.floats(sampler.output, output, {1}, components);
        else
            track.values = reader.floats(sampler.output, output, {3}, components);
        const size_t keys = track.times.size() * (track.interpolation == Interpolation::CubicSpline ? 3 : 1);
        track.components = path == "weights" ? target_count(model, track.node) : size_t(components);
        if (path == "weights" && track.components == 0) continue;  // node without morph targets
        if (track.values.size() != keys * track.components)
            reader.fail(output + " has " + std::to_string(track.values.size() / size_t(components)) + " elements but " +
                        std::to_string(track.times.size()) + " keyframes" +
                        (path == "weights" ? " of " + std::to_string(track.components) + " morph weights" : "") +
                        " need " + std::to_string(keys * track.components / size_t(components)));
        start = std::min(start, double(track.times.front()));
        end = std::max(end, double(track.times.back()));
        tracks.push_back(std::move(track));
    }
    std::vector<AnimatedNode> nodes(model.nodes.size());
    if (tracks.empty()) return nodes;
    const double t = std::clamp(time, start, end);
    for (const Track& track : tracks) {
        const std::vector<double> v = sample_keyframes(track.times, track.values, track.components, track.interpolation,
                                                       t, track.path == "rotation");
        AnimatedNode& node = nodes[size_t(track.node)];
        if (track.path == "translation")
            node.translation = glm::dvec3(v[0], v[1], v[2]);
        else if (track.path == "scale")
            node.scale = glm::dvec3(v[0], v[1], v[2]);
        else if (track.path == "rotation")
            node.rotation = glm::dquat(v[3], v[0], v[1], v[2]);
        else
            node.weights = std::vector<float>(v.begin(), v.end());
    }
    return nodes;
}

}  // namespace inkshade::io
