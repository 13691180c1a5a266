#include <gtest/gtest.h>

#include <cmath>

#include "io/gltf_files.hpp"
#include "io/mesh_files.hpp"
#include "io/readers.hpp"
#include "support/temp_dir.hpp"

namespace inkshade::test {
namespace {

void expect_cube(const Mesh& m) {
    ASSERT_EQ(m.vertex_count(), 8u);
    ASSERT_EQ(m.triangle_count(), 12u);
    for (size_t i = 0; i < 8; ++i)
        EXPECT_EQ(m.positions[i], glm::vec3(kCubeVertices[i][0], kCubeVertices[i][1], kCubeVertices[i][2]));
    auto tris = cube_triangles();
    for (size_t t = 0; t < 12; ++t) EXPECT_EQ(m.triangles[t], glm::uvec3(tris[t][0], tris[t][1], tris[t][2]));
}

TEST(PlyReader, AsciiCubeHasExactVerticesAndFanTriangles) {
    TempDir dir;
    expect_cube(io::read_ply(dir.write("cube.ply", cube_ascii_ply())));
}

TEST(PlyReader, BinaryLittleEndianCube) {
    TempDir dir;
    expect_cube(io::read_ply(dir.write("cube.ply", cube_binary_ply(false))));
}

TEST(PlyReader, BinaryBigEndianCube) {
    TempDir dir;
    expect_cube(io::read_ply(dir.write("cube.ply", cube_binary_ply(true))));
}

TEST(PlyReader, LoadMeshKeepsIndexingAndAddsNormals) {
    TempDir dir;
    Mesh m = load_mesh(dir.write("cube.ply", cube_binary_ply(false)));
    EXPECT_EQ(m.vertex_count(), 8u);
    EXPECT_EQ(m.triangle_count(), 12u);
    EXPECT_FALSE(m.welded);
    ASSERT_EQ(m.normals.size(), 8u);
    for (auto n : m.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
}

TEST(PlyReader, ColoursNormalsAndUvsAreKept) {
    TempDir dir;
    std::string text =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        "property float nx\nproperty float ny\nproperty float nz\nproperty uchar red\nproperty uchar green\n"
        "property uchar blue\nproperty uchar alpha\nproperty float s\nproperty float t\n"
        "element face 1\nproperty list uchar uint vertex_index\nend_header\n"
        "0 0 0 0 0 1 255 0 0 255 0 0\n1 0 0 0 0 1 0 255 0 255 1 0\n0 1 0 0 0 1 0 0 51 255 0 1\n3 0 1 2\n";
    Mesh m = load_mesh(dir.write("tri.ply", text));
    ASSERT_EQ(m.colors.size(), 3u);
    EXPECT_EQ(m.colors[0], glm::vec3(1, 0, 0));
    EXPECT_EQ(m.colors[1], glm::vec3(0, 1, 0));
    EXPECT_NEAR(m.colors[2].z, 0.2f, 1e-6f);
    ASSERT_EQ(m.normals.size(), 3u);
    EXPECT_EQ(m.normals[1], glm::vec3(0, 0, 1));
    ASSERT_EQ(m.uvs.size(), 3u);
    EXPECT_EQ(m.uvs[2], glm::vec2(0, 1));
}

std::string textured_ply(const std::string& texture_comment, const std::string& u = "texture_u",
                         const std::string& v = "texture_v") {
    return "ply\nformat ascii 1.0\n" + texture_comment +
           "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
           "property float " +
           u + "\nproperty float " + v +
           "\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n"
           "0 0 0 0 0\n1 0 0 1 0\n1 1 0 1 1\n0 1 0 0 1\n3 0 1 2\n3 0 2 3\n";
}

TEST(PlyReader, TextureUvPropertyNamesAreRead) {
    TempDir dir;
    for (auto [u, v] : {std::pair{"u", "v"}, {"s", "t"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}}) {
        Mesh m = load_mesh(dir.write("uv.ply", textured_ply("", u, v)));
        ASSERT_EQ(m.uvs.size(), 4u) << u;
        EXPECT_EQ(m.uvs[2], glm::vec2(1, 1)) << u;
        EXPECT_EQ(m.uvs[1], glm::vec2(1, 0)) << u;
    }
}

TEST(PlyReader, TextureFileCommentLoadsTheTexture) {
    TempDir dir;
    dir.write("scan texture.png", png_bytes(2, 2, kTexturePixels));
    Mesh m = load_mesh(dir.write("scan.ply", textured_ply("comment TextureFile scan texture.png\n")));
    ASSERT_EQ(m.materials.size(), 1u);
    ASSERT_TRUE(m.materials[0].texture);
    EXPECT_EQ(m.materials[0].texture->rgba, kTexturePixels);
    EXPECT_EQ(m.materials[0].diffuse, glm::vec3(1));
    EXPECT_EQ(m.face_materials, (std::vector<uint32_t>{0, 0}));
    EXPECT_TRUE(m.warnings.empty());
}

TEST(PlyReader, MissingTextureFileIsAWarningNotAFailure) {
    TempDir dir;
    std::string p = dir.write("scan.ply", textured_ply("comment TextureFile gone.png\n"));
    Mesh m = load_mesh(p);
    EXPECT_EQ(m.triangle_count(), 2u);
    EXPECT_TRUE(m.materials.empty());
    ASSERT_EQ(m.warnings.size(), 1u);
    EXPECT_EQ(m.warnings[0], p + ": texture 'gone.png' not loaded (file not found); using the base colour");
}

TEST(PlyReader, SoupWeldingKeepsUvSeamsAndMergesTheRest) {
    TempDir dir;
    // Two triangles written as a soup sharing the edge (0,0,0)-(1,1,0); the uvs agree at
    // (0,0,0) but differ at (1,1,0) (a texture seam).
    std::string s =
        "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\nproperty float z\n"
        "property float u\nproperty float v\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n"
        "0 0 0 0 0\n1 0 0 1 0\n1 1 0 1 1\n0 0 0 0 0\n1 1 0 0.5 0.5\n0 1 0 0 1\n3 0 1 2\n3 3 4 5\n";
    Mesh m = load_mesh(dir.write("seam.ply", s));
    EXPECT_TRUE(m.welded);
    ASSERT_EQ(m.vertex_count(), 5u);  // (0,0,0) merged; (1,1,0) kept twice
    ASSERT_EQ(m.uvs.size(), 5u);
    EXPECT_EQ(m.triangles[0].x, m.triangles[1].x);
    EXPECT_NE(m.triangles[0].z, m.triangles[1].y);
    EXPECT_EQ(m.uvs[m.triangles[0].z], glm::vec2(1, 1));
    EXPECT_EQ(m.uvs[m.triangles[1].y], glm::vec2(0.5f, 0.5f));
    EXPECT_EQ(m.positions[m.triangles[1].y], glm::vec3(1, 1, 0));
}

TEST(PlyReader, SoupWeldingKeepsColourBoundaries) {
    TempDir dir;
    std::string s =
        "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\nproperty float z\n"
        "property uchar red\nproperty uchar green\nproperty uchar blue\nelement face 2\n"
        "property list uchar int vertex_indices\nend_header\n"
        "0 0 0 255 0 0\n1 0 0 255 0 0\n1 1 0 255 0 0\n0 0 0 0 0 255\n1 1 0 0 0 255\n0 1 0 0 0 255\n3 0 1 2\n3 3 4 5\n";
    Mesh m = load_mesh(dir.write("colours.ply", s));
    EXPECT_EQ(m.vertex_count(), 6u);  // every shared position changes colour: nothing merges
    for (size_t k = 0; k < 3; ++k) EXPECT_EQ(m.colors[m.triangles[1][k]], glm::vec3(0, 0, 1));
}

TEST(PlyReader, FloatColoursAreKeptAsIs) {
    TempDir dir;
    std::string s =
        "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty double x\nproperty double y\n"
        "property double z\nproperty float red\nproperty float green\nproperty float blue\n"
        "element face 1\nproperty list int short vertex_indices\nend_header\n";
    float rgb[3][3] = {{0.25f, 0.5f, 0.75f}, {1, 1, 1}, {0, 0, 0}};
    double xyz[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    for (int i = 0; i < 3; ++i) {
        for (double x : xyz[i]) put<double>(s, x, true);
        for (float c : rgb[i]) put<float>(s, c, true);
    }
    put<int32_t>(s, 3, true);
    for (int16_t i : {0, 1, 2}) put<int16_t>(s, i, true);
    Mesh m = io::read_ply(dir.write("tri.ply", s));
    ASSERT_EQ(m.colors.size(), 3u);
    EXPECT_EQ(m.colors[0], glm::vec3(0.25f, 0.5f, 0.75f));
    EXPECT_EQ(m.positions[2], glm::vec3(0, 1, 0));
    EXPECT_EQ(m.triangles[0], glm::uvec3(0, 1, 2));
}

TEST(PlyReader, UnknownElementsAndPropertiesAreSkipped) {
    TempDir dir;
    for (bool binary : {false, true}) {
        std::string s = std::string("ply\nformat ") + (binary ? "binary_little_endian" : "ascii") +
                        " 1.0\ncomment extra stuff everywhere\nobj_info scanner 3\n"
                        "element camera 1\nproperty float view_px\nproperty list uchar int32 ids\n"
                        "element vertex 3\nproperty int8 flags\nproperty float32 x\nproperty float32 y\n"
                        "property list uint16 float32 weights\nproperty float32 z\nproperty uint16 quality\n"
                        "element face 1\nproperty uchar kind\nproperty list uint8 int32 vertex_indices\n"
                        "property list uchar float texcoord\n"
                        "element edge 2\nproperty int vertex1\nproperty int vertex2\nend_header\n";
        if (!binary) {
            s += "1.5 2 7 8\n1 0 0 2 0.5 0.5 0 9\n2 1 0 0 0 9\n3 0 1 1 1.0 0 9\n9 3 0 1 2 2 0.1 0.2\n0 1\n1 2\n";
        } else {
            put<float>(s, 1.5f);
            put<uint8_t>(s, 2);
            put<int32_t>(s, 7);
            put<int32_t>(s, 8);
            float xyz[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
            for (int i = 0; i < 3; ++i) {
                put<int8_t>(s, 1);
                put<float>(s, xyz[i][0]);
                put<float>(s, xyz[i][1]);
                put<uint16_t>(s, uint16_t(i));  // list of i weights
                for (int k = 0; k < i; ++k) put<float>(s, 0.5f);
                put<float>(s, xyz[i][2]);
                put<uint16_t>(s, 9);
            }
            put<uint8_t>(s, 9);
            put<uint8_t>(s, 3);
            for (int32_t i : {0, 1, 2}) put<int32_t>(s, i);
            put<uint8_t>(s, 2);
            put<float>(s, 0.1f);
            put<float>(s, 0.2f);
            for (int32_t i : {0, 1, 1, 2}) put<int32_t>(s, i);
        }
        Mesh m = io::read_ply(dir.write("extra.ply", s));
        ASSERT_EQ(m.vertex_count(), 3u) << binary;
        EXPECT_EQ(m.positions[1], glm::vec3(1, 0, 0)) << binary;
        EXPECT_EQ(m.positions[2], glm::vec3(0, 1, 0)) << binary;
        ASSERT_EQ(m.triangle_count(), 1u) << binary;
        EXPECT_EQ(m.triangles[0], glm::uvec3(0, 1, 2)) << binary;
    }
}

TEST(PlyReader, PolygonsAreFanTriangulatedAndShortFacesDropped) {
    TempDir dir;
    std::string s =
        "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 2\nproperty list uchar int vertex_indices\nend_header\n"
        "0 0 0\n1 0 0\n1 1 0\n0.5 1.5 0\n0 1 0\n5 0 1 2 3 4\n2 0 1\n";
    Mesh m = io::read_ply(dir.write("penta.ply", s));
    ASSERT_EQ(m.triangle_count(), 3u);
    EXPECT_EQ(m.triangles[2], glm::uvec3(0, 3, 4));
}

TEST(PlyReader, CrlfHeaderIsAccepted) {
    TempDir dir;
    std::string s = cube_ascii_ply();
    std::string crlf;
    for (char c : s) {
        if (c == '\n') crlf += '\r';
        crlf += c;
    }
    expect_cube(io::read_ply(dir.write("crlf.ply", crlf)));
}

TEST(PlyReader, EmptyFileIsAnError) {
    TempDir dir;
    EXPECT_TRUE(LoadFailsWith(dir.write("empty.ply", ""), "empty file"));
}

TEST(PlyReader, MissingMagicIsAnError) {
    TempDir dir;
    EXPECT_TRUE(LoadFailsWith(dir.write("x.ply", "solid not a ply\n"), "not a PLY file"));
    EXPECT_TRUE(LoadFailsWith(dir.write("y.ply", std::string("\x89PNG\r\n\x1a\n\0\0", 10)), "not a PLY file"));
}

TEST(PlyReader, HeaderErrorsAreReportedWithLine) {
    TempDir dir;
    EXPECT_TRUE(LoadFailsWith(dir.write("a.ply", "ply\nformat ascii 1.0\nelement vertex 3\n"),
                              "truncated PLY header (no end_header)"));
    EXPECT_TRUE(
        LoadFailsWith(dir.write("b.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty quad x\nend_header\n"),
                      "unknown PLY property type 'quad' at line 4"));
    EXPECT_TRUE(
        LoadFailsWith(dir.write("c.ply", "ply\nformat utf8 1.0\nend_header\n"), "unknown PLY format 'utf8' at line 2"));
    EXPECT_TRUE(LoadFailsWith(dir.write("d.ply", "ply\nformat ascii 1.0\nelement vertex many\nend_header\n"),
                              "expected an element count but found 'many' at line 3"));
    EXPECT_TRUE(
        LoadFailsWith(dir.write("e.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float y\nend_header\n1\n"),
                      "PLY vertex element lacks x, y or z"));
}

// Blender 2.47's PLY export writes this line without `comment`; assimp and Blender skip it.
const std::string kBlenderLine = "Created by Blender3D 247 - www.blender.org, source file: ''";

// `ply` with `line` inserted after the format line (line 3).
std::string with_line_after_format(std::string ply, const std::string& line) {
    const size_t at = ply.find('\n', ply.find("format")) + 1;
    return ply.insert(at, line + "\n");
}

TEST(PlyReader, HeaderLinesThatAreNotPlyAreSkippedWithOneWarning) {
    TempDir dir;
    for (auto [name, bytes] : std::vector<std::pair<std::string, std::string>>{
             {"ascii.ply", cube_ascii_ply()}, {"le.ply", cube_binary_ply(false)}, {"be.ply", cube_binary_ply(true)}}) {
        const std::string p = dir.write(name, with_line_after_format(bytes, kBlenderLine));
        Mesh m = load_mesh(p);
        EXPECT_EQ(m.vertex_count(), 8u) << name;
        EXPECT_EQ(m.triangle_count(), 12u) << name;
        EXPECT_EQ(sorted_positions(m), sorted_cube()) << name;
        EXPECT_EQ(m.warnings,
                  std::vector<std::string>{
                      p + ": skipped 1 header line that is not PLY (line 3: 'Created by Blender3D 247...')"})
            << name;
    }
}

TEST(PlyReader, SeveralForeignHeaderLinesNameTheFirst) {
    TempDir dir;
    std::string ply = with_line_after_format(cube_ascii_ply(), "  exported\r");
    ply = with_line_after_format(ply, "by hand");  // now line 3; "  exported" is line 4
    const size_t props = ply.find("property float z\n");
    ply.insert(props, "x-custom 1 2\n");
    const std::string p = dir.write("several.ply", ply);
    Mesh m = load_mesh(p);
    EXPECT_EQ(m.triangle_count(), 12u);
    EXPECT_EQ(m.warnings,
              std::vector<std::string>{p + ": skipped 3 header lines that are not PLY (first: line 3: 'by hand')"});
}

TEST(PlyReader, MalformedKeywordLinesAreStillErrors) {
    TempDir dir;
    const std::string ply = with_line_after_format(cube_ascii_ply(), kBlenderLine);
    std::string bad = ply;
    bad.replace(bad.find("element vertex 8"), 16, "element vertex x");
    EXPECT_TRUE(LoadFailsWith(dir.write("a.ply", bad), "expected an element count but found 'x' at line 5"));
    bad = ply;
    bad.replace(bad.find("property float z"), 16, "property quad z");
    EXPECT_TRUE(LoadFailsWith(dir.write("b.ply", bad), "unknown PLY property type 'quad' at line 8"));
}

TEST(PlyReader, TruncatedBinaryIsAnError) {
    TempDir dir;
    std::string s = cube_binary_ply(false);
    EXPECT_TRUE(LoadFailsWith(dir.write("cut_vertices.ply", s.substr(0, s.find("end_header") + 11 + 40)),
                              "header claims 8 vertices but file has only 40 bytes"));
    EXPECT_TRUE(LoadFailsWith(dir.write("cut_faces.ply", s.substr(0, s.size() - 3)), "truncated"));
}

TEST(PlyReader, TruncatedAsciiReportsLine) {
    TempDir dir;
    std::string s = cube_ascii_ply();
    EXPECT_TRUE(LoadFailsWith(dir.write("cut.ply", s.substr(0, s.size() - 4)), "unexpected end of file while reading"));
    EXPECT_TRUE(LoadFailsWith(dir.write("cut.ply", s.substr(0, s.size() - 4)), "at line 24"));
}

TEST(PlyReader, HeaderClaimingTwoToThe31ElementsFailsWithoutAllocating) {
    TempDir dir;
    std::string s = cube_binary_ply(false);
    std::string v = s, f = s, a = cube_ascii_ply();
    v.replace(v.find("vertex 8"), 8, "vertex 2147483648");
    f.replace(f.find("face 6"), 6, "face 2147483648");
    a.replace(a.find("vertex 8"), 8, "vertex 2147483648");
    EXPECT_TRUE(LoadFailsWith(dir.write("v.ply", v), "header claims 2147483648 vertices but file has only"));
    EXPECT_TRUE(LoadFailsWith(dir.write("f.ply", f), "header claims 2147483648 faces but file has only 102 bytes"));
    EXPECT_TRUE(LoadFailsWith(dir.write("a.ply", a), "header claims 2147483648 vertices but file has only"));
    std::string huge_list =
        "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nelement face 1\nproperty list uint int vertex_indices\nend_header\n";
    for (int k = 0; k < 9; ++k) put<float>(huge_list, float(k % 2));
    put<uint32_t>(huge_list, 0x80000000u);
    put<int32_t>(huge_list, 0);
    EXPECT_TRUE(LoadFailsWith(dir.write("list.ply", huge_list), "list claims 2147483648 items"));
}

TEST(PlyReader, OutOfRangeAndNegativeIndicesAreErrors) {
    TempDir dir;
    std::string s = cube_ascii_ply();
    std::string big = s, neg = s;
    big.replace(big.rfind("4 1 2 6 5"), 9, "4 1 2 6 8");
    neg.replace(neg.rfind("4 1 2 6 5"), 9, "4 1 -1 6 5");
    EXPECT_TRUE(
        LoadFailsWith(dir.write("big.ply", big), "face 5 refers to vertex 8 but there are only 8 vertices at line 24"));
    EXPECT_TRUE(LoadFailsWith(dir.write("neg.ply", neg), "face 5 refers to vertex -1"));
    std::string bin = cube_binary_ply(true);
    bin[bin.size() - 1] = 9;  // last index of the last face, big endian low byte
    EXPECT_TRUE(
        LoadFailsWith(dir.write("bin.ply", bin), "face 5 refers to vertex 9 but there are only 8 vertices at byte"));
}

TEST(PlyReader, NanInfAndNonNumericValuesAreErrors) {
    TempDir dir;
    std::string s = cube_ascii_ply();
    size_t at = s.find("end_header\n") + 11;
    std::string nan = s, inf = s, word = s;
    nan.replace(s.find("1 1 0\n", at), 5, "1 nan 0");
    inf.replace(s.find("1 1 0\n", at), 5, "1 -inf 0");
    word.replace(s.find("1 1 0\n", at), 5, "1 one 0");
    EXPECT_TRUE(LoadFailsWith(dir.write("nan.ply", nan), "vertex 2 has a non-finite coordinate at line 13"));
    EXPECT_TRUE(LoadFailsWith(dir.write("inf.ply", inf), "vertex 2 has a non-finite coordinate"));
    EXPECT_TRUE(LoadFailsWith(dir.write("word.ply", word), "expected a PLY property value but found 'one' at line 13"));
    std::string bin = cube_binary_ply(false);
    size_t data = bin.find("end_header\n") + 11;
    float n = std::nanf("");
    std::memcpy(&bin[data + 12 * 3 + 4], &n, 4);
    EXPECT_TRUE(LoadFailsWith(dir.write("nan_bin.ply", bin), "vertex 3 has a non-finite coordinate"));
}

TEST(PlyReader, ElementsWithoutPropertiesTakeNoTimeWhateverTheirCount) {
    TempDir dir;
    std::string s = cube_binary_ply(false);
    s.insert(s.find("element face"), "element nothing 1152921504606846976\n");
    s.insert(s.find("end_header"), "element face 1152921504606846976\n");
    EXPECT_EQ(io::read_ply(dir.write("empty_elements.ply", s)).triangle_count(), 12u);
}

TEST(PlyReader, PointCloudHasNoTriangles) {
    TempDir dir;
    EXPECT_TRUE(LoadFailsWith(dir.write("points.ply",
                                        "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\n"
                                        "property float y\nproperty float z\nend_header\n0 0 0\n1 1 1\n"),
                              "no triangles"));
}

}  // namespace
}  // namespace inkshade::test
