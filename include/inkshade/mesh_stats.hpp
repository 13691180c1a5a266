// Topological facts about a mesh, as `inkshade info` and the viewer's model panel give them.
#pragma once
#include <cstddef>

#include "inkshade/mesh.hpp"

namespace inkshade {

struct MeshStats {
    size_t vertices = 0;
    size_t triangles = 0;
    size_t edges = 0;               // undirected unique edges
    size_t boundary_edges = 0;      // edges with one incident face
    size_t non_manifold_edges = 0;  // edges with more than two incident faces
    size_t degenerate_faces = 0;    // repeated index or zero area
    size_t duplicate_faces = 0;     // same vertex set as an earlier face
    size_t components = 0;          // connected components over faces sharing vertices
    size_t unreferenced_vertices = 0;
    long euler_characteristic = 0;  // V - E + F over referenced vertices
};

MeshStats mesh_stats(const Mesh& mesh);

}  // namespace inkshade
