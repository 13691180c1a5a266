// What each mesh fuzz target does with one input, as functions: the fuzz_*.cpp files call them
// from LLVMFuzzerTestOneInput, and tests/io/fuzz_regressions_test.cpp replays the inputs the
// fuzzers found through the very same code. Each returns normally, throws ContractBroken when a
// promise is broken, or lets an unexpected exception escape.
#pragma once
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz_common.hpp"
#include "inkshade/camera.hpp"
#include "inkshade/line_drawing.hpp"

namespace inkshade::fuzz {

// Cuts a model from the files next to it (MTL, textures, glTF buffers).
inline constexpr std::string_view kPartMarker = "\n#%%\n";

// OBJ + MTL (+ a map_Kd texture): the input is cut at "\n#%%\n" lines into up to three files
// side by side, input.obj, m.mtl (for `mtllib m.mtl`) and t.png (for `map_Kd t.png`; any image
// format); parts the input lacks are absent.
inline void obj_input(std::string_view data) {
    const auto parts = split(data, kPartMarker, 3);
    const std::string path = write_file("input.obj", parts[0]);
    if (parts.size() > 1)
        write_file("m.mtl", parts[1]);
    else
        remove_file("m.mtl");
    if (parts.size() > 2)
        write_file("t.png", parts[2]);
    else
        remove_file("t.png");
    Mesh mesh;
    load_checked(path, mesh);
}

// STL, ASCII and binary (the reader picks by size and content).
inline void stl_input(std::string_view data) {
    Mesh mesh;
    load_checked(write_file("input.stl", data), mesh);
}

// OFF (and COFF, NOFF, STOFF, ...).
inline void off_input(std::string_view data) {
    Mesh mesh;
    load_checked(write_file("input.off", data), mesh);
}

// PLY, ascii and binary of both byte orders; a part after "\n#%%\n" becomes t.png next to the
// file, for `comment TextureFile t.png`.
inline void ply_input(std::string_view data) {
    const auto parts = split(data, kPartMarker, 2);
    const std::string path = write_file("input.ply", parts[0]);
    if (parts.size() > 1)
        write_file("t.png", parts[1]);
    else
        remove_file("t.png");
    Mesh mesh;
    load_checked(path, mesh);
}

// The pose `choice` (1..127) picks among the names a loaded glTF/VRM file's pose takes: an
// animation (or none), a time of 0..5.5 s (which also runs the spring bones, off when bit 64 is
// set), the first morph target at a weight of -1..2.75 and the first expression at 0, 0.5 or 1;
// the file is loaded again in it, so that animation sampling, skinning, spring bones, morph
// targets and VRM expression binds see the fuzzer's bytes.
inline Pose fuzz_pose(const FilePoseNames& names, unsigned choice) {
    Pose pose;
    pose.time = float((choice * 7) % 23) * 0.25f;
    pose.spring_bones = (choice & 64) == 0;
    if (!names.animations.empty()) {
        const size_t a = choice % (names.animations.size() + 1);
        if (a < names.animations.size()) {
            const std::string& name = names.animations[a].name;
            pose.animation = name.empty() ? std::to_string(a) : name;
        }
    }
    if (!names.morph_targets.empty() && (choice & 8))
        pose.morphs.push_back({names.morph_targets.front(), float(choice % 16) * 0.25f - 1.0f});
    if (!names.expressions.empty() && (choice & 16))
        pose.expressions.push_back({names.expressions.front().name, float(choice % 3) * 0.5f});
    return pose;
}

// Loads `path` in `pose`, as load_checked does; an error may also be about `other` (a VRM
// animation file the pose names), and then starts with that file's name.
inline void load_posed(const std::string& path, const Pose& pose, const std::string& other = {}) {
    Mesh mesh;
    try {
        mesh = load_mesh(path, LoadOptions{.pose = pose});
    } catch (const InputError& e) {
        check_error(e, !other.empty() && std::string(e.what()).rfind(other + ": ", 0) == 0 ? other : path);
        return;
    }
    check_mesh(mesh);
}

// glTF 2.0 JSON and GLB: byte 0's lowest bit picks the extension (even: .gltf, odd: .glb; the
// reader also decides by content), its other bits a pose (fuzz_pose; 0: the rest pose only); the
// rest is cut at "\n#%%\n" into the file and b.bin next to it (for "uri": "b.bin" buffers and
// images).
inline void gltf_input(std::string_view data) {
    if (data.empty()) return;
    const unsigned byte0 = static_cast<unsigned char>(data[0]);
    const char* name = byte0 % 2 == 0 ? "input.gltf" : "input.glb";
    const auto parts = split(data.substr(1), kPartMarker, 2);
    const std::string path = write_file(name, parts[0]);
    if (parts.size() > 1)
        write_file("b.bin", parts[1]);
    else
        remove_file("b.bin");
    Mesh mesh;
    if (!load_checked(path, mesh) || byte0 / 2 == 0) return;
    const Pose pose = fuzz_pose(mesh.pose_names, byte0 / 2);
    if (pose != Pose{}) load_posed(path, pose);
}

// A VRM avatar and a VRM animation (.vrma) cut from one input at "\n#%%\n": the avatar takes the
// clip at a time of 0..7.75 s picked by byte 0 (its bit 128: spring bones off), which reads the
// clip, retargets it to the avatar's humanoid with its expressions and look-at, and applies the
// avatar's node constraints.
inline void vrma_input(std::string_view data) {
    if (data.empty()) return;
    const unsigned byte0 = static_cast<unsigned char>(data[0]);
    const auto parts = split(data.substr(1), kPartMarker, 2);
    const std::string avatar = write_file("avatar.vrm", parts[0]);
    const std::string clip = write_file("clip.vrma", parts.size() > 1 ? parts[1] : std::string_view());
    Pose pose;
    pose.animation = clip;
    pose.time = float(byte0 % 32) * 0.25f;
    pose.spring_bones = (byte0 & 128) == 0;
    load_posed(avatar, pose, clip);
}

// The mesh pipeline after loading, on whatever a loader accepts: welding and normals (load_mesh),
// then adjacency, curvature and object-space line extraction with visibility (LineExtractor) for
// contour, suggestive, crease, border, ridge, valley, isophote, topographic and highlight lines,
// and the SVG and JSON writers.
// Byte 0 picks the format, byte 1 the view and options; the rest is the file. Meshes over
// kMaxPipelineTriangles are skipped to keep executions fast.
inline constexpr size_t kMaxPipelineTriangles = 5000;
inline void mesh_pipeline_input(std::string_view data) {
    static constexpr const char* kExtensions[] = {".obj", ".stl", ".ply", ".off", ".gltf", ".glb"};
    if (data.size() < 2) return;
    const std::string ext = kExtensions[static_cast<unsigned char>(data[0]) % std::size(kExtensions)];
    const unsigned options = static_cast<unsigned char>(data[1]);
    Mesh mesh;
    if (!load_checked(write_file("input" + ext, data.substr(2)), mesh) || mesh.triangle_count() > kMaxPipelineTriangles)
        return;

    // Eight views around the model, auto-framed as `inkshade lines` does, from above or below,
    // sometimes orthographic; sometimes hidden lines too, every piece kept and smoothed.
    CameraOptions view;
    view.azimuth_degrees = float(options % 8) * 45.0f;
    view.elevation_degrees = (options & 8) ? -30.0f : 20.0f;
    view.orthographic = (options & 16) != 0;
    const int width = 48, height = 32;
    const Camera camera = frame_camera(mesh.bounds(), view, float(width) / float(height));
    std::vector<LineSettings> lines;
    for (const char* type : {"contour", "suggestive", "crease", "border", "ridge", "valley", "isophote", "topo",
                             "suggestive-highlight", "principal-highlight"}) {
        LineSettings settings{type, {}};
        if (options & 32) {
            settings.params["hidden"] = {1.0f};
            settings.params["min-length"] = {0.0f};
            settings.params["smooth"] = {2.0f};
        }
        lines.push_back(settings);
    }
    if (options & 64) lines[0].params["silhouette-edges"] = {1.0f};

    LineExtractor extractor(mesh);
    const LineDrawing drawing = extractor.draw(camera, width, height, lines);
    if (drawing.layers.size() != lines.size()) broken("a line layer is missing");
    for (const LineLayer& layer : drawing.layers)
        for (const auto* paths : {&layer.visible, &layer.hidden})
            for (const LinePath& p : *paths)
                if (p.depth.size() != p.points.size() || p.strength.size() != p.points.size())
                    broken("path attributes do not match its points");
    if (options & 128) extractor.radial_curvature(camera);
    (void)format_svg(drawing, glm::vec4(1.0f));
    (void)format_lines_json(drawing);
}

}  // namespace inkshade::fuzz
