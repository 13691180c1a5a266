// Material colours reach every shading model's C: PLY vertex colours, MTL Kd per face
// group, and the per-mesh base colour multiplying both.
#include <algorithm>

#include "inkshade/io.hpp"
#include "render/render_fixture.hpp"
#include "support/temp_dir.hpp"

namespace inkshade::test {
namespace {

RenderOptions small() {
    RenderOptions o;
    o.width = o.height = 64;
    o.samples = 1;
    return o;
}

// A unit square in the z = 0 plane facing +z, split at x = 0 into a left and right half.
const char* kTwoHalvesPly =
    "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\nproperty float z\n"
    "property uchar red\nproperty uchar green\nproperty uchar blue\nelement face 4\n"
    "property list uchar int vertex_indices\nend_header\n"
    "-1 -1 0 255 0 0\n0 -1 0 255 0 0\n0 1 0 255 0 0\n-1 1 0 255 0 0\n"
    "0 -1 0 0 0 255\n1 -1 0 0 0 255\n1 1 0 0 0 255\n0 1 0 0 0 255\n"
    "3 0 1 2\n3 0 2 3\n3 4 5 6\n3 4 6 7\n";

TEST(MaterialColors, PlyVertexColoursAreTheBaseColour) {
    TempDir dir;
    Mesh mesh = load_mesh(dir.write("halves.ply", kTwoHalvesPly));
    ASSERT_EQ(mesh.colors.size(), mesh.positions.size());
    ShadingSelection sel;
    sel.model = "lambert";
    sel.base_color = glm::vec3(1.0f, 1.0f, 0.5f);  // multiplies the vertex colour
    Image img = render_ortho(mesh, ambient_only(), sel, small());
    const uint8_t* left = img.pixel(16, 32);
    const uint8_t* right = img.pixel(48, 32);
    EXPECT_EQ(int(left[0]), 255);
    EXPECT_EQ(int(left[2]), 0);
    EXPECT_EQ(int(right[0]), 0);
    EXPECT_EQ(int(right[2]), 128);  // 0.5 * 255
}

TEST(MaterialColors, MtlDiffusePerFaceGroup) {
    TempDir dir;
    dir.write("m.mtl", "newmtl green\nKd 0 0.6 0\nnewmtl grey\nKd 0.3 0.3 0.3\n");
    std::string obj = dir.write("halves.obj",
                                "mtllib m.mtl\nv -1 -1 0\nv 0 -1 0\nv 0 1 0\nv -1 1 0\nv 1 -1 0\nv 1 1 0\n"
                                "usemtl green\nf 1 2 3 4\nusemtl grey\nf 2 5 6 3\n");
    Mesh mesh = load_mesh(obj);
    for (const char* model : {"lambert", "cel", "mtoon", "gooch"}) {
        ShadingSelection sel;
        sel.model = model;
        Image img = render_ortho(mesh, ambient_only(), sel, small());
        // The two halves differ in colour exactly as their materials do.
        const uint8_t* left = img.pixel(16, 32);
        const uint8_t* right = img.pixel(48, 32);
        EXPECT_GT(int(left[1]), int(left[0]) + 40) << model << ": green half not green";
        EXPECT_NEAR(int(right[0]), int(right[1]), 2) << model << ": grey half not grey";
        if (std::string(model) == "lambert") {
            EXPECT_NEAR(int(left[1]), 153, 1);
            EXPECT_NEAR(int(right[0]), 77, 1);
        }
    }
}

}  // namespace
}  // namespace inkshade::test
