#include <gtest/gtest.h>

#include "io/mesh_files.hpp"
#include "io/readers.hpp"
#include "support/temp_dir.hpp"

namespace inkshade::test {
namespace {

TEST(OffReader, CubeHasExactVerticesAndFanTriangles) {
    TempDir dir;
    Mesh m = io::read_off(dir.write("cube.off", cube_off()));
    ASSERT_EQ(m.vertex_count(), 8u);
    ASSERT_EQ(m.triangle_count(), 12u);
    for (size_t i = 0; i < 8; ++i)
        EXPECT_EQ(m.positions[i], glm::vec3(kCubeVertices[i][0], kCubeVertices[i][1], kCubeVertices[i][2]));
    auto tris = cube_triangles();
    for (size_t t = 0; t < 12; ++t) EXPECT_EQ(m.triangles[t], glm::uvec3(tris[t][0], tris[t][1], tris[t][2]));
    EXPECT_TRUE(m.colors.empty());
}

TEST(OffReader, CountsOnKeywordLineCommentsAndFaceColoursAreAccepted) {
    TempDir dir;
    std::string s =
        "OFF 4 2 0 # counts here\n# a comment line\n\n0 0 0\n1 0 0 # trailing comment\n1 1 0\n0 1 0\n"
        "3 0 1 2 255 0 0\n3 0 2 3 0.5 0.5 0.5 1\n";
    Mesh m = load_mesh(dir.write("quad.off", s));
    EXPECT_EQ(m.vertex_count(), 4u);
    EXPECT_EQ(m.triangle_count(), 2u);
}

TEST(OffReader, HeaderKeywordIsOptional) {
    TempDir dir;
    Mesh m = io::read_off(dir.write("bare.off", "3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"));
    EXPECT_EQ(m.triangle_count(), 1u);
}

TEST(OffReader, CoffColoursAreReadAsBytesOrFloats) {
    TempDir dir;
    std::string s = "COFF\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 51 0 255\n0 1 0 0.25 0.5 1.0 1.0\n3 0 1 2\n";
    Mesh m = io::read_off(dir.write("c.off", s));
    ASSERT_EQ(m.colors.size(), 3u);
    EXPECT_EQ(m.colors[0], glm::vec3(1, 0, 0));
    EXPECT_NEAR(m.colors[1].y, 0.2f, 1e-6f);
    EXPECT_EQ(m.colors[2], glm::vec3(0.25f, 0.5f, 1.0f));
}

TEST(OffReader, NoffNormalsAndStoffUvsAreKept) {
    TempDir dir;
    Mesh n = io::read_off(dir.write("n.off", "NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n"));
    ASSERT_EQ(n.normals.size(), 3u);
    EXPECT_EQ(n.normals[2], glm::vec3(0, 0, 1));
    Mesh st = io::read_off(
        dir.write("st.off", "STCOFF\n3 1 0\n0 0 0 1 0 0 1 0.5 0.25\n1 0 0 0 1 0 1 1 0\n0 1 0 0 0 1 1 0 1\n3 0 1 2\n"));
    ASSERT_EQ(st.uvs.size(), 3u);
    EXPECT_EQ(st.uvs[0], glm::vec2(0.5f, 0.25f));
    EXPECT_EQ(st.colors[1], glm::vec3(0, 1, 0));
}

TEST(OffReader, EmptyFileIsAnError) {
    TempDir dir;
    EXPECT_TRUE(LoadFailsWith(dir.write("empty.off", ""), "empty file"));
    EXPECT_TRUE(
        LoadFailsWith(dir.write("comments.off", "# nothing\n"), "unexpected end of file before the vertex count"));
}

TEST(OffReader, TruncatedFileReportsLine) {
    TempDir dir;
    std::string s = cube_off();
    EXPECT_TRUE(LoadFailsWith(dir.write("cut.off", s.substr(0, s.size() - 4)),
                              "unexpected end of file while reading a vertex index at line 17"));
    EXPECT_TRUE(LoadFailsWith(dir.write("cut2.off", s.substr(0, s.find("1 1 1"))),
                              "header claims 8 vertices but file has only 37 bytes"));
    EXPECT_TRUE(LoadFailsWith(dir.write("cut3.off", s.substr(0, s.find("4 0 3 2 1"))),
                              "unexpected end of file while reading a face vertex count at line 12"));
}

TEST(OffReader, NonNumericNanAndInfAreErrors) {
    TempDir dir;
    std::string s = cube_off();
    std::string word = s, nan = s, inf = s;
    word.replace(s.find("1 1 1"), 5, "1 x 1");
    nan.replace(s.find("1 1 1"), 5, "1 NaN 1");
    inf.replace(s.find("1 1 1"), 5, "inf 1 1");
    EXPECT_TRUE(LoadFailsWith(dir.write("word.off", word), "expected a vertex coordinate but found 'x' at line 10"));
    EXPECT_TRUE(LoadFailsWith(dir.write("nan.off", nan), "vertex 6 has a non-finite coordinate at line 10"));
    EXPECT_TRUE(LoadFailsWith(dir.write("inf.off", inf), "vertex 6 has a non-finite coordinate"));
}

TEST(OffReader, OutOfRangeAndNegativeIndicesAreErrors) {
    TempDir dir;
    std::string s = cube_off();
    std::string big = s, neg = s;
    big.replace(s.rfind("4 1 2 6 5"), 9, "4 1 2 6 12");
    neg.replace(s.rfind("4 1 2 6 5"), 9, "4 1 2 -3 5");
    EXPECT_TRUE(LoadFailsWith(dir.write("big.off", big),
                              "face 5 refers to vertex 12 but there are only 8 vertices at line 17"));
    EXPECT_TRUE(LoadFailsWith(dir.write("neg.off", neg), "face 5 refers to vertex -3"));
}

TEST(OffReader, HeaderClaimingTwoToThe31ElementsFailsWithoutAllocating) {
    TempDir dir;
    std::string s = cube_off();
    std::string v = s, f = s;
    v.replace(s.find("8 6 12"), 6, "2147483648 6 12");
    f.replace(s.find("8 6 12"), 6, "8 2147483648 12");
    EXPECT_TRUE(LoadFailsWith(dir.write("v.off", v), "header claims 2147483648 vertices but file has only"));
    EXPECT_TRUE(LoadFailsWith(dir.write("f.off", f), "header claims 2147483648 faces but file has only"));
    std::string poly = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2147483648 0 1 2\n";
    EXPECT_TRUE(LoadFailsWith(dir.write("p.off", poly), "face 0 claims 2147483648 vertices"));
}

TEST(OffReader, UnsupportedVariantsAreErrors) {
    TempDir dir;
    EXPECT_TRUE(LoadFailsWith(dir.write("b.off", "OFF BINARY\n"), "binary OFF is not supported"));
    EXPECT_TRUE(LoadFailsWith(dir.write("4.off", "4OFF\n1 0 0\n"), "unsupported OFF variant '4OFF'"));
    EXPECT_TRUE(LoadFailsWith(dir.write("x.off", "PLY\n"), "not an OFF file"));
}

}  // namespace
}  // namespace inkshade::test
