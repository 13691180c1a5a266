// Loading meshes from files (OBJ, STL, PLY, OFF, glTF 2.0 / GLB / VRM) and built-in models
// ("builtin:NAME"). docs/inputs.md says what each format contributes.
#pragma once
#include <string>
#include <vector>

#include "inkshade/mesh.hpp"

namespace inkshade {

// A weight given to a name: a morph target (NAME=W) or a VRM expression.
struct NamedWeight {
    std::string name;
    float weight = 0.0f;
    bool operator==(const NamedWeight&) const = default;
};

// The pose a glTF/VRM file is loaded in (docs/inputs.md, "Posed and animated glTF"): the file's
// node transforms and morph weights, then an animation sampled at `time`, then VRM expressions,
// then morph weights by name; skins deform the mesh on the CPU, so every later stage sees the
// posed triangles. The default is the file as it is (its rest pose and default weights).
struct Pose {
    // A glTF animation, by name or index, or a VRM animation file (a path ending in .vrma,
    // retargeted to a VRM avatar's humanoid); empty = none.
    std::string animation;
    // Seconds into the animation, clamped to its keyframes' range.
    float time = 0.0f;
    // VRM expressions (VRM 1.0 preset or custom names; VRM 0.x presets by their 1.0 names, as
    // three-vrm names them), weights in [0, 1], in order.
    std::vector<NamedWeight> expressions;
    // Morph target weights by name (mesh.extras.targetNames), in order; the last one wins.
    std::vector<NamedWeight> morphs;
    // VRM spring bones (VRMC_springBone, VRM 0.x secondary animation) simulated from the file's
    // pose at t = 0 to `time` in 1/60 s steps, as three-vrm moves them; off: the joints keep the
    // file's (or the animation's) rotations.
    bool spring_bones = true;

    // Whether nothing but the file's own pose is asked for (`time` alone moves only spring bones).
    bool is_rest() const { return animation.empty() && expressions.empty() && morphs.empty(); }
    bool operator==(const Pose&) const = default;
};

struct LoadOptions {
    // Welding epsilon relative to the bounding-box diagonal (triangle soups: STL, unwelded OBJ).
    float weld_epsilon = 1e-6f;
    // Compute angle-weighted vertex normals when the file has none (or they are not sane).
    bool compute_normals = true;
    // Drop faces with the same vertex set as an earlier face (either winding; compared after
    // welding), keeping the first, with one warning giving the count. `inkshade info` turns this
    // off to report what the file holds. Built-in models have none.
    bool drop_duplicate_faces = true;
    // Auto-smooth for files without normals: shading normals split at edges whose faces meet at
    // more than this many degrees (Mesh::shading_splits); 180 = one smooth normal per vertex.
    float smooth_angle = 30.0f;
    // How computed normals weight the faces: by angle, or by area as three.js does (Scene's
    // load_options asks for it in the three.js convention).
    NormalWeighting normal_weighting = NormalWeighting::Angle;
    // The pose of a glTF/VRM file; a pose other than the rest pose is an error for other formats.
    Pose pose;
};

// Loads a mesh by path or "builtin:NAME". Throws InputError("FILE: problem") on bad input.
// The result is indexed, validated (indices in range, finite coordinates) and has normals.
// Problems that do not stop the load (a texture that cannot be read) are in Mesh::warnings.
Mesh load_mesh(const std::string& path, const LoadOptions& options = {});

// A node of a glTF/VRM file and where a pose puts it (world space, the file's units).
struct PosedNode {
    std::string name;
    glm::dvec3 position{0.0};
    std::string human_bone;            // its VRM humanoid bone ("" when none)
    std::vector<float> morph_weights;  // its mesh's morph target weights in the pose (empty: none)
};

// Every node of a glTF, GLB or VRM file, in file order, placed as load_mesh places them in
// `pose` (animation, VRM animation, look-at, node constraints, spring bones): for comparing a
// pose with other tools' (three-vrm's). Throws InputError as load_mesh does.
std::vector<PosedNode> posed_nodes(const std::string& path, const Pose& pose);

// Every file extension load_mesh reads, space-separated: ".obj .stl .ply .off .gltf .glb .vrm"
// and, when built with assimp, the other formats it has importers for.
std::string readable_extensions();

// Names accepted after "builtin:" (sphere, torus, torus-knot, teapot).
std::vector<std::string> builtin_model_names();

}  // namespace inkshade
