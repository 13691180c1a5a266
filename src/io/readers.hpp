// Per-format readers. Each throws InputError(path, problem) on bad input and returns the
// mesh as stored (triangulated, not yet welded or given normals): load_mesh does the rest.
#pragma once
#include <string>

#include "inkshade/io.hpp"
#include "inkshade/mesh.hpp"

namespace inkshade::io {

Mesh read_obj(const std::string& path);  // + MTL Kd and map_Kd, polygons fan-triangulated, negative indices
Mesh read_stl(const std::string& path);  // ASCII and binary; a triangle soup (3 vertices per face)
Mesh read_ply(const std::string& path);  // ascii, binary_little_endian, binary_big_endian
Mesh read_off(const std::string& path);  // OFF, with optional vertex colours (COFF)
// glTF 2.0 .gltf, GLB .glb and VRM .vrm: the default scene flattened, in the pose asked for.
Mesh read_gltf(const std::string& path, const Pose& pose = {});

// Any other format assimp reads (FBX, COLLADA .dae, 3DS, .blend, .x, ...), when Inkshade is
// built with it (INKSHADE_WITH_ASSIMP); without it assimp_reads is false and read_with_assimp
// throws. The scene is flattened with its node transforms; base colours and textures as for OBJ.
Mesh read_with_assimp(const std::string& path);
bool assimp_reads(const std::string& extension);  // ".fbx": true when assimp has an importer for it
std::string assimp_extensions();                  // ".3ds .ac ...", space-separated; empty without assimp

// read_obj that also reports whether the file is a soup anyway: exporters that write each
// face's corners as fresh `v` lines repeat most positions exactly, and need welding too.
Mesh read_obj(const std::string& path, bool& is_soup);

// True when the reader returned an unindexed soup that load_mesh must weld.
bool format_is_soup(const std::string& extension);

}  // namespace inkshade::io
