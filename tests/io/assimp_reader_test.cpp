// The assimp fallback (src/io/assimp_reader.cpp) on a COLLADA file written here: two nodes
// instancing one quad with their own transforms and materials (a colour, a texture).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "inkshade/error.hpp"
#include "inkshade/image.hpp"
#include "inkshade/io.hpp"
#include "io/readers.hpp"

namespace inkshade {
namespace {

namespace fs = std::filesystem;

// Quad (0,0,0)-(1,1,0) with uvs; node "textured" translated by (1,2,3), node "blue" scaled by 2
// then translated by (-5,0,0). COLLADA 1.4.1, as Blender and SketchUp export it.
constexpr const char* kDae = R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="meter" meter="1"/><up_axis>Y_UP</up_axis></asset>
  <library_images><image id="checker" name="checker"><init_from>checker.png</init_from></image></library_images>
  <library_effects>
    <effect id="textured-fx"><profile_COMMON>
      <newparam sid="surf"><surface type="2D"><init_from>checker</init_from></surface></newparam>
      <newparam sid="samp"><sampler2D><source>surf</source></sampler2D></newparam>
      <technique sid="common"><lambert><diffuse><texture texture="samp" texcoord="UVMap"/></diffuse></lambert></technique>
    </profile_COMMON></effect>
    <effect id="blue-fx"><profile_COMMON>
      <technique sid="common"><lambert><diffuse><color>0.2 0.4 0.6 1</color></diffuse></lambert></technique>
    </profile_COMMON></effect>
  </library_effects>
  <library_materials>
    <material id="textured" name="textured"><instance_effect url="#textured-fx"/></material>
    <material id="blue" name="blue"><instance_effect url="#blue-fx"/></material>
  </library_materials>
  <library_geometries><geometry id="quad" name="quad"><mesh>
    <source id="quad-pos">
      <float_array id="quad-pos-array" count="12">0 0 0 1 0 0 1 1 0 0 1 0</float_array>
      <technique_common><accessor source="#quad-pos-array" count="4" stride="3">
        <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
      </accessor></technique_common>
    </source>
    <source id="quad-uv">
      <float_array id="quad-uv-array" count="8">0 0 1 0 1 1 0 1</float_array>
      <technique_common><accessor source="#quad-uv-array" count="4" stride="2">
        <param name="S" type="float"/><param name="T" type="float"/>
      </accessor></technique_common>
    </source>
    <vertices id="quad-vtx"><input semantic="POSITION" source="#quad-pos"/></vertices>
    <triangles material="mat" count="2">
      <input semantic="VERTEX" source="#quad-vtx" offset="0"/>
      <input semantic="TEXCOORD" source="#quad-uv" offset="1" set="0"/>
      <p>0 0 1 1 2 2 0 0 2 2 3 3</p>
    </triangles>
  </mesh></geometry></library_geometries>
  <library_visual_scenes><visual_scene id="scene">
    <node id="textured-node" name="textured-node">
      <translate>1 2 3</translate>
      <instance_geometry url="#quad"><bind_material><technique_common>
        <instance_material symbol="mat" target="#textured"><bind_vertex_input semantic="UVMap" input_semantic="TEXCOORD" input_set="0"/></instance_material>
      </technique_common></bind_material></instance_geometry>
    </node>
    <node id="blue-node" name="blue-node">
      <translate>-5 0 0</translate><scale>2 2 2</scale>
      <instance_geometry url="#quad"><bind_material><technique_common>
        <instance_material symbol="mat" target="#blue"/>
      </technique_common></bind_material></instance_geometry>
    </node>
  </visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
)";

class AssimpReader : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("inkshade-assimp-" + std::to_string(::getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string write(const std::string& name, const std::string& text) {
        const fs::path p = dir_ / name;
        std::ofstream(p, std::ios::binary) << text;
        return p.string();
    }
    fs::path dir_;
};

#if INKSHADE_HAVE_ASSIMP

TEST_F(AssimpReader, ColladaNodesMaterialsAndTexturesLoad) {
    Image checker(2, 2);  // red, green / blue, white
    const uint8_t px[4][4] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {255, 255, 255, 255}};
    for (int i = 0; i < 4; ++i)
        for (int c = 0; c < 4; ++c) checker.rgba[4 * i + c] = px[i][c];
    write_png((dir_ / "checker.png").string(), checker);
    const Mesh mesh = load_mesh(write("scene.dae", kDae));

    EXPECT_TRUE(mesh.warnings.empty()) << mesh.warnings.front();
    ASSERT_EQ(mesh.triangle_count(), 4u);
    const BoundingBox box = mesh.bounds();
    EXPECT_EQ(box.min, glm::vec3(-5.0f, 0.0f, 0.0f));
    EXPECT_EQ(box.max, glm::vec3(2.0f, 3.0f, 3.0f));
    ASSERT_EQ(mesh.face_materials.size(), 4u);
    ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());

