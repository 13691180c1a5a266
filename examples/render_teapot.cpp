// Renders the built-in teapot in the `anime` style to a PNG and its object-space lines (those of
// the `ink-vector` style) to an SVG with the installed library (find_package(inkshade); see
// CMakeLists.txt here): what `inkshade render builtin:teapot --style anime --size 512x512` and
// `inkshade lines builtin:teapot --style ink-vector --size 512x512` write.
#include <cstdio>
#include <exception>
#include <string>

#include <inkshade/io.hpp>
#include <inkshade/scene.hpp>

int main(int argc, char** argv) {
    const std::string stem = argc > 1 ? argv[1] : "teapot";
    try {
        inkshade::SceneRequest request;  // what the CLI's options, Python's keywords and batch fill in
        request.model = "builtin:teapot";
        request.style = "anime";
        request.size = {512, 512};
        const inkshade::Scene scene = inkshade::make_scene(request);  // checks every value
        const inkshade::Mesh mesh = inkshade::load_mesh(scene.model, scene.load_options());
        const inkshade::Camera camera = scene.frame(mesh);  // auto-framed

        inkshade::Renderer renderer;  // headless OpenGL 4.5 (EGL)
        renderer.set_mesh(mesh);
        inkshade::write_png(stem + ".png",
                            inkshade::render_scene(renderer, scene, camera, scene.light(mesh.bounds(), camera)));

        request.style = "ink-vector";
        request.outputs = {.image = false, .line_drawing = true};
        const inkshade::Scene lines = inkshade::make_scene(request);
        inkshade::LineExtractor extractor(mesh);  // contours, creases... as vector paths
        const auto drawing = inkshade::draw_scene_lines(extractor, lines, camera);
        inkshade::write_svg(stem + ".svg", drawing, lines.style.background);
        std::printf("wrote %s.png and %s.svg with %zu line layers\n", stem.c_str(), stem.c_str(),
                    drawing.layers.size());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "render_teapot: %s\n", e.what());
        return 1;
    }
    return 0;
}
