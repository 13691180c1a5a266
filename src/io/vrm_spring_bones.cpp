#include "io/vrm_spring_bones.hpp"

#include <fstream>  // as in gltf_reader.cpp: tiny_gltf.h needs it with TINYGLTF_NO_FS

#include "io/tiny_gltf_config.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "inkshade/error.hpp"
#include "io/gltf_names.hpp"
#include "io/gltf_value_member.hpp"

namespace inkshade::io {

namespace {

// "9", "-1", "0.5": a number as the file might spell it.
std::string number_text(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

bool uses(const tinygltf::Model& model, const std::string& extension) {
    return std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(), extension) != model.extensionsUsed.end();
}

// Reads one extension's values, each checked, naming the value in its errors.
class Values {
public:
    Values(const tinygltf::Model& model, const std::string& path) : model_(model), path_(path) {}

    [[noreturn]] void fail(const std::string& problem) const { throw InputError(path_, problem); }

    // A number member, `fallback` when absent; an error when present and not a finite number.
    double number(const tinygltf::Value& object, const char* key, double fallback, const std::string& what) const {
        const tinygltf::Value& v = member(object, key);
        if (v.Type() == tinygltf::NULL_TYPE) return fallback;
        if (!v.IsNumber() || !std::isfinite(v.GetNumberAsDouble())) fail(what + "." + key + " is not a finite number");
        return v.GetNumberAsDouble();
    }

    // A number at least `min` (and at most `max`).
    double bounded(const tinygltf::Value& object, const char* key, double fallback, const std::string& what, double min,
                   double max = INFINITY) const {
        const double v = number(object, key, fallback, what);
        if (v < min || v > max)
            fail(what + "." + key + " is " + number_text(v) + ", outside [" + number_text(min) +
                 (std::isinf(max) ? ", inf)" : ", " + number_text(max) + "]"));
        return v;
    }

    // An index below `count`; `fallback` when absent (-2: required).
    int index(const tinygltf::Value& object, const char* key, size_t count, const std::string& what,
              const std::string& of, int fallback = -2) const {
        const tinygltf::Value& v = member(object, key);
        if (v.Type() == tinygltf::NULL_TYPE && fallback != -2) return fallback;
        return index(v, count, what + "." + key, of);
    }
    int index(const tinygltf::Value& v, size_t count, const std::string& what, const std::string& of) const {
        const double d = v.IsNumber() ? v.GetNumberAsDouble() : -1.0;
        if (!(d >= 0.0 && d < double(count) && d == std::floor(d)))
            fail(what + " is " + (v.IsNumber() ? number_text(d) : std::string("not an index")) + " but the file has " +
                 std::to_string(count) + " " + of);
        return int(d);
    }
    int node(const tinygltf::Value& object, const char* key, const std::string& what, int fallback = -2) const {
        return index(object, key, model_.nodes.size(), what, "nodes", fallback);
    }

    // [x, y, z] (VRMC_springBone) or {x, y, z} (VRM 0.x), `fallback` when absent.
    glm::dvec3 vec3(const tinygltf::Value& object, const char* key, glm::dvec3 fallback,
                    const std::string& what) const {
        const tinygltf::Value& v = member(object, key);
        if (v.Type() == tinygltf::NULL_TYPE) return fallback;
        const std::string name = what + "." + key;
        if (v.IsObject()) return {number(v, "x", 0.0, name), number(v, "y", 0.0, name), number(v, "z", 0.0, name)};
        if (!v.IsArray() || v.ArrayLen() != 3) fail(name + " is not 3 numbers");
        glm::dvec3 out;
        for (int k = 0; k < 3; ++k) {
            const tinygltf::Value& c = v.Get(k);
            if (!c.IsNumber() || !std::isfinite(c.GetNumberAsDouble())) fail(name + " is not 3 finite numbers");
            out[k] = c.GetNumberAsDouble();
        }
        return out;
    }

    // The entries of an array member (none when absent).
    std::vector<const tinygltf::Value*> array(const tinygltf::Value& object, const char* key,
                                              const std::string& what) const {
        const tinygltf::Value& v = member(object, key);
        std::vector<const tinygltf::Value*> out;
        if (v.Type() == tinygltf::NULL_TYPE) return out;
        if (!v.IsArray()) fail(what + "." + key + " is not an array");
        for (size_t i = 0; i < v.ArrayLen(); ++i) out.push_back(&v.Get(int(i)));
        return out;
    }

