// Renders the built-in teapot in the `anime` style to a PNG and its object-space lines to an
// SVG with the installed library (find_package(inkshade); see CMakeLists.txt here).
#include <cstdio>
#include <exception>
#include <string>

#include <inkshade/io.hpp>
#include <inkshade/line_drawing.hpp>
#include <inkshade/renderer.hpp>
#include <inkshade/style.hpp>

int main(int argc, char** argv) {
    const std::string stem = argc > 1 ? argv[1] : "teapot";
    try {
        const inkshade::Mesh mesh = inkshade::load_mesh("builtin:teapot");
        const inkshade::Style style = inkshade::load_style("anime");
        inkshade::RenderOptions options{.width = 512, .height = 512, .background = style.background};
        const inkshade::Camera camera = inkshade::frame_camera(mesh.bounds(), {}, 1.0f);
        inkshade::Light light = inkshade::default_light(mesh.bounds(), camera);
        inkshade::apply_style_light(style, light);

        inkshade::Renderer renderer;  // headless OpenGL 4.5 (EGL)
        renderer.set_mesh(mesh);
        inkshade::write_png(stem + ".png", renderer.render(camera, light, style.shading, style.lines, options));

        inkshade::LineExtractor extractor(mesh);  // contours, creases... as vector paths
        const auto drawing = extractor.draw(camera, 512, 512, inkshade::load_style("ink-vector").lines);
        inkshade::write_svg(stem + ".svg", drawing, style.background);
        std::printf("wrote %s.png and %s.svg with %zu line layers\n", stem.c_str(), stem.c_str(),
                    drawing.layers.size());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "render_teapot: %s\n", e.what());
        return 1;
    }
    return 0;
}
