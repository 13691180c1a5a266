#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <filesystem>

#include "io/mesh_files.hpp"
#include "support/temp_dir.hpp"

namespace inkshade::test {
namespace {

TEST(LoadMesh, MissingFileSaysSo) {
    TempDir dir;
    EXPECT_TRUE(LoadFailsWith(dir.file("absent.obj"), "cannot open file (No such file or directory)"));
}

TEST(LoadMesh, DirectoryIsNotAFile) {
    TempDir dir;
    std::filesystem::create_directory(dir.file("folder.ply"));
    EXPECT_TRUE(LoadFailsWith(dir.file("folder.ply"), "is a directory"));
}

TEST(LoadMesh, UnknownExtensionListsTheSupportedOnes) {
    TempDir dir;
    EXPECT_TRUE(LoadFailsWith(dir.write("mesh.xyz", "1 2 3\n"),
                              "unknown file extension '.xyz' (supported: .obj .stl .ply .off .gltf .glb .vrm"));
    EXPECT_TRUE(LoadFailsWith(dir.write("mesh", "1 2 3\n"),
                              "no file extension (supported: .obj .stl .ply .off .gltf .glb .vrm"));
}

TEST(LoadMesh, ExtensionIsCaseInsensitive) {
    TempDir dir;
    Mesh m = load_mesh(dir.write("CUBE.STL", cube_binary_stl()));
    EXPECT_EQ(m.vertex_count(), 8u);
}

TEST(LoadMesh, EmptyFileOfEveryFormatIsAnError) {
    TempDir dir;
    for (const char* name : {"e.obj", "e.stl", "e.ply", "e.off"})
        EXPECT_TRUE(LoadFailsWith(dir.write(name, ""), "empty file"));
}

TEST(LoadMesh, BuiltinModelsLoadByName) {
    auto names = builtin_model_names();
    for (const char* expected : {"sphere", "torus", "torus-knot", "teapot"})
        EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
    Mesh m = load_mesh("builtin:sphere");
    EXPECT_GT(m.triangle_count(), 100u);
    EXPECT_EQ(m.normals.size(), m.vertex_count());
    EXPECT_THROW(load_mesh("builtin:no-such-model"), InputError);
}

TEST(LoadMesh, NormalsAreComputedUnlessDisabled) {
    TempDir dir;
    std::string p = dir.write("cube.off", cube_off());
    Mesh m = load_mesh(p);
    ASSERT_EQ(m.normals.size(), 8u);
    for (auto n : m.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
    // The (0,0,0) corner's normal points away from the cube, along -(1,1,1).
    EXPECT_NEAR(glm::dot(m.normals[0], glm::normalize(glm::vec3(-1))), 1.0f, 1e-4f);
    LoadOptions no_normals;
    no_normals.compute_normals = false;
    EXPECT_TRUE(load_mesh(p, no_normals).normals.empty());
}

TEST(LoadMesh, ZeroAreaFacesLoadAndDuplicatesAreDropped) {
    TempDir dir;
    std::string s =
        "OFF\n5 4 0\n0 0 0\n1 0 0\n0 1 0\n2 0 0\n0 0 1\n"
        "3 0 1 2\n3 0 1 2\n3 0 1 3\n3 4 4 4\n";  // duplicate, collinear, collapsed
    Mesh m = load_mesh(dir.write("degenerate.off", s));
    EXPECT_EQ(m.triangle_count(), 3u);
    EXPECT_EQ(m.normals.size(), m.vertex_count());
    for (auto n : m.normals) EXPECT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
}

// The message load_mesh gives for `count` dropped faces of `path`.
std::string dropped_warning(const std::string& path, size_t count) {
    return path + ": dropped " + std::to_string(count) + " duplicate face" + (count == 1 ? "" : "s") +
           " (same vertices as an earlier face, either winding)";
}

TEST(LoadMesh, DuplicateFacesOfEitherWindingAreDroppedWithOneWarning) {
    TempDir dir;
    // The cube with quads repeated: one as written, one reversed, one rotated (each two triangles).
    std::string off = cube_off();
    const std::string header = "OFF\n# unit cube\n8 6 12\n";
    ASSERT_EQ(off.rfind(header, 0), 0u);
    off.replace(0, header.size(), "OFF\n8 9 12\n");
    off += "4 0 3 2 1\n4 0 1 2 3\n4 6 7 4 5\n";
    const std::string p = dir.write("dup.off", off);
    Mesh m = load_mesh(p);
    EXPECT_EQ(m.triangle_count(), 12u);
    EXPECT_EQ(m.vertex_count(), 8u);
    EXPECT_EQ(m.warnings, std::vector<std::string>{dropped_warning(p, 6)});
    EXPECT_EQ(sorted_positions(m), sorted_cube());
    // The kept faces are the cube's own, in the file's order, with its orientation.
    for (size_t t = 0; t < 12; ++t)
        EXPECT_EQ(m.triangles[t], glm::uvec3(cube_triangles()[t][0], cube_triangles()[t][1], cube_triangles()[t][2]));
    for (auto n : m.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);

    LoadOptions keep;
    keep.drop_duplicate_faces = false;
    Mesh all = load_mesh(p, keep);
    EXPECT_EQ(all.triangle_count(), 18u);
    EXPECT_TRUE(all.warnings.empty());
}

TEST(LoadMesh, DroppedDuplicatesKeepFaceMaterialsAligned) {
    TempDir dir;
    dir.write("colours.mtl", "newmtl red\nKd 1 0 0\n\nnewmtl blue\nKd 0 0 1\n\nnewmtl green\nKd 0 1 0\n");
    const std::string obj =
        "mtllib colours.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\n"
        "usemtl red\nf 1 2 3\nusemtl blue\nf 3 2 1\nf 1 3 4\nusemtl green\nf 2 3 1\nf 2 5 3\nusemtl blue\nf 4 1 3\n";
    const std::string p = dir.write("dup.obj", obj);
    Mesh m = load_mesh(p);
    ASSERT_EQ(m.triangle_count(), 3u);
    ASSERT_EQ(m.face_materials.size(), 3u);
    EXPECT_EQ(m.triangles[0], glm::uvec3(0, 1, 2));
    EXPECT_EQ(m.triangles[1], glm::uvec3(0, 2, 3));
    EXPECT_EQ(m.triangles[2], glm::uvec3(1, 4, 2));
    EXPECT_EQ(m.materials[m.face_materials[0]].name, "red");
    EXPECT_EQ(m.materials[m.face_materials[1]].name, "blue");
    EXPECT_EQ(m.materials[m.face_materials[2]].name, "green");
    EXPECT_EQ(m.warnings, std::vector<std::string>{dropped_warning(p, 3)});
}

TEST(LoadMesh, DuplicatesAreFoundAfterWelding) {
    TempDir dir;
    auto soup = cube_soup();
    soup.push_back(soup[3]);                               // as written
    soup.push_back({soup[5][0], soup[5][2], soup[5][1]});  // reversed
    const std::string p = dir.write("dup.stl", binary_stl(soup));
    Mesh m = load_mesh(p);
    EXPECT_EQ(m.vertex_count(), 8u);
    EXPECT_EQ(m.triangle_count(), 12u);
    EXPECT_EQ(m.warnings, std::vector<std::string>{dropped_warning(p, 2)});
}

TEST(LoadMesh, AFaceAndItsReverseKeepOneFace) {
    TempDir dir;
    const std::string p = dir.write("pair.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 3 2\n");
    Mesh m = load_mesh(p);
    ASSERT_EQ(m.triangle_count(), 1u);
    EXPECT_EQ(m.triangles[0], glm::uvec3(0, 1, 2));
    EXPECT_EQ(m.warnings, std::vector<std::string>{dropped_warning(p, 1)});
    ASSERT_EQ(m.normals.size(), 3u);
    EXPECT_NEAR(m.normals[0].z, 1.0f, 1e-6f);
}

TEST(LoadMesh, NoDuplicatesNoWarning) {
    TempDir dir;
    for (auto [name, bytes] : std::vector<std::pair<std::string, std::string>>{
             {"a.obj", cube_obj()}, {"b.stl", cube_binary_stl()}, {"c.ply", cube_ascii_ply()}, {"d.off", cube_off()}}) {
        Mesh m = load_mesh(dir.write(name, bytes));
        EXPECT_EQ(m.triangle_count(), 12u) << name;
        EXPECT_TRUE(m.warnings.empty()) << name;
    }
    EXPECT_TRUE(load_mesh("builtin:teapot").warnings.empty());
}

TEST(LoadMesh, NonManifoldMeshLoads) {
    TempDir dir;
    // Three triangles sharing the edge 0-1, and a bow tie meeting at vertex 0.
    std::string s =
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv -1 0 0\nv -1 -1 1\n"
        "f 1 2 3\nf 2 1 4\nf 1 2 5\nf 1 6 7\n";
    Mesh m = load_mesh(dir.write("nonmanifold.obj", s));
    EXPECT_EQ(m.vertex_count(), 7u);
    EXPECT_EQ(m.triangle_count(), 4u);
}

TEST(LoadMesh, UnsharedPlyTrianglesAreWeldedAsASoup) {
    TempDir dir;
    std::string s =
        "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 2\nproperty list uchar int vertex_indices\nend_header\n"
        "0 0 0\n1 0 0\n1 1 0\n0 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 3 4 5\n";
    Mesh m = load_mesh(dir.write("soup.ply", s));
    EXPECT_EQ(m.vertex_count(), 4u);
    EXPECT_TRUE(m.welded);
}

TEST(LoadMesh, WeldEpsilonIsRelativeToTheBoundingBox) {
    TempDir dir;
    auto soup = cube_soup();
    soup[0][0][0] += 1e-3f;  // (0,0,0) of the first facet nudged by 1e-3 of a ~1.7 diagonal
    std::string p = dir.write("nudged.stl", binary_stl(soup));
    EXPECT_EQ(load_mesh(p).vertex_count(), 9u);
    LoadOptions loose;
    loose.weld_epsilon = 1e-2f;
    EXPECT_EQ(load_mesh(p, loose).vertex_count(), 8u);
}

TEST(LoadMesh, EveryFormatGivesTheSameCube) {
    TempDir dir;
    for (auto [name, bytes] : std::vector<std::pair<std::string, std::string>>{{"a.obj", cube_obj()},
                                                                               {"b.stl", cube_ascii_stl()},
                                                                               {"c.stl", cube_binary_stl()},
                                                                               {"d.ply", cube_ascii_ply()},
                                                                               {"e.ply", cube_binary_ply(false)},
                                                                               {"f.ply", cube_binary_ply(true)},
                                                                               {"g.off", cube_off()}}) {
        Mesh m = load_mesh(dir.write(name, bytes));
        EXPECT_EQ(m.vertex_count(), 8u) << name;
        EXPECT_EQ(m.triangle_count(), 12u) << name;
        EXPECT_EQ(sorted_positions(m), sorted_cube()) << name;
        EXPECT_EQ(m.normals.size(), 8u) << name;
    }
}

}  // namespace
}  // namespace inkshade::test

namespace inkshade::test {
namespace {

TEST(LoadMesh, DevicesAndFifosAreRefused) {
    TempDir dir;
    std::filesystem::create_symlink("/dev/zero", dir.file("zero.stl"));
    EXPECT_TRUE(LoadFailsWith(dir.file("zero.stl"), "not a regular file"));
    ASSERT_EQ(::mkfifo(dir.file("pipe.obj").c_str(), 0600), 0);
    EXPECT_TRUE(LoadFailsWith(dir.file("pipe.obj"), "not a regular file"));
}

TEST(LoadMesh, MaterialLibraryMustBeARegularFile) {
    TempDir dir;
    std::filesystem::create_symlink("/dev/zero", dir.file("zero.mtl"));
    EXPECT_TRUE(LoadFailsWith(dir.write("m.obj", "mtllib zero.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"),
                              "material library 'zero.mtl' is not a regular file at line 1"));
}

TEST(LoadMesh, InsaneFileNormalsAreDroppedWhenNotComputed) {
    TempDir dir;
    std::string p = dir.write("n.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 0\nf 1//1 2//1 3//1\n");
    LoadOptions keep;
    keep.compute_normals = false;
    EXPECT_TRUE(load_mesh(p, keep).normals.empty());
    Mesh m = load_mesh(p);
    ASSERT_EQ(m.normals.size(), 3u);
    EXPECT_NEAR(m.normals[0].z, 1.0f, 1e-6f);
}

}  // namespace
}  // namespace inkshade::test
