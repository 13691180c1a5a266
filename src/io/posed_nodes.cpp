// posed_nodes (inkshade/io.hpp): the nodes of a glTF/VRM file where GltfPose puts them.
#include <fstream>  // as in gltf_reader.cpp: tiny_gltf.h needs it with TINYGLTF_NO_FS

#include "io/tiny_gltf_config.hpp"

#include "inkshade/error.hpp"
#include "inkshade/io.hpp"
#include "io/gltf_accessors.hpp"
#include "io/gltf_container.hpp"
#include "io/gltf_pose.hpp"
#include "io/gltf_scene_nodes.hpp"
#include "io/vrm_humanoid.hpp"

namespace inkshade {

std::vector<PosedNode> posed_nodes(const std::string& path, const Pose& pose) {
    tinygltf::Model model;
    io::load_gltf_model(path, model);
    const io::GltfAccessorReader reader(model, path);
    std::vector<std::string> warnings;
    const io::GltfPose posed(model, path, pose, reader, &io::gltf_node_transform, warnings);
    std::vector<PosedNode> out(model.nodes.size());
    for (size_t i = 0; i < out.size(); ++i) {
        out[i].name = model.nodes[i].name;
        out[i].position = glm::dvec3(posed.world(i)[3]);
        out[i].morph_weights = posed.morph_weights(i);
    }
    try {
        if (const auto humanoid = io::read_vrm_humanoid(model, path, warnings))
            for (const auto& [bone, node] : humanoid->bones) out[size_t(node)].human_bone = bone;
    } catch (const InputError&) {  // a humanoid three-vrm would refuse names no bones
    }
    return out;
}

}  // namespace inkshade