    // Each triangle: its material by its node's place (textured at z = 3, blue at z = 0).
    int textured = 0, blue = 0;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const Material& m = mesh.materials.at(mesh.face_materials[t]);
        const float z = mesh.positions[mesh.triangles[t].x].z;
        if (z == 3.0f) {
            ++textured;
            ASSERT_TRUE(m.texture) << m.name;
            EXPECT_EQ(m.texture->width, 2);
            EXPECT_EQ(m.texture->height, 2);
            EXPECT_EQ(m.texture->rgba[0], 255);  // top-left texel red
            EXPECT_EQ(m.texture->rgba[1], 0);
            EXPECT_EQ(m.diffuse, glm::vec3(1.0f));
        } else {
            ++blue;
            EXPECT_EQ(z, 0.0f);
            EXPECT_FALSE(m.texture);
            EXPECT_NEAR(m.diffuse.r, 0.2f, 1e-6f);
            EXPECT_NEAR(m.diffuse.g, 0.4f, 1e-6f);
            EXPECT_NEAR(m.diffuse.b, 0.6f, 1e-6f);
        }
    }
    EXPECT_EQ(textured, 2);
    EXPECT_EQ(blue, 2);
    // uv (1,1) sits at the quad's (1,1) corner of the translated node: (2,3,3).
    bool corner = false;
    for (size_t v = 0; v < mesh.positions.size(); ++v)
        corner |= mesh.positions[v] == glm::vec3(2, 3, 3) && mesh.uvs[v] == glm::vec2(1, 1);
    EXPECT_TRUE(corner);
    // Counter-clockwise seen from +z: the face normal of the first triangle points at +z.
    const glm::uvec3 t = mesh.triangles[0];
    const glm::vec3 n =
        glm::cross(mesh.positions[t.y] - mesh.positions[t.x], mesh.positions[t.z] - mesh.positions[t.x]);
    EXPECT_GT(n.z, 0.0f);
}

TEST_F(AssimpReader, MissingTextureIsAWarningNotAFailure) {
    const Mesh mesh = load_mesh(write("scene.dae", kDae));
    ASSERT_EQ(mesh.triangle_count(), 4u);
    ASSERT_EQ(mesh.warnings.size(), 1u);
    EXPECT_NE(mesh.warnings[0].find("checker.png"), std::string::npos) << mesh.warnings[0];
    EXPECT_NE(mesh.warnings[0].find("base colour"), std::string::npos) << mesh.warnings[0];
}

TEST_F(AssimpReader, BadFilesAreOneLineErrorsNamingTheFile) {
    const std::string truncated = write("truncated.dae", std::string(kDae).substr(0, 900));
    static constexpr char kFbxHeader[] = "Kaydara FBX Binary  \0\x1a\0\xff\xff\xff\xff";  // then nothing
    const std::string garbage = write("garbage.fbx", std::string(kFbxHeader, sizeof kFbxHeader - 1));
    const std::string no_mesh = write("empty.dae", R"(<?xml version="1.0"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1"><asset/>
<library_visual_scenes><visual_scene id="s"><node id="n"/></visual_scene></library_visual_scenes>
<scene><instance_visual_scene url="#s"/></scene></COLLADA>)");
    for (const std::string& path : {truncated, garbage, no_mesh, (dir_ / "missing.dae").string()}) {
        try {
            load_mesh(path);
            ADD_FAILURE() << path << " loaded";
        } catch (const InputError& e) {
            const std::string what = e.what();
            EXPECT_EQ(what.rfind(path, 0), 0u) << what;
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        }
    }
}

TEST(AssimpExtensions, FallbackKeepsNativeReadersAndListsItsFormats) {
    EXPECT_TRUE(io::assimp_reads(".fbx"));
    EXPECT_TRUE(io::assimp_reads(".dae"));
    EXPECT_TRUE(io::assimp_reads(".3ds"));
    EXPECT_FALSE(io::assimp_reads(".nope"));
    EXPECT_NE(io::assimp_extensions().find(".fbx"), std::string::npos);
}

#else

TEST_F(AssimpReader, WithoutAssimpOtherFormatsAreUnknownExtensions) {
    EXPECT_FALSE(io::assimp_reads(".fbx"));
    EXPECT_THROW(load_mesh(write("scene.dae", kDae)), InputError);
}

#endif

}  // namespace
}  // namespace inkshade
