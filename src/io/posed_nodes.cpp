// posed_nodes (inkshade/io.hpp): the nodes of a glTF/VRM file where GltfPose puts them.
#include <fstream>  // as in gltf_reader.cpp: tiny_gltf.h needs it with TINYGLTF_NO_FS

#include "io/tiny_gltf_config.hpp"

#include "inkshade/io.hpp"
#include "io/gltf_container.hpp"
#include "io/gltf_pose.hpp"
#include "io/gltf_scene_nodes.hpp"

namespace inkshade {

std::vector<PosedNode> posed_nodes(const std::string& path, const Pose& pose) {
    tinygltf::Model model;
    io::load_gltf_model(path, model);
    const io::GltfAccessorReader reader(model, path);
    std::vector<std::string> warnings;
    const io::GltfPose posed(model, path, pose, reader, &io::gltf_node_transform, warnings);
    std::vector<PosedNode> nodes;
    for (size_t i = 0; i < model.nodes.size(); ++i)
        nodes.push_back({model.nodes[i].name, glm::dvec3(posed.world(i)[3])});
    return nodes;
}

}  // namespace inkshade
