// Inputs the fuzzers (fuzz/, docs/testing.md "Fuzzing") found crashing, hanging or allocating
// without bound, and the limits the issue asks for. tests/io/fuzz_regressions/TARGET/ holds each
// input exactly as libFuzzer saved it; FuzzRegressions.Replay* feed them (and the seed corpora)
// through the fuzz targets' own code (fuzz/mesh_targets.hpp: the same file cutting, loading,
// line drawing and contract checks), so every one must load or fail with a one-line InputError.
// The named tests pin each fix down with a small input written by hand.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "../../fuzz/mesh_targets.hpp"
#include "io/gltf_files.hpp"
#include "io/mesh_files.hpp"
#include "io/texture_image.hpp"
#include "support/fuzz_replay.hpp"
#include "support/temp_dir.hpp"

namespace inkshade::test {
namespace {

// Every saved input of `target` and its seed corpus (fuzz/corpus/TARGET: valid files).
void replay(const std::string& target, void (*run)(std::string_view)) {
    const std::string saved = "tests/io/fuzz_regressions/" + target, corpus = "fuzz/corpus/" + target;
    replay_fuzz_inputs({saved.c_str(), corpus.c_str()}, [&](const std::string& bytes) { run(bytes); });
}

TEST(FuzzRegressions, ReplayObj) { replay("obj", fuzz::obj_input); }
TEST(FuzzRegressions, ReplayStl) { replay("stl", fuzz::stl_input); }
TEST(FuzzRegressions, ReplayPly) { replay("ply", fuzz::ply_input); }
TEST(FuzzRegressions, ReplayOff) { replay("off", fuzz::off_input); }
TEST(FuzzRegressions, ReplayGltf) { replay("gltf", fuzz::gltf_input); }
// The posed seed reaches the pose code through fuzz_gltf's harness: byte 0 picks the animation
// at a time, the morph target and the expression (fuzz_pose), and the posed load moves vertices.
TEST(FuzzRegressions, PosedSeedIsPosedByTheHarness) {
    std::ifstream in(std::string(INKSHADE_SOURCE_DIR) + "/fuzz/corpus/gltf/posed.glb", std::ios::binary);
    const std::string seed((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_GT(seed.size(), 1u);
    TempDir dir;
    const std::string path = dir.write("posed.glb", seed.substr(1));
    const Mesh rest = load_mesh(path);
    ASSERT_EQ(rest.pose_names.animations.size(), 1u);
    const Pose pose = fuzz::fuzz_pose(rest.pose_names, static_cast<unsigned char>(seed[0]) / 2);
    EXPECT_EQ(pose.animation, "wave");
    EXPECT_FLOAT_EQ(pose.time, 3.75f);
    ASSERT_EQ(pose.morphs.size(), 1u);
    EXPECT_EQ(pose.morphs[0].name, "smile");
    ASSERT_EQ(pose.expressions.size(), 1u);
    EXPECT_EQ(pose.expressions[0].name, "happy");
    const Mesh posed = load_mesh(path, LoadOptions{.pose = pose});
    ASSERT_EQ(posed.positions.size(), rest.positions.size());
    EXPECT_NE(posed.positions, rest.positions);
    EXPECT_EQ(posed.lights.size(), 2u);
    EXPECT_EQ(posed.cameras.size(), 1u);
}

TEST(FuzzRegressions, ReplayVrma) { replay("vrma", fuzz::vrma_input); }

// The rig seeds reach the VRM pose code: the clip retargets onto the avatar's humanoid and moves
// its head (the spine turns and the hips rise), the expression moves the morph target, and the
// spring bones and the roll constraint load without an error.
TEST(FuzzRegressions, VrmaSeedPosesTheRig) {
    std::ifstream in(std::string(INKSHADE_SOURCE_DIR) + "/fuzz/corpus/vrma/rig_at_1.25s.bin", std::ios::binary);
    const std::string seed((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_GT(seed.size(), 1u);
    const auto parts = fuzz::split(std::string_view(seed).substr(1), fuzz::kPartMarker, 2);
    ASSERT_EQ(parts.size(), 2u);
    TempDir dir;
    const std::string avatar = dir.write("rig.vrm", std::string(parts[0]));
    const std::string clip = dir.write("clip.vrma", std::string(parts[1]));
    const Mesh rest = load_mesh(avatar);
    ASSERT_EQ(rest.pose_names.expressions.size(), 1u);
    const Mesh posed = load_mesh(avatar, LoadOptions{.pose = {.animation = clip, .time = 1.25f}});
    ASSERT_EQ(posed.positions.size(), rest.positions.size());
    EXPECT_NE(posed.positions, rest.positions);
    EXPECT_TRUE(posed.warnings.empty()) << posed.warnings.front();
}

TEST(FuzzRegressions, ReplayMeshPipeline) { replay("mesh_pipeline", fuzz::mesh_pipeline_input); }

std::shared_ptr<const Texture> decode_texture_for_test(const std::string& bytes, std::string& problem) {
    return io::decode_texture(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), "test.png", problem);
}

// A 2 x 2 PNG whose chunk `type` has its length field replaced by `length`.
std::string png_with_chunk_length(const char* type, uint32_t length) {
    std::string png = png_bytes(2, 2, kTexturePixels);
    const size_t at = png.find(type);
    for (int k = 0; k < 4; ++k) png[at - 4 + size_t(k)] = char(length >> (24 - 8 * k));
    return png;
}

// fuzz_ply and fuzz_gltf: stb_image grows its IDAT buffer to the length a chunk claims before
// it reads the chunk, so a 70-byte PNG made it allocate 1.7 GB. Chunks must now fit the image.
TEST(FuzzRegressions, PngChunkClaimingGigabytesIsRefusedBeforeDecoding) {
    std::string problem;
    const std::string png = png_with_chunk_length("IDAT", 0x70000000u);
    EXPECT_EQ(decode_texture_for_test(png, problem), nullptr);
    EXPECT_NE(problem.find("PNG chunk of 1879048192 bytes at offset 33 runs past the end"), std::string::npos)
        << problem;

    // Through a reader: the texture is a warning, the mesh loads.
    TempDir dir;
    dir.write("t.png", png);
    const std::string ply =
        "ply\nformat ascii 1.0\ncomment TextureFile t.png\nelement vertex 3\nproperty float x\n"
        "property float y\nproperty float z\nproperty float u\nproperty float v\nelement face 1\n"
        "property list uchar int vertex_indices\nend_header\n0 0 0 0 0\n1 0 0 1 0\n0 1 0 0 1\n3 0 1 2\n";
    Mesh m = load_mesh(dir.write("tri.ply", ply));
    ASSERT_EQ(m.warnings.size(), 1u);
    EXPECT_NE(m.warnings[0].find("texture 't.png' not loaded (corrupt image data (PNG chunk"), std::string::npos)
        << m.warnings[0];
}

// The "a 2 GiB claim in a 1 KiB file is refused instantly", for images: the header's
// size is checked against what the encoded bytes can hold before the decoder allocates.
TEST(FuzzRegressions, ImageClaimingMorePixelsThanItsBytesHoldIsRefused) {
    std::string png = png_bytes(2, 2, kTexturePixels);
    const size_t ihdr = png.find("IHDR") + 4;
    for (size_t k : {0u, 4u}) {  // width and height 16384 (stb_image ignores the CRC)
        png[ihdr + k + 2] = char(0x40);
        png[ihdr + k + 3] = char(0);
    }
    std::string problem;
    EXPECT_EQ(decode_texture_for_test(png, problem), nullptr);
    EXPECT_NE(problem.find("16384 x 16384 pixels cannot be encoded in " + std::to_string(png.size()) + " bytes"),
              std::string::npos)
        << problem;
    // The real 2 x 2 image still decodes.
    EXPECT_NE(decode_texture_for_test(png_bytes(2, 2, kTexturePixels), problem), nullptr) << problem;
}

// fuzz_mesh_pipeline: a PLY vertex at -1e34 made the bounding box diagonal overflow float,
// auto-framing put the eye at infinity, and line visibility converted NaN to int. Coordinates
// beyond +-1e15 are refused by load_mesh; up to that, lines are drawn with finite points.
TEST(FuzzRegressions, CoordinatesBeyond1e15AreRefusedAndLargeModelsDrawFinitely) {
    TempDir dir;
    EXPECT_TRUE(LoadFailsWith(dir.write("far.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 -1e34 0\n3 0 1 2\n"),
                              "vertex 2 has a coordinate beyond +-1e15 (too large to draw)"));
    EXPECT_TRUE(LoadFailsWith(dir.write("far2.off", "OFF\n3 1 0\n0 0 0\n2e15 0 0\n0 1 0\n3 0 1 2\n"),
                              "vertex 1 has a coordinate beyond"));

    std::string off = cube_off();
    for (const char* from : {"\n0 0 1\n", "\n1 1 1\n"})
        off.replace(off.find(from), 7, std::string(from).replace(1, 1, "-1e15"));
    const Mesh mesh = load_mesh(dir.write("large.off", off));
    LineExtractor extractor(mesh);
    const Camera camera = frame_camera(mesh.bounds(), {}, 1.0f);
    const LineDrawing drawing = extractor.draw(camera, 64, 64, {{"contour", {}}, {"crease", {}}, {"border", {}}});
    size_t points = 0;
    for (const LineLayer& layer : drawing.layers)
        for (const LinePath& path : layer.visible)
            for (glm::vec2 p : path.points) {
                EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y));
                ++points;
            }
    EXPECT_GT(points, 0u);
}

// fuzz_obj: tinyobj converts a `vw` (skin weight) joint id such as 1e400 to int, undefined
// behaviour; Inkshade uses no skin weights, so `vw` lines are dropped before tinyobj reads.
TEST(FuzzRegressions, ObjSkinWeightLinesAreIgnored) {
    TempDir dir;
    Mesh m = load_mesh(dir.write("vw.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvw 5 0 1e400\n  vw\t1 inf 2\nf 1 2 3\n"));
    EXPECT_EQ(m.triangle_count(), 1u);
}

// tinyobj ends a line at a lone '\r' but the pre-scan did not: "#...\rf 1 2 9" hid a face from
// the pre-scan's index checks. Both now see the same lines (old Mac files load as before).
TEST(FuzzRegressions, ObjLoneCarriageReturnEndsALineForThePrescanToo) {
    TempDir dir;
    EXPECT_TRUE(LoadFailsWith(dir.write("cr.obj", "v 0 0 0\rv 1 0 0\rv 0 1 0\r# note\rf 1 2 9\r"),
                              "face refers to vertex 9 but the file has only 3 at line 5"));
    EXPECT_TRUE(LoadFailsWith(
        dir.write("cr2.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n# note\rvw 1 1e400 1\rt x 1/1/0 99999999\rf 1 2 x\n"),
        "bad face index 'x'"));
    Mesh m = load_mesh(dir.write("mac.obj", "v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r"));
    EXPECT_EQ(m.triangle_count(), 1u);
}

// fuzz_obj: tinyobj's own number parser overflows an int on an exponent of ten digits
// ("Kd 1e2147483648" in an MTL file; "vn 1e2147483648 0 0" passed the pre-scan as infinity).
// Such numbers are refused before tinyobj reads the OBJ or its material libraries.
TEST(FuzzRegressions, ObjAndMtlNumbersWithTenDigitExponentsAreRefused) {
    TempDir dir;
    dir.write("m.mtl", "newmtl red\n# Kd 1e9999999999 in a comment is fine\nKd 1e2147483648 0 0\n");
    EXPECT_TRUE(LoadFailsWith(dir.write("mtl.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n"),
                              "material library 'm.mtl': number with a 10-digit exponent at line 3"));
    EXPECT_TRUE(
        LoadFailsWith(dir.write("vn.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1E-0000000001\nf 1//1 2//1 3//1\n"),
                      "number with a 10-digit exponent at line 4"));
    dir.write("ok.mtl", "newmtl red\nKd 1e0 0.5e-1 1E+2\n");
    Mesh m = load_mesh(dir.write("ok.obj", "mtllib ok.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n"));
    ASSERT_EQ(m.materials.size(), 1u);
    EXPECT_EQ(m.materials[0].diffuse, glm::vec3(1.0f, 0.05f, 1.0f));
}

// --- limits: claims checked against the file size before anything is allocated ------------

bool sanitized() {
#if defined(INKSHADE_SANITIZE) || defined(__SANITIZE_ADDRESS__)
    return true;
#else
    return false;
#endif
}

// Child process of expect_refused_without_allocating: load_mesh with an address space that may
// grow by 256 MiB only. Exit code 0: InputError; 2: std::bad_alloc; 3: another exception; 1: loaded.
[[noreturn]] void load_with_little_memory(const std::string& path) {
    long pages = 0;
    if (FILE* f = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(f, "%ld", &pages) != 1) pages = 0;
        std::fclose(f);
    }
    const rlim_t limit = rlim_t(pages) * rlim_t(sysconf(_SC_PAGESIZE)) + (rlim_t(256) << 20);
    const rlimit rl{limit, limit};
    if (pages == 0 || setrlimit(RLIMIT_AS, &rl) != 0) std::_Exit(4);
    try {
        load_mesh(path);
    } catch (const InputError&) {
        std::_Exit(0);
    } catch (const std::bad_alloc&) {
        std::_Exit(2);
    } catch (...) {
        std::_Exit(3);
    }
    std::_Exit(1);
}

// load_mesh(path) must fail with an InputError containing `phrase` without allocating from the
// claim: it runs first in a child whose address space may grow by only 256 MiB, where trusting
// a count of 2^31 would end in std::bad_alloc (or a null from malloc) instead. Sanitizer builds,
// which reserve terabytes of address space, check the message only.
void expect_refused_without_allocating(const std::string& path, const std::string& phrase) {
    if (!sanitized()) {
        GTEST_FLAG_SET(death_test_style, "threadsafe");
        EXPECT_EXIT(load_with_little_memory(path), ::testing::ExitedWithCode(0), "") << path;
        if (::testing::Test::HasFailure()) return;  // it allocated: not again in this process
    }
    EXPECT_TRUE(LoadFailsWith(path, phrase));
}

TEST(InputLimits, StlClaimingTwoBillionTrianglesInATinyFileIsRefused) {
    TempDir dir;
    std::string stl = binary_stl(cube_soup());
    stl.resize(84 + 50);  // one record
    for (int k = 0; k < 4; ++k) stl[80 + size_t(k)] = char(0x7fffffffu >> (8 * k));
    expect_refused_without_allocating(dir.write("claim.stl", stl),
                                      "header claims 2147483647 triangles but file has room for 1");
}

TEST(InputLimits, PlyAndOffClaimingTwoBillionElementsAreRefused) {
    TempDir dir;
    std::string ascii = cube_ascii_ply(), binary = cube_binary_ply(false), off = cube_off();
    ascii.replace(ascii.find("vertex 8"), 8, "vertex 2147483648");
    binary.replace(binary.find("face 6"), 6, "face 2147483648");
    off.replace(off.find("8 6 12"), 6, "8 2147483648 12");
    expect_refused_without_allocating(dir.write("v.ply", ascii), "header claims 2147483648 vertices but file has only");
    expect_refused_without_allocating(dir.write("f.ply", binary), "header claims 2147483648 faces but file has only");
    expect_refused_without_allocating(dir.write("f.off", off), "header claims 2147483648 faces but file has only");
    std::string list = cube_ascii_ply();  // one face's index list claims 2^31 - 1 items
    list.replace(list.find("\n4 0 3 2 1\n"), 2, "\n2147483647");
    expect_refused_without_allocating(dir.write("list.ply", list), "list claims");
}

TEST(InputLimits, GlbAndAccessorsClaimingGigabytesAreRefused) {
    TempDir dir;
    std::string glb = textured_quad().glb();
    for (int k = 0; k < 4; ++k) glb[8 + size_t(k)] = char(0x80000000u >> (8 * k));  // total length 2 GiB
    expect_refused_without_allocating(dir.write("length.glb", glb),
                                      "truncated GLB: the header says 2147483648 bytes but the file has");
    GltfBuilder g = textured_quad();
    g.doc["accessors"][0]["count"] = 2147483648LL;
    expect_refused_without_allocating(dir.write("count.glb", g.glb()), "claims 2147483648 elements (limit 805306368)");
    g = textured_quad();
    g.doc["bufferViews"][0]["byteLength"] = 2147483648LL;
    expect_refused_without_allocating(dir.write("view.glb", g.glb()), "is past the end of buffer 0");
}

// Node graphs are walked without recursion: cycles, shared children and deep chains end with
// an error instead of a hang or a stack overflow.
TEST(InputLimits, GltfNodeCyclesAndDeepHierarchiesAreErrors) {
    TempDir dir;
    GltfBuilder g = textured_quad();
    g.doc["nodes"][0]["children"] = {0};
    EXPECT_TRUE(LoadFailsWith(dir.write("self.glb", g.glb()), "node 0 is reached twice"));
    g.doc["nodes"][0]["children"] = {1};
    g.doc["nodes"].push_back({{"children", {0}}});
    g.doc.erase("scenes");
    g.doc.erase("scene");  // no scene and no root: every node is somebody's child
    EXPECT_TRUE(LoadFailsWith(dir.write("ring.glb", g.glb()), "no triangles (the scene has no mesh)"));
    g = textured_quad();
    for (int i = 1; i <= 2000; ++i) {
        g.doc["nodes"][size_t(i - 1)]["children"] = {i};
        g.doc["nodes"].push_back({{"mesh", 0}});
    }
    EXPECT_TRUE(LoadFailsWith(dir.write("deep.glb", g.glb()), "node hierarchy deeper than 1024"));
}

// tinygltf copies `extras` and `extensions` into its own value tree recursively: JSON nested
// 200000 deep (a 400 KB file) overflowed the stack. JSON may nest 512 levels.
TEST(InputLimits, DeeplyNestedGltfJsonIsRefusedBeforeTheStackOverflows) {
    TempDir dir;
    GltfBuilder g = textured_quad();
    std::string json = g.gltf_embedded();
    json.insert(json.size() - 1, ",\"extras\":" + std::string(200000, '[') + std::string(200000, ']'));
    EXPECT_TRUE(LoadFailsWith(dir.write("deep.gltf", json), "JSON nested deeper than 512 levels at byte"));
    g.doc["extensions"]["X"] = nlohmann::json::object();
    nlohmann::json* leaf = &g.doc["extensions"]["X"];
    for (int i = 0; i < 600; ++i)
        leaf = &((*leaf)["a\"[{"] = nlohmann::json::object());  // brackets in keys do not count
    EXPECT_TRUE(LoadFailsWith(dir.write("deep.glb", g.glb()), "JSON nested deeper than 512 levels"));
    g = textured_quad();
    g.doc["extras"] = nlohmann::json::parse(std::string(500, '[') + std::string(500, ']'));
    EXPECT_EQ(load_mesh(dir.write("fine.glb", g.glb())).triangle_count(), 2u);
}

TEST(InputLimits, ObjFaceReferringToVertexTwoBillionIsRefused) {
    TempDir dir;
    expect_refused_without_allocating(dir.write("idx.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 2147483648\n"),
                                      "face refers to vertex 2147483648 but the file has only 3 at line 4");
}

}  // namespace
}  // namespace inkshade::test
