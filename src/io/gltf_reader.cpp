// glTF 2.0 (.gltf with .bin files or data: URIs) and GLB (.glb; .vrm avatars are GLB) through
// tinygltf (Debian's header-only tiny_gltf.h, compiled in gltf_container.cpp). tinygltf parses
// the JSON and loads buffers, but trusts accessor and bufferView sizes, so every byte range is
// checked before it is read (gltf_accessors.cpp), and counts are bounded before anything is
// allocated from them. tinygltf gets no file system of its own: buffers come through callbacks
// that only read regular files (gltf_container.cpp), and images are decoded by the material
// reader (stb_image; gltf_materials.cpp), so a bad texture is a warning, never a failure.
//
// What is read (section numbers are the glTF 2.0 specification's):
// - the default scene (or the first scene, or every root node when there is none), node
//   hierarchies with matrix or TRS transforms (3.5.2-3.5.3; gltf_scene_nodes.cpp); normals by
//   the inverse transpose, and a mirroring transform flips the winding so front faces stay
//   counter-clockwise (3.7.4);
// - TRIANGLES, TRIANGLE_STRIP and TRIANGLE_FAN primitives (3.7.2.1; gltf_mesh_builder.cpp);
//   points and lines skipped;
// - POSITION, NORMAL, TEXCOORD_n, COLOR_0 in any component type the spec or
//   KHR_mesh_quantization allows, sparse accessors (3.6.2.3), accessors without a bufferView;
// - pbrMetallicRoughness baseColorFactor and baseColorTexture (3.9.2) with its KHR_texture_transform
//   (texture_transform.cpp), alphaMode, alphaCutoff
//   and doubleSided (3.9.4-3.9.5), KHR_materials_unlit, VRM 0.x and VRM 1.0 MToon parameters
//   and textures with an MToon material's emissive and normal map (gltf_materials.cpp,
//   vrm_materials.cpp);
// - the nodes' cameras (3.10) and KHR_lights_punctual lights (gltf_cameras_lights.cpp);
// - skins, morph targets, animations and VRM expressions, posed as LoadOptions::pose asks
//   (gltf_pose.cpp and the files it uses).
#include <fstream>  // as in gltf_container.cpp: tiny_gltf.h needs it with TINYGLTF_NO_FS

#include "io/tiny_gltf_config.hpp"

#include <string>

#include "inkshade/error.hpp"
#include "io/gltf_accessors.hpp"
#include "io/gltf_cameras_lights.hpp"
#include "io/gltf_container.hpp"
#include "io/gltf_mesh_builder.hpp"
#include "io/gltf_pose.hpp"
#include "io/gltf_pose_names.hpp"
#include "io/gltf_scene_nodes.hpp"
#include "io/readers.hpp"

namespace inkshade::io {

Mesh read_gltf(const std::string& path, const Pose& pose) {
    tinygltf::Model model;
    load_gltf_model(path, model);

    Mesh mesh;
    const GltfAccessorReader reader(model, path);
    const GltfPose posed(model, path, pose, reader, &gltf_node_transform, mesh.warnings);
    GltfMeshBuilder builder(model, path, mesh, reader);
    const GltfSceneNodes nodes = gltf_scene_nodes(model, path, posed);
    for (const GltfInstance& instance : nodes.meshes) builder.add(instance, posed);
    builder.finish();
    add_gltf_cameras(model, nodes.cameras_and_lights, path, mesh);
    add_gltf_lights(model, nodes.cameras_and_lights, path, mesh);
    mesh.pose_names = read_gltf_pose_names(model, path, reader);
    if (mesh.triangles.empty()) {
        if (builder.skipped() > 0)
            throw InputError(path, "no triangles (only point or line primitives: " + std::to_string(builder.skipped()) +
                                       " skipped)");
        if (!mesh.line_segments.empty()) throw InputError(path, "no triangles (only line primitives)");
        throw InputError(path, "no triangles (the scene has no mesh)");
    }
    return mesh;
}

}  // namespace inkshade::io
