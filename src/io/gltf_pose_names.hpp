// The names a glTF/VRM file's pose can be given by (Mesh::pose_names): its animations with their
// durations, its morph target names and its VRM expressions, for `inkshade info` to list.
#pragma once
#include <string>

#include "inkshade/file_scene.hpp"
#include "io/gltf_accessors.hpp"

namespace tinygltf {
class Model;
}

namespace inkshade::io {

// Reads the names; throws nothing of its own: an animation whose keyframe times cannot be read
// has no duration (posing by it reports the problem). Warnings about expression binds are the
// pose's (GltfPose), not repeated.
FilePoseNames read_gltf_pose_names(const tinygltf::Model& model, const std::string& path,
                                   const GltfFloatReader& reader);

}  // namespace inkshade::io
