// What line sets select faces by, as each reader fills it (docs/inputs.md, "Objects and face
// marks"): object names and face marks per face, kept through load_mesh.
#include <gtest/gtest.h>

#include "inkshade/io.hpp"
#include "io/gltf_files.hpp"
#include "io/readers.hpp"
#include "support/temp_dir.hpp"

namespace inkshade::test {
namespace {

// The object name of each face.
std::vector<std::string> face_object_names(const Mesh& m) {
    std::vector<std::string> out;
    for (uint32_t o : m.face_objects) out.push_back(m.object_names.at(o));
    return out;
}

TEST(FaceLabels, ObjObjectsAreTheLastOOrGAndMarksTheSmoothingGroups) {
    TempDir dir;
    const std::string obj =
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\n"
        "o Body\ns 1\nf 1 2 3\nf 1 3 4\n"  // a quad: two triangles of Body, mark 1
        "g Lid\ns off\nf 1 2 5\n"          // Lid, unmarked
        "o Body\ns 300\nf 2 3 5\n";        // Body again, a group past 255
    const Mesh m = io::read_obj(dir.write("parts.obj", obj));
    ASSERT_EQ(m.triangle_count(), 4u);
    EXPECT_EQ(face_object_names(m), (std::vector<std::string>{"Body", "Body", "Lid", "Body"}));
    EXPECT_EQ(m.object_names.size(), 2u);  // one name, one object
    EXPECT_EQ(m.face_marks, (std::vector<uint8_t>{1, 1, 0, 255}));
}

TEST(FaceLabels, ObjWithoutObjectsOrGroupsHasNone) {
    TempDir dir;
    const Mesh m = io::read_obj(dir.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
    EXPECT_TRUE(m.face_objects.empty());
    EXPECT_TRUE(m.face_marks.empty());
}

TEST(FaceLabels, PlyFacemarkPropertyMarksEachPolygonsTriangles) {
    TempDir dir;
    const std::string ply =
        "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 2\nproperty uchar facemark\nproperty list uchar int vertex_indices\nend_header\n"
        "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n"
        "3 4 0 1 2 3\n"  // a quad with mark 3
        "0 3 0 1 4\n";   // unmarked
    const Mesh m = load_mesh(dir.write("marks.ply", ply));
    ASSERT_EQ(m.triangle_count(), 3u);
    EXPECT_EQ(m.face_marks, (std::vector<uint8_t>{3, 3, 0}));
}

// Two nodes instancing two meshes, the second's _FACEMARK marking one of its two triangles.
GltfBuilder two_named_nodes() {
    GltfBuilder g;
    const int pos = g.floats({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, "VEC3", 3);
    const int idx = g.data(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}, kUShort, 1, "SCALAR");
    const int mark = g.floats({0, 0, 0, 2}, "SCALAR", 1);  // corner 3 only
    const int mark_all = g.floats({2, 2, 2, 2}, "SCALAR", 1);
    const int plain = g.mesh({{"POSITION", pos}}, idx);
    const int marked = g.mesh({{"POSITION", pos}, {"_FACEMARK", mark_all}}, idx);
    const int partly = g.mesh({{"POSITION", pos}, {"_FACEMARK", mark}}, idx);
    g.doc["meshes"][size_t(partly)]["name"] = "PartlyMesh";
    g.scene({g.node({{"mesh", plain}, {"name", "Bracket"}}),
             g.node({{"mesh", marked}, {"name", "Bolt"}, {"translation", {2, 0, 0}}}),
             g.node({{"mesh", partly}, {"translation", {4, 0, 0}}})});
    return g;
}

TEST(FaceLabels, GltfObjectsAreNodeNamesAndMarksTheSmallestCornerFacemark) {
    TempDir dir;
    const Mesh m = io::read_gltf(dir.write("nodes.glb", two_named_nodes().glb()));
    ASSERT_EQ(m.triangle_count(), 6u);
    // An unnamed node takes its mesh's name.
    EXPECT_EQ(face_object_names(m),
              (std::vector<std::string>{"Bracket", "Bracket", "Bolt", "Bolt", "PartlyMesh", "PartlyMesh"}));
    // No corner of (0, 1, 2) or (0, 2, 3) of the last mesh has all three marked: both 0.
    EXPECT_EQ(m.face_marks, (std::vector<uint8_t>{0, 0, 2, 2, 0, 0}));
}

TEST(FaceLabels, LoadMeshKeepsThemThroughWelding) {
    TempDir dir;
    const Mesh m = load_mesh(dir.write("nodes.glb", two_named_nodes().glb()));
    ASSERT_EQ(m.face_objects.size(), m.triangle_count());
    ASSERT_EQ(m.face_marks.size(), m.triangle_count());
    EXPECT_EQ(m.object_names.at(m.face_objects[2]), "Bolt");
    EXPECT_EQ(m.face_marks[2], 2);
}

}  // namespace
}  // namespace inkshade::test
