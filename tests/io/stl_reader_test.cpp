#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "io/mesh_files.hpp"
#include "io/readers.hpp"
#include "support/temp_dir.hpp"

namespace inkshade::test {
namespace {

TEST(StlReader, AsciiCubeWeldsToEightVertices) {
    TempDir dir;
    Mesh m = load_mesh(dir.write("cube.stl", cube_ascii_stl()));
    EXPECT_EQ(m.vertex_count(), 8u);
    EXPECT_EQ(m.triangle_count(), 12u);
    EXPECT_TRUE(m.welded);
    EXPECT_EQ(sorted_positions(m), sorted_cube());
    EXPECT_EQ(m.normals.size(), 8u);
}

TEST(StlReader, BinaryCubeWeldsToEightVertices) {
    TempDir dir;
    Mesh m = load_mesh(dir.write("cube.stl", cube_binary_stl()));
    EXPECT_EQ(m.vertex_count(), 8u);
    EXPECT_EQ(m.triangle_count(), 12u);
    EXPECT_EQ(sorted_positions(m), sorted_cube());
}

TEST(StlReader, BinaryWhoseHeaderStartsWithSolidIsReadAsBinary) {
    TempDir dir;
    Mesh m = load_mesh(dir.write("cube.stl", cube_binary_stl("solid exported by a CAD tool")));
    EXPECT_EQ(m.vertex_count(), 8u);
    EXPECT_EQ(m.triangle_count(), 12u);
}

TEST(StlReader, BinaryWithTrailingBytesIsRead) {
    TempDir dir;
    Mesh m = load_mesh(dir.write("cube.stl", cube_binary_stl("solid x") + std::string(7, '\0')));
    EXPECT_EQ(m.triangle_count(), 12u);
}

TEST(StlReader, ReaderReturnsSoupWithThreeVerticesPerFacet) {
    TempDir dir;
    Mesh m = io::read_stl(dir.write("cube.stl", cube_binary_stl()));
    ASSERT_EQ(m.vertex_count(), 36u);
    ASSERT_EQ(m.triangle_count(), 12u);
    for (uint32_t t = 0; t < 12; ++t) EXPECT_EQ(m.triangles[t], glm::uvec3(3 * t, 3 * t + 1, 3 * t + 2));
    auto tri = cube_triangles()[5];
    EXPECT_EQ(m.positions[15], glm::vec3(kCubeVertices[tri[0]][0], kCubeVertices[tri[0]][1], kCubeVertices[tri[0]][2]));
    EXPECT_TRUE(io::format_is_soup(".stl"));
    EXPECT_TRUE(io::format_is_soup("STL"));
    EXPECT_FALSE(io::format_is_soup(".ply"));
}

TEST(StlReader, AsciiAndBinaryGiveTheSameSoup) {
    TempDir dir;
    Mesh a = io::read_stl(dir.write("a.stl", cube_ascii_stl()));
    Mesh b = io::read_stl(dir.write("b.stl", cube_binary_stl()));
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.triangles, b.triangles);
}

TEST(StlReader, AsciiKeywordsAreCaseInsensitiveAndSolidsMayRepeat) {
    TempDir dir;
    std::string one =
        "SOLID a\nFACET NORMAL 0 0 1\nOUTER LOOP\nVERTEX 0 0 0\nVERTEX 1 0 0\nVERTEX 0 1 "
        "0\nENDLOOP\nENDFACET\nENDSOLID a\n";
    Mesh m = io::read_stl(dir.write("two.stl", one + one));
    EXPECT_EQ(m.triangle_count(), 2u);
}

TEST(StlReader, AsciiPolygonFacetIsFanTriangulated) {
    TempDir dir;
    Mesh m = io::read_stl(dir.write("quad.stl",
                                    "solid q\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 "
                                    "0\nvertex 0 1 0\nendloop\nendfacet\nendsolid q\n"));
    EXPECT_EQ(m.triangle_count(), 2u);
    EXPECT_EQ(m.triangles[1], glm::uvec3(0, 2, 3));
}

TEST(StlReader, EmptyFileIsAnError) {
    TempDir dir;
    EXPECT_TRUE(LoadFailsWith(dir.write("empty.stl", ""), "empty file"));
}

TEST(StlReader, TruncatedBinaryIsAnError) {
    TempDir dir;
    std::string bytes = cube_binary_stl();
    EXPECT_TRUE(LoadFailsWith(dir.write("cut.stl", bytes.substr(0, bytes.size() - 20)),
                              "header claims 12 triangles but file has room for 11"));
    EXPECT_TRUE(LoadFailsWith(dir.write("short.stl", bytes.substr(0, 50)), "truncated binary STL"));
}

TEST(StlReader, HeaderClaimingTwoToThe31TrianglesFailsWithoutAllocating) {
    TempDir dir;
    std::string p = dir.write("huge.stl", binary_stl(cube_soup(), "huge", int64_t(1) << 31));
    EXPECT_TRUE(LoadFailsWith(p, "header claims 2147483648 triangles but file has room for 12"));
}

TEST(StlReader, TruncatedAsciiReportsLine) {
    TempDir dir;
    std::string text = cube_ascii_stl();
    std::string cut = text.substr(0, text.find("endloop", text.size() / 2));
    EXPECT_TRUE(
        LoadFailsWith(dir.write("cut.stl", cut), "unexpected end of file (truncated STL?) inside a facet at line"));
    std::string no_end = text.substr(0, text.find("endsolid"));
    EXPECT_TRUE(LoadFailsWith(dir.write("noend.stl", no_end), "missing 'endsolid' at line"));
}

TEST(StlReader, NonNumericCoordinateIsAnError) {
    TempDir dir;
    std::string text = cube_ascii_stl();
    text.replace(text.find("vertex 1"), 8, "vertex abc");
    EXPECT_TRUE(LoadFailsWith(dir.write("bad.stl", text), "expected a vertex coordinate but found 'abc' at line"));
}

TEST(StlReader, MissingCoordinateIsAnError) {
    TempDir dir;
    EXPECT_TRUE(
        LoadFailsWith(dir.write("bad.stl", "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0\nvertex 1 0 0\n"),
                      "line ends before a vertex coordinate at line 4"));
}

TEST(StlReader, NanAndInfCoordinatesAreErrors) {
    TempDir dir;
    std::string text = cube_ascii_stl();
    std::string nan_text = text, inf_text = text;
    nan_text.replace(nan_text.find("vertex 1"), 8, "vertex nan");
    inf_text.replace(inf_text.find("vertex 1"), 8, "vertex 1e999");
    EXPECT_TRUE(LoadFailsWith(dir.write("nan.stl", nan_text), "non-finite coordinate"));
    EXPECT_TRUE(LoadFailsWith(dir.write("inf.stl", inf_text), "non-finite coordinate"));
    auto soup = cube_soup();
    soup[1][1][2] = std::numeric_limits<float>::infinity();
    EXPECT_TRUE(LoadFailsWith(dir.write("inf_bin.stl", binary_stl(soup)), "vertex 4 has a non-finite coordinate"));
    soup[1][1][2] = std::nanf("");
    EXPECT_TRUE(LoadFailsWith(dir.write("nan_bin.stl", binary_stl(soup)), "vertex 4 has a non-finite coordinate"));
}

TEST(StlReader, ZeroTrianglesIsAnError) {
    TempDir dir;
    EXPECT_TRUE(LoadFailsWith(dir.write("none.stl", binary_stl({})), "no triangles"));
    EXPECT_TRUE(LoadFailsWith(dir.write("none_ascii.stl", "solid e\nendsolid e\n"), "no triangles"));
}

TEST(StlReader, GarbageAfterSolidIsAnError) {
    TempDir dir;
    EXPECT_TRUE(LoadFailsWith(dir.write("junk.stl", "solid x\nhello world\n"),
                              "expected 'facet' or 'endsolid' but found 'hello'"));
}

}  // namespace
}  // namespace inkshade::test
