// Several renderers in one process (a library user's, the Python module's): each keeps its own
// context, and one going away leaves the others working.
#include "render/render_fixture.hpp"

namespace inkshade::test {
namespace {

Image render_sphere(Renderer& renderer) {
    RenderOptions options{.width = 32, .height = 32, .samples = 1};
    Light light;
    light.position = {0, 0, 5};
    return renderer.render(ortho_camera(), light, ShadingSelection{}, options);
}

TEST(RendererLifetime, SecondRendererGoingAwayLeavesTheFirstWorking) {
    Renderer& first = shared_renderer();
    first.set_mesh(fine_sphere());
    const Image before = render_sphere(first);
    {
        Renderer second;
        second.set_mesh(builtin::sphere(8, 16));
        const Image other = render_sphere(second);
        EXPECT_NE(other.rgba, before.rgba);  // a coarse sphere: a different picture
    }
    // The shared EGL display stays initialised while a renderer still uses it.
    EXPECT_EQ(first.gl_renderer().empty(), false);
    const Image after = render_sphere(first);
    EXPECT_EQ(after.rgba, before.rgba);
}

}  // namespace
}  // namespace inkshade::test
