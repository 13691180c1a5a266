// The scene's node hierarchy (gltf_scene_nodes.hpp; glTF 2.0 sections 3.5.2-3.5.3).
#include "io/gltf_scene_nodes.hpp"

#include <fstream>  // as in gltf_container.cpp: tiny_gltf.h needs it with TINYGLTF_NO_FS

#include "io/tiny_gltf_config.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "inkshade/error.hpp"
#include "io/gltf_pose.hpp"

namespace inkshade::io {
namespace {

constexpr size_t kMaxNodeDepth = 1024;

// The roots of the default scene (or the first), or every node that is nobody's child.
std::vector<int> scene_roots(const tinygltf::Model& model, const std::string& path) {
    std::vector<int> roots;
    const int scene = model.defaultScene >= 0 ? model.defaultScene : (model.scenes.empty() ? -1 : 0);
    if (scene >= 0) {
        if (size_t(scene) >= model.scenes.size())
            throw InputError(path, "default scene " + std::to_string(scene) + " does not exist (the file has " +
                                       std::to_string(model.scenes.size()) + ")");
        roots = model.scenes[size_t(scene)].nodes;
    } else {  // no scene: every node that is nobody's child
        std::vector<char> is_child(model.nodes.size(), 0);
        for (const tinygltf::Node& n : model.nodes)
            for (int c : n.children)
                if (c >= 0 && size_t(c) < model.nodes.size()) is_child[size_t(c)] = 1;
        for (size_t i = 0; i < model.nodes.size(); ++i)
            if (!is_child[i]) roots.push_back(int(i));
    }
    return roots;
}

}  // namespace

glm::dmat4 gltf_node_transform(const tinygltf::Node& node, size_t index, const std::string& path) {
    auto bad = [&](const char* what) {
        throw InputError(path, "node " + std::to_string(index) + " has a bad " + what);
    };
    auto finite = [](const std::vector<double>& v) {
        return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
    };
    if (!node.matrix.empty()) {  // column-major, as glm (section 3.5.2)
        if (node.matrix.size() != 16 || !finite(node.matrix)) bad("matrix");
        return glm::make_mat4(node.matrix.data());
    }
    glm::dmat4 m(1.0);
    if (!node.translation.empty()) {
        if (node.translation.size() != 3 || !finite(node.translation)) bad("translation");
        m = glm::translate(m, glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
    }
    if (!node.rotation.empty()) {  // unit quaternion (x, y, z, w)
        if (node.rotation.size() != 4 || !finite(node.rotation)) bad("rotation");
        glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
        double len = glm::length(q);
        if (len > 0.0) m *= glm::mat4_cast(q / len);
    }
    if (!node.scale.empty()) {
        if (node.scale.size() != 3 || !finite(node.scale)) bad("scale");
        m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
    }
    return m;  // T * R * S
}

GltfSceneNodes gltf_scene_nodes(const tinygltf::Model& model, const std::string& path, const GltfPose& pose) {
    const std::vector<int> roots = scene_roots(model, path);
    GltfSceneNodes out;
    std::vector<char> visited(model.nodes.size(), 0);
    struct Item {
        int node;
        glm::dmat4 parent;
        size_t depth;
    };
    std::vector<Item> stack;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back({*it, glm::dmat4(1.0), 0});
    while (!stack.empty()) {
        Item item = stack.back();
        stack.pop_back();
        if (item.node < 0 || size_t(item.node) >= model.nodes.size())
            throw InputError(path, "scene refers to node " + std::to_string(item.node) + " but the file has " +
                                       std::to_string(model.nodes.size()));
        if (visited[size_t(item.node)]++)
            throw InputError(
                path, "node " + std::to_string(item.node) + " is reached twice (the node hierarchy must be a tree)");
        if (item.depth > kMaxNodeDepth)
            throw InputError(path, "node hierarchy deeper than " + std::to_string(kMaxNodeDepth));
        const tinygltf::Node& node = model.nodes[size_t(item.node)];
        const glm::dmat4 world = item.parent * pose.local(size_t(item.node));
        if (node.mesh >= 0) {
            if (size_t(node.mesh) >= model.meshes.size())
                throw InputError(path, "node " + std::to_string(item.node) + " refers to mesh " +
                                           std::to_string(node.mesh) + " but the file has " +
                                           std::to_string(model.meshes.size()));
            // A skinned mesh ignores its node's transform (section 3.7.3.3): its joints place it
            // (GltfPose::deform).
            out.meshes.push_back({item.node, node.mesh, node.skin >= 0 ? glm::dmat4(1.0) : world});
        }
        if (node.camera >= 0 || node.extensions.count("KHR_lights_punctual"))
            out.cameras_and_lights.push_back({item.node, world});
        for (auto c = node.children.rbegin(); c != node.children.rend(); ++c)
            stack.push_back({*c, world, item.depth + 1});
    }
    return out;
}

}  // namespace inkshade::io
