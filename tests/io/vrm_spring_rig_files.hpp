// The rig avatar of vrm_rig_files.hpp with spring bone hair (VRMC_springBone 1.0) for the tests
// of springs driven by a VRM animation, node constraints or a glTF animation: a chain on the
// head (its root's parent, which a .vrma turns), a chain on a node that a rotation constraint
// turns as the head turns (between the animated bone and the spring's root), and a glTF
// animation "nod" turning the head node itself.
#pragma once
#include <string>
#include <vector>

#include "io/vrm_rig_files.hpp"

namespace inkshade::test {

// The index of the node named `name` (-1: none).
inline int rig_node(const GltfBuilder& g, const std::string& name) {
    for (size_t i = 0; i < g.doc["nodes"].size(); ++i)
        if (g.doc["nodes"][i].value("name", "") == name) return int(i);
    return -1;
}

// A chain of `segments` joints and a tail under `parent`, its root at `offset`, each next node
// `step` further (local); returns the spring's joints JSON (the tail last, as VRMC_springBone
// lists it).
inline nlohmann::json add_hair_chain(GltfBuilder& g, int parent, const std::string& name, glm::dvec3 offset,
                                     glm::dvec3 step, int segments) {
    nlohmann::json joints = nlohmann::json::array();
    int at = parent;
    for (int k = 0; k <= segments; ++k) {
        at = add_tip(g, at, name + std::to_string(k + 1), k == 0 ? offset : step);
        joints.push_back({{"node", at},
                          {"hitRadius", 0.02},
                          {"stiffness", 0.6},
                          {"gravityPower", 1.5},
                          {"gravityDir", {0, -1, 0}},
                          {"dragForce", 0.35}});
    }
    return joints;
}

// The rig avatar (VRM 1.0) with the hair chains "HeadHair" (on the head) and "BackHair" (on
// "HairBase", under the chest, which a rotation constraint turns as the head turns), and the
// glTF animation "nod" (the head's raw rotation, 2 s).
inline GltfBuilder rig_avatar_with_hair() {
    GltfBuilder g = rig_avatar(false);
    const int head = rig_node(g, "J_head"), chest = rig_node(g, "J_chest");
    const int base = add_constraint(g, chest, "HairBase", {0, 0.1, -0.1}, axis_degrees({1, 0, 0}, 10), "rotation",
                                    {{"source", head}, {"weight", 1.0}});
    const nlohmann::json springs = {
        {{"name", "HeadHair"}, {"joints", add_hair_chain(g, head, "HeadHair", {0, 0.04, -0.09}, {0, -0.07, -0.02}, 3)}},
        {{"name", "BackHair"}, {"joints", add_hair_chain(g, base, "BackHair", {0, 0, -0.04}, {0.01, -0.08, 0}, 3)}}};
    g.doc["extensionsUsed"].push_back("VRMC_springBone");
    g.doc["extensions"]["VRMC_springBone"] = {{"specVersion", "1.0"}, {"springs", springs}};

    nlohmann::json nod = {
        {"name", "nod"}, {"samplers", nlohmann::json::array()}, {"channels", nlohmann::json::array()}};
    const std::vector<float> times = {0.0f, 0.5f, 1.0f, 2.0f};
    const std::vector<double> angles = {0, 50, -30, 45};
    const nlohmann::json& r = g.doc["nodes"][size_t(head)]["rotation"];
    const glm::dquat rest(r[3].get<double>(), r[0].get<double>(), r[1].get<double>(), r[2].get<double>());
    std::vector<float> values;
    for (double a : angles) {
        const glm::dquat q = rest * axis_degrees({1, 0.3, 0.2}, a);
        values.insert(values.end(), {float(q.x), float(q.y), float(q.z), float(q.w)});
    }
    add_track(g, nod, head, "rotation", times, values, "VEC4");
    g.doc["animations"] = {nod};
    return g;
}

}  // namespace inkshade::test