    // The joint settings three-vrm's VRMSpringBoneJoint reads, with its defaults.
    void settings(const tinygltf::Value& o, const char* stiffness, SpringJoint& j, const std::string& what) const {
        j.hit_radius = bounded(o, "hitRadius", 0.0, what, 0.0);
        j.stiffness = bounded(o, stiffness, 1.0, what, 0.0);
        j.gravity_power = bounded(o, "gravityPower", 0.0, what, 0.0);
        j.drag_force = bounded(o, "dragForce", 0.4, what, 0.0, 1.0);
        j.gravity_dir = vec3(o, "gravityDir", {0.0, -1.0, 0.0}, what);
    }

    void add(SpringBones& bones, SpringJoint joint) const {
        if (bones.joints.size() >= kMaxSpringJoints)
            fail("more than " + std::to_string(kMaxSpringJoints) + " spring bone joints");
        bones.joints.push_back(std::move(joint));
    }

    const tinygltf::Model& model_;
    const std::string& path_;
};

// The collider indices of the groups `groups` lists, in order (three-vrm's joint.colliderGroups).
std::vector<int> group_colliders(const Values& in, const std::vector<const tinygltf::Value*>& groups,
                                 const std::vector<std::vector<int>>& members, const std::string& what) {
    std::vector<int> out;
    for (size_t g = 0; g < groups.size(); ++g) {
        const int group = in.index(*groups[g], members.size(), what + ".colliderGroups[" + std::to_string(g) + "]",
                                   "collider groups");
        out.insert(out.end(), members[size_t(group)].begin(), members[size_t(group)].end());
    }
    return out;
}

// VRMC_springBone 1.0: a spring's joints pair each with the next (the last is only a tail).
SpringBones read_v1(const Values& in, const tinygltf::Value& ext, std::vector<std::string>& warnings) {
    SpringBones bones;
    std::vector<int> collider_at;  // file collider -> bones.colliders index, -1: skipped
    const auto colliders = in.array(ext, "colliders", "VRMC_springBone");
    for (size_t c = 0; c < colliders.size(); ++c) {
        const std::string what = "VRMC_springBone.colliders[" + std::to_string(c) + "]";
        SpringCollider col;
        col.node = in.node(*colliders[c], "node", what);
        const tinygltf::Value& shape = member(*colliders[c], "shape");
        const tinygltf::Value& sphere = member(shape, "sphere");
        const tinygltf::Value& capsule = member(shape, "capsule");
        const tinygltf::Value& s = sphere.IsObject() ? sphere : capsule;
        if (!s.IsObject()) {
            warnings.push_back(in.path_ + ": " + what + " has no sphere or capsule shape; skipped");
            collider_at.push_back(-1);
            continue;
        }
        col.capsule = !sphere.IsObject();
        col.offset = in.vec3(s, "offset", glm::dvec3(0.0), what + ".shape");
        col.radius = in.bounded(s, "radius", 0.0, what + ".shape", 0.0);
        if (col.capsule) col.tail = in.vec3(s, "tail", glm::dvec3(0.0), what + ".shape");
        collider_at.push_back(int(bones.colliders.size()));
        bones.colliders.push_back(col);
    }
    std::vector<std::vector<int>> groups;
    const auto group_list = in.array(ext, "colliderGroups", "VRMC_springBone");
    for (size_t g = 0; g < group_list.size(); ++g) {
        const std::string what = "VRMC_springBone.colliderGroups[" + std::to_string(g) + "]";
        groups.emplace_back();
        const auto members = in.array(*group_list[g], "colliders", what);
        for (size_t m = 0; m < members.size(); ++m) {
            const int c =
                in.index(*members[m], colliders.size(), what + ".colliders[" + std::to_string(m) + "]", "colliders");
            if (collider_at[size_t(c)] >= 0) groups.back().push_back(collider_at[size_t(c)]);
        }
    }
    const auto springs = in.array(ext, "springs", "VRMC_springBone");
    for (size_t s = 0; s < springs.size(); ++s) {
        const std::string what = "VRMC_springBone.springs[" + std::to_string(s) + "]";
        const std::vector<int> cols = group_colliders(in, in.array(*springs[s], "colliderGroups", what), groups, what);
        const int center = in.node(*springs[s], "center", what, -1);
        const auto joints = in.array(*springs[s], "joints", what);
        for (size_t k = 0; k + 1 < joints.size(); ++k) {
            const std::string jw = what + ".joints[" + std::to_string(k) + "]";
            SpringJoint j;
            j.node = in.node(*joints[k], "node", jw);
            j.child = in.node(*joints[k + 1], "node", what + ".joints[" + std::to_string(k + 1) + "]");
            in.settings(*joints[k], "stiffness", j, jw);
            j.colliders = cols;
            j.center = center;
            in.add(bones, std::move(j));
        }
    }
    return bones;
}

// VRM 0.x secondaryAnimation: every node of a bone group's roots' subtrees is a joint whose tail
// is its first child (three.js's Object3D.traverse order: the node, then each child's subtree).
SpringBones read_v0(const Values& in, const tinygltf::Value& secondary) {
    SpringBones bones;
    std::vector<std::vector<int>> groups;
    const auto group_list = in.array(secondary, "colliderGroups", "VRM.secondaryAnimation");
    for (size_t g = 0; g < group_list.size(); ++g) {
        const std::string what = "VRM.secondaryAnimation.colliderGroups[" + std::to_string(g) + "]";
        const int node = in.node(*group_list[g], "node", what);
        groups.emplace_back();
        const auto colliders = in.array(*group_list[g], "colliders", what);
        for (size_t c = 0; c < colliders.size(); ++c) {
            const std::string cw = what + ".colliders[" + std::to_string(c) + "]";
            SpringCollider col{.node = node};
            col.offset = in.vec3(*colliders[c], "offset", glm::dvec3(0.0), cw);
            col.offset.z = -col.offset.z;  // VRM 0.x's z points the other way (three-vrm _v0Import)
            col.radius = in.bounded(*colliders[c], "radius", 0.0, cw, 0.0);
            groups.back().push_back(int(bones.colliders.size()));
            bones.colliders.push_back(col);
        }
    }
    const auto bone_groups = in.array(secondary, "boneGroups", "VRM.secondaryAnimation");
    for (size_t b = 0; b < bone_groups.size(); ++b) {
        const std::string what = "VRM.secondaryAnimation.boneGroups[" + std::to_string(b) + "]";
        SpringJoint settings;
        in.settings(*bone_groups[b], "stiffiness", settings, what);  // sic: VRM 0.x's spelling
        settings.colliders = group_colliders(in, in.array(*bone_groups[b], "colliderGroups", what), groups, what);
        // A center of -1 (as VRM 0.x exporters write) or none: world space.
        const tinygltf::Value& center = member(*bone_groups[b], "center");
        settings.center =
            center.IsNumber() && center.GetNumberAsDouble() == -1.0 ? -1 : in.node(*bone_groups[b], "center", what, -1);
        const auto roots = in.array(*bone_groups[b], "bones", what);
        for (size_t r = 0; r < roots.size(); ++r) {
            std::vector<int> stack = {
                in.index(*roots[r], in.model_.nodes.size(), what + ".bones[" + std::to_string(r) + "]", "nodes")};
            while (!stack.empty()) {
                const int n = stack.back();
                stack.pop_back();
                const std::vector<int>& children = in.model_.nodes[size_t(n)].children;
                SpringJoint j = settings;
                j.node = n;
                j.child = children.empty() ? -1 : children[0];
                for (int c : children)
                    if (c < 0 || size_t(c) >= in.model_.nodes.size())
                        in.fail("node " + std::to_string(n) + " has child " + std::to_string(c) + " but the file has " +
                                std::to_string(in.model_.nodes.size()) + " nodes");
                in.add(bones, std::move(j));  // bounds the walk: a cycle of nodes runs into the cap
                for (auto it = children.rbegin(); it != children.rend(); ++it) stack.push_back(*it);
            }
        }
    }
    return bones;
}

}  // namespace

SpringBones read_vrm_spring_bones(const tinygltf::Model& model, const std::string& path,
                                  std::vector<std::string>& warnings) {
    const Values in(model, path);
    if (uses(model, "VRMC_springBone")) {
        const auto it = model.extensions.find("VRMC_springBone");
        if (it != model.extensions.end()) {
            const tinygltf::Value& version = member(it->second, "specVersion");
            const std::string v = version.IsString() ? version.Get<std::string>() : "";
            if (v == "1.0" || v == "1.0-beta") return read_v1(in, it->second, warnings);
            warnings.push_back(path + ": VRMC_springBone specVersion '" + printable_name(v) +
                               "' is not 1.0; its spring bones are ignored");
            return {};
        }
    }
    if (!uses(model, "VRM")) return {};
    const auto it = model.extensions.find("VRM");
    if (it == model.extensions.end()) return {};
    const tinygltf::Value& secondary = member(it->second, "secondaryAnimation");
    if (!member(secondary, "boneGroups").IsArray()) return {};
    return read_v0(in, secondary);
}

}  // namespace inkshade::io
