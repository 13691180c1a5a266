#include <gtest/gtest.h>

#include <random>
#include <set>

#include "io/gltf_files.hpp"
#include "io/mesh_files.hpp"
#include "io/readers.hpp"
#include "support/temp_dir.hpp"

namespace inkshade::test {
namespace {

const char* kTetrahedron =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
    "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

TEST(ObjReader, TetrahedronHasExactVerticesAndTriangles) {
    TempDir dir;
    Mesh m = load_mesh(dir.write("tet.obj", kTetrahedron));
    ASSERT_EQ(m.vertex_count(), 4u);
    ASSERT_EQ(m.triangle_count(), 4u);
    EXPECT_EQ(m.positions[3], glm::vec3(0, 0, 1));
    EXPECT_EQ(m.triangles[0], glm::uvec3(0, 2, 1));
    EXPECT_EQ(m.triangles[3], glm::uvec3(1, 2, 3));
    EXPECT_FALSE(m.welded);
    EXPECT_EQ(m.normals.size(), 4u);
    EXPECT_TRUE(m.materials.empty());
    EXPECT_TRUE(m.face_materials.empty());
}

TEST(ObjReader, QuadsAreTriangulated) {
    TempDir dir;
    Mesh m = load_mesh(dir.write("cube.obj", cube_obj()));
    EXPECT_EQ(m.vertex_count(), 8u);
    EXPECT_EQ(m.triangle_count(), 12u);
    EXPECT_EQ(sorted_positions(m), sorted_cube());
    // Every quad's corners appear in its two triangles.
    for (size_t q = 0; q < 6; ++q) {
        std::set<uint32_t> corners;
        for (size_t t = 2 * q; t < 2 * q + 2; ++t)
            for (int k = 0; k < 3; ++k) corners.insert(m.triangles[t][k]);
        EXPECT_EQ(corners, std::set<uint32_t>(kCubeQuads[q].begin(), kCubeQuads[q].end()));
    }
}

TEST(ObjReader, NegativeIndicesCountBackFromTheLastVertex) {
    TempDir dir;
    Mesh m = load_mesh(dir.write("neg.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nv 0 0 1\nf -4 -3 -1\n"));
    ASSERT_EQ(m.triangle_count(), 2u);
    EXPECT_EQ(m.triangles[0], glm::uvec3(0, 1, 2));
    EXPECT_EQ(m.triangles[1], glm::uvec3(0, 1, 3));
}

TEST(ObjReader, MtlDiffuseColoursArePerFace) {
    TempDir dir;
    dir.write("colours.mtl", "newmtl red\nKd 1 0 0\n\nnewmtl blue\nKd 0 0 1\n");
    std::string obj =
        "mtllib colours.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
        "f 1 2 3\nusemtl red\nf 1 3 4\nusemtl blue\nf 1 2 3 4\n";
    LoadOptions keep;  // the quad repeats the first two triangles: keep them to see every face's material
    keep.drop_duplicate_faces = false;
    Mesh m = load_mesh(dir.write("coloured.obj", obj), keep);
    ASSERT_EQ(m.triangle_count(), 4u);
    ASSERT_EQ(m.face_materials.size(), 4u);
    auto colour = [&](size_t t) { return m.materials[m.face_materials[t]].diffuse; };
    EXPECT_EQ(m.materials[m.face_materials[0]].name, "default");
    EXPECT_EQ(colour(1), glm::vec3(1, 0, 0));
    EXPECT_EQ(colour(2), glm::vec3(0, 0, 1));
    EXPECT_EQ(colour(3), glm::vec3(0, 0, 1));
    EXPECT_EQ(m.materials[m.face_materials[1]].name, "red");
}

const char* kTexturedQuadObj =
    "mtllib mat/skin.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
    "usemtl skin\nf 1/1 2/2 3/3 4/4\n";

TEST(ObjReader, MapKdTextureIsLoadedRelativeToTheMtlFile) {
    TempDir dir;
    std::filesystem::create_directories(dir.path() / "mat");
    dir.write("mat/skin.png", png_bytes(2, 2, kTexturePixels));
    dir.write("mat/skin.mtl", "newmtl skin\nKd 1 0.5 0.25\nmap_Kd skin.png\n");
    Mesh m = load_mesh(dir.write("quad.obj", kTexturedQuadObj));
    ASSERT_EQ(m.materials.size(), 1u);
    EXPECT_EQ(m.materials[0].diffuse, glm::vec3(1, 0.5f, 0.25f));
    ASSERT_TRUE(m.materials[0].texture);
    EXPECT_EQ(m.materials[0].texture->width, 2);
    EXPECT_EQ(m.materials[0].texture->rgba, kTexturePixels);
    EXPECT_EQ(m.materials[0].texture->source, dir.file("mat/skin.png"));
    ASSERT_EQ(m.uvs.size(), 4u);
    EXPECT_TRUE(m.warnings.empty());
}

TEST(ObjReader, MapKdWithoutKdIsNotBlack) {
    TempDir dir;
    std::filesystem::create_directories(dir.path() / "mat" / "tex");
    dir.write("mat/tex/skin.png", png_bytes(2, 2, kTexturePixels));
    dir.write("mat/skin.mtl", "newmtl skin\nmap_Kd tex\\skin.png\n");  // Windows separator
    Mesh m = load_mesh(dir.write("quad.obj", kTexturedQuadObj));
    ASSERT_TRUE(m.materials[0].texture);
    EXPECT_EQ(m.materials[0].diffuse, glm::vec3(1));
}

TEST(ObjReader, MissingOrBadMapKdIsAWarningNotAFailure) {
    TempDir dir;
    std::filesystem::create_directories(dir.path() / "mat");
    dir.write("mat/skin.mtl", "newmtl skin\nKd 1 0 0\nmap_Kd missing.png\n");
    std::string obj = dir.write("quad.obj", kTexturedQuadObj);
    Mesh m = load_mesh(obj);
    EXPECT_EQ(m.triangle_count(), 2u);
    EXPECT_FALSE(m.materials[0].texture);
    EXPECT_EQ(m.materials[0].diffuse, glm::vec3(1, 0, 0));
    ASSERT_EQ(m.warnings.size(), 1u);
    EXPECT_EQ(m.warnings[0], obj + ": texture 'missing.png' not loaded (file not found); using the base colour");

    dir.write("mat/missing.png", "\x89PNG\r\n\x1a\n garbage");
    Mesh bad = load_mesh(obj);
    ASSERT_EQ(bad.warnings.size(), 1u);
    EXPECT_NE(bad.warnings[0].find("texture 'missing.png' not loaded (not a decodable image"), std::string::npos)
        << bad.warnings[0];
}

TEST(ObjReader, MissingMtlFileFallsBackToNoMaterials) {
    TempDir dir;
    Mesh m = load_mesh(dir.write("nomtl.obj", std::string("mtllib missing.mtl\nusemtl red\n") + kTetrahedron));
    EXPECT_EQ(m.triangle_count(), 4u);
    EXPECT_TRUE(m.face_materials.empty());
}

TEST(ObjReader, FileNormalsAreKeptAndSplitVerticesOnlyWhereTheyDiffer) {
    TempDir dir;
    std::string s =
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvn 0 0 -1\nvn 0 -1 0\n"
        "f 1//1 3//1 2//1\nf 1//2 2//2 4//2\n";
    Mesh m = load_mesh(dir.write("n.obj", s));
    ASSERT_EQ(m.triangle_count(), 2u);
    EXPECT_EQ(m.vertex_count(), 6u);  // vertices 1 and 2 differ in normal between the faces
    EXPECT_FALSE(m.welded);
    ASSERT_EQ(m.normals.size(), 6u);
    EXPECT_EQ(m.normals[m.triangles[0][0]], glm::vec3(0, 0, -1));
    EXPECT_EQ(m.normals[m.triangles[1][2]], glm::vec3(0, -1, 0));
    EXPECT_NE(m.triangles[0][0], m.triangles[1][0]);
}

TEST(ObjReader, SharedCornersStayShared) {
    TempDir dir;
    std::string s =
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\n"
        "f 1/1/1 2/2/1 3/3/1\nf 1/1/1 3/3/1 4/4/1\n";
    Mesh m = load_mesh(dir.write("quad.obj", s));
    EXPECT_EQ(m.vertex_count(), 4u);
    ASSERT_EQ(m.uvs.size(), 4u);
    EXPECT_EQ(m.uvs[m.triangles[1][2]], glm::vec2(0, 1));
    EXPECT_EQ(m.normals[0], glm::vec3(0, 0, 1));
}

TEST(ObjReader, VertexColoursAreKept) {
    TempDir dir;
    Mesh m = load_mesh(dir.write("c.obj", "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nf 1 2 3\n"));
    ASSERT_EQ(m.colors.size(), 3u);
    EXPECT_EQ(m.colors[1], glm::vec3(0, 1, 0));
}

TEST(ObjReader, SoupWithRepeatedPositionsIsWelded) {
    TempDir dir;
    std::string s;
    for (auto t : cube_triangles()) {
        for (uint32_t i : t)
            s += "v " + std::to_string(int(kCubeVertices[i][0])) + " " + std::to_string(int(kCubeVertices[i][1])) +
                 " " + std::to_string(int(kCubeVertices[i][2])) + "\n";
        s += "f -3 -2 -1\n";
    }
    Mesh m = load_mesh(dir.write("soup.obj", s));
    EXPECT_EQ(m.vertex_count(), 8u);
    EXPECT_EQ(m.triangle_count(), 12u);
    EXPECT_TRUE(m.welded);
}

TEST(ObjReader, SoupWithNearlyEqualPositionsIsWeldedWithinEpsilon) {
    TempDir dir;
    // Two triangles written separately; the shared edge's copies differ in the last digits.
    std::string s = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0.0000001 0 0\nv 1 1.0000001 0\nv 0 1 0\nf 1 2 3\nf 4 5 6\n";
    Mesh m = load_mesh(dir.write("near.obj", s));
    EXPECT_EQ(m.vertex_count(), 4u);
    EXPECT_TRUE(m.welded);
}

TEST(ObjReader, LargePolygonsAreTriangulated) {
    TempDir dir;
    for (int n : {20, 300}) {  // 300 > 255: tinyobj's per-face counts are 8-bit
        std::string s, f = "f";
        for (int i = 0; i < n; ++i) {
            double a = 6.283185307179586 * i / n;
            s += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
            f += " " + std::to_string(i + 1);
        }
        // The triangle after it is not one of the fan's (those would be dropped as duplicates).
        Mesh m = load_mesh(dir.write("poly.obj", s + f + "\nf 2 3 4\n"));
        EXPECT_EQ(m.triangle_count(), size_t(n - 2 + 1)) << n;
        EXPECT_EQ(m.triangles.back(), glm::uvec3(1, 2, 3)) << n;
        EXPECT_TRUE(m.warnings.empty()) << n;
    }
}

TEST(ObjReader, TagLinesAreIgnored) {
    TempDir dir;
    std::string s = kTetrahedron;
    for (int i = 0; i < 1000; ++i) s += "t crease 8192/8192/8192\n";
    Mesh m = load_mesh(dir.write("tags.obj", s));
    EXPECT_EQ(m.triangle_count(), 4u);
}

TEST(ObjReader, EmptyFileIsAnError) {
    TempDir dir;
    EXPECT_TRUE(LoadFailsWith(dir.write("empty.obj", ""), "empty file"));
    EXPECT_TRUE(LoadFailsWith(dir.write("comments.obj", "# nothing here\n\n"), "no triangles"));
}

TEST(ObjReader, TruncatedFileIsAnError) {
    TempDir dir;
    std::string s = kTetrahedron;
    EXPECT_TRUE(LoadFailsWith(dir.write("cut.obj", s.substr(0, 13)), "line ends before a vertex coordinate at line 2"));
    EXPECT_TRUE(LoadFailsWith(dir.write("cut2.obj", s.substr(0, 32)), "no triangles"));
}

TEST(ObjReader, BinaryGarbageIsNotAText) {
    TempDir dir;
    std::string garbage;
    std::mt19937 rng(7);
    for (int i = 0; i < 4096; ++i) garbage += char(rng());
    EXPECT_TRUE(LoadFailsWith(dir.write("garbage.obj", garbage), "not a text OBJ file"));
    EXPECT_TRUE(LoadFailsWith(dir.write("png.obj", std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16)),
                              "not a text OBJ file (binary byte at offset 6)"));
}

TEST(ObjReader, NonNumericTokensAreErrors) {
    TempDir dir;
    EXPECT_TRUE(
        LoadFailsWith(dir.write("a.obj", "v 0 zero 0\n"), "expected a vertex coordinate but found 'zero' at line 1"));
    EXPECT_TRUE(LoadFailsWith(dir.write("b.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 three\n"),
                              "bad face index 'three' (indices are non-zero integers) at line 4"));
    EXPECT_TRUE(LoadFailsWith(dir.write("c.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/a 2 3\n"), "bad face index '1/a'"));
    EXPECT_TRUE(LoadFailsWith(dir.write("d.obj", "v 0 0 0 0 0 0 junk\n"),
                              "expected a vertex weight or colour but found 'junk'"));
}

TEST(ObjReader, NanAndInfCoordinatesAreErrors) {
    TempDir dir;
    EXPECT_TRUE(LoadFailsWith(dir.write("nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n"),
                              "vertex 1 has a non-finite coordinate at line 2"));
    EXPECT_TRUE(LoadFailsWith(dir.write("inf.obj", "v 0 0 0\nv 0 1 0\nv 0 0 -inf\nf 1 2 3\n"),
                              "vertex 2 has a non-finite coordinate at line 3"));
    EXPECT_TRUE(LoadFailsWith(dir.write("big.obj", "v 0 0 0\nv 0 1 0\nv 0 0 1e39\nf 1 2 3\n"),
                              "vertex 2 has a non-finite coordinate"));
}

TEST(ObjReader, OutOfRangeIndicesAreErrors) {
    TempDir dir;
    EXPECT_TRUE(LoadFailsWith(dir.write("big.obj", cube_obj() + "f 1 2 9\n"),
                              "face refers to vertex 9 but the file has only 8 at line 17"));
    EXPECT_TRUE(LoadFailsWith(dir.write("neg.obj", cube_obj() + "f 1 2 -9\n"),
                              "face refers to vertex -9 but only 8 are defined before it at line 17"));
    EXPECT_TRUE(LoadFailsWith(dir.write("zero.obj", cube_obj() + "f 0 1 2\n"), "bad face index '0'"));
    EXPECT_TRUE(LoadFailsWith(dir.write("min.obj", cube_obj() + "f 1 2 -9223372036854775808\n"),
                              "face refers to vertex -9223372036854775808"));
    EXPECT_TRUE(LoadFailsWith(dir.write("max.obj", cube_obj() + "f 1 2 99999999999999999999\n"), "bad face index"));
    EXPECT_TRUE(LoadFailsWith(dir.write("quad.obj", cube_obj() + "f 1 2 3 99\n"), "face refers to vertex 99"));
    EXPECT_TRUE(LoadFailsWith(dir.write("vn.obj", std::string(kTetrahedron) + "vn 0 0 1\nf 1//2 2//1 3//1\n"),
                              "face refers to normal 2 but the file has only 1"));
    EXPECT_TRUE(LoadFailsWith(dir.write("vt.obj", std::string(kTetrahedron) + "f 1/-1 2/1 3/1\n"),
                              "face refers to texture coordinate -1 but only 0 are defined"));
}

TEST(ObjReader, RandomBytesNeverCrash) {
    TempDir dir;
    std::mt19937 rng(42);
    const std::string alphabet = "vfnt/ -0123456789.e#\n\r\tusemtlibxyz";
    for (int i = 0; i < 300; ++i) {
        std::string s;
        size_t n = rng() % 2000;
        bool text = i % 2 == 0;  // half printable OBJ-ish text, half raw bytes
        for (size_t k = 0; k < n; ++k) s += text ? alphabet[rng() % alphabet.size()] : char(rng());
        std::string p = dir.write("fuzz.obj", s);
        try {
            load_mesh(p);
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
        }
    }
}

}  // namespace
}  // namespace inkshade::test
