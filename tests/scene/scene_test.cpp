// make_scene: one check of every request value, the same messages for every front end, the
// style and the line drawing's line types resolved as `inkshade render` and `lines` use them.
#include <gtest/gtest.h>

#include <functional>

#include "inkshade/error.hpp"
#include "inkshade/scene.hpp"

namespace inkshade {
namespace {

// The message make_scene throws for a request changed by `edit`, or "" when it accepts it.
std::string error_of(const std::function<void(SceneRequest&)>& edit, OptionNames names = OptionNames::Cli) {
    SceneRequest r;
    r.model = "builtin:sphere";
    r.names = names;
    edit(r);
    try {
        make_scene(r);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

std::vector<std::string> types_of(const std::vector<LineSettings>& lines) {
    std::vector<std::string> out;
    for (const LineSettings& l : lines) out.push_back(l.type);
    return out;
}

TEST(Scene, BadValuesNameTheOptionAsTheFrontEndSpellsIt) {
    EXPECT_EQ(error_of([](SceneRequest& r) { r.camera.fov_degrees = 0.0f; }), "--fov: expected degrees in (0, 180)");
    EXPECT_EQ(error_of([](SceneRequest& r) { r.camera.fov_degrees = 180.0f; }, OptionNames::Keywords),
              "fov: expected degrees in (0, 180)");
    EXPECT_EQ(error_of([](SceneRequest& r) { r.light_position = glm::vec3(NAN); }, OptionNames::Keywords),
              "light_pos: must be finite");
    EXPECT_EQ(error_of([](SceneRequest& r) { r.size = {0, 8}; }), "--size: each side must be in 1..16384, got 0x8");
    EXPECT_EQ(error_of([](SceneRequest& r) { r.samples = 17; }), "--samples: expected 1..16, got 17");
    EXPECT_EQ(error_of([](SceneRequest& r) { r.camera.distance = -1.0f; }), "--distance: must be a positive number");
    EXPECT_EQ(error_of([](SceneRequest& r) { r.camera.up = glm::vec3(0.0f); }), "--up: must not be zero");
    EXPECT_EQ(error_of([](SceneRequest& r) { r.camera.near_plane = 0.0f; }), "--near: must be a positive number");
    EXPECT_EQ(error_of([](SceneRequest& r) { r.camera.orthographic = true, r.camera.near_plane = -1.0f; }), "");
    EXPECT_EQ(error_of([](SceneRequest& r) { r.camera.near_plane = 2.0f, r.camera.far_plane = 1.0f; }),
              "--far: must be greater than --near");
    EXPECT_EQ(error_of([](SceneRequest& r) { r.camera.ortho_height = 0.0f; }, OptionNames::Keywords),
              "ortho_height: must be a positive number");
    EXPECT_EQ(error_of([](SceneRequest& r) { r.light_color = glm::vec3(2.0f); }),
              "--light-color: components must be in [0, 1]");
    EXPECT_EQ(error_of([](SceneRequest& r) { r.style = "cel", r.shading = "phong"; }),
              "--style and --shading are alternatives: use one (a style names its shading model)");
    EXPECT_EQ(error_of([](SceneRequest& r) { r.outputs = {.image = false, .line_drawing = false}; }),
              "the request asks for no output");
}

TEST(Scene, OverrideErrorsNameTheOverride) {
    // cel draws no hull: the override is refused, as `inkshade render --style cel --set ...` does.
    EXPECT_EQ(error_of([](SceneRequest& r) { r.style = "cel", r.sets = {"hull.width=2"}; }, OptionNames::Keywords)
                  .rfind("set hull.width=2: ", 0),
              0u);
    EXPECT_EQ(error_of([](SceneRequest& r) {
                  r.style = "anime", r.sets = {"hull.width=2", "cel.shade-color=0.2,0.1,0.3"};
              }),
              "");
    EXPECT_EQ(error_of([](SceneRequest& r) {
                  r.style = "lambert", r.sets = {"shininess=3"};
              }).rfind("--set shininess=3: ", 0),
              0u);
}

TEST(Scene, ImageStyleHasOverridesAndColourOptions) {
    SceneRequest r;
    r.style = "anime";
    r.sets = {"hull.width=7"};
    r.background = glm::vec4(0.0f);
    r.base_color = glm::vec3(0.5f);
    r.size = {96, 64};
    r.samples = 2;
    r.srgb = true;
    const Scene s = make_scene(r);
    EXPECT_EQ(s.style.name, "anime");
    ASSERT_EQ(s.style.lines.at(0).type, "hull");
    EXPECT_EQ(s.style.lines.at(0).params.at("width"), ParamValue{7.0f});
    EXPECT_EQ(s.style.shading.base_color, glm::vec3(0.5f));
    EXPECT_EQ(s.options.background, glm::vec4(0.0f));
    EXPECT_EQ(s.options.width, 96);
    EXPECT_EQ(s.options.height, 64);
    EXPECT_EQ(s.options.samples, 2);
    EXPECT_TRUE(s.options.srgb_output);
    EXPECT_TRUE(s.vector_lines.empty());  // no line drawing asked for
}

TEST(Scene, ShadingGivesTheModelWithItsDefaults) {
    SceneRequest r;
    r.shading = "phong";
    const Scene s = make_scene(r);
    EXPECT_EQ(s.style.shading.model, "phong");
    EXPECT_TRUE(s.style.shading.params.empty());
    EXPECT_NE(error_of([](SceneRequest& q) { q.shading = "no-such-model"; }).find("no-such-model"), std::string::npos);
}

// `--shading mtoon` is the model with its defaults (three-vrm MToonMaterial's), not the
// built-in `mtoon` style, which shares the name and picks its own colours and convention.
TEST(Scene, ShadingNamesTheModelEvenWhereAPresetHasItsName) {
    SceneRequest r;
    r.shading = "mtoon";
    const Scene model = make_scene(r);
    EXPECT_EQ(model.style.shading.model, "mtoon");
    EXPECT_TRUE(model.style.shading.params.empty());
    EXPECT_FALSE(model.style.light_color);
    EXPECT_EQ(model.style.shading.base_color, glm::vec3(1.0f));
    SceneRequest preset;
    preset.style = "mtoon";
    const Scene styled = make_scene(preset);
    EXPECT_FALSE(styled.style.shading.params.empty());  // the preset keeps its look
    EXPECT_TRUE(styled.style.light_color);
}

// --light-intensity, --light-decay, --light-distance: a model's light parameters where it has
// them (threejs-*), else the style's [light] values, which the scene's light carries; checked
// once with the option's name.
TEST(Scene, LightValuesReachTheModelOrTheLight) {
    const BoundingBox box{glm::vec3(-1.0f), glm::vec3(1.0f)};
    SceneRequest r;
    r.shading = "lambert";
    r.light_intensity = 3.0f;
    r.light_decay = 1.0f;
    r.light_distance = 7.0f;
    const Scene lambert = make_scene(r);
    EXPECT_EQ(lambert.style.light_intensity, 3.0f);
    const Light l = lambert.light(box, lambert.frame(box));
    EXPECT_FLOAT_EQ(l.intensity, 3.0f);
    EXPECT_FLOAT_EQ(l.decay, 1.0f);
    EXPECT_FLOAT_EQ(l.range, 7.0f);
    EXPECT_FALSE(l.physical_falloff);  // directional, display units
    r.shading = "threejs-phong";
    const Scene three = make_scene(r);
    EXPECT_EQ(three.style.shading.params.at("light-intensity"), ParamValue{3.0f});
    EXPECT_EQ(three.style.shading.params.at("light-decay"), ParamValue{1.0f});
    EXPECT_EQ(three.style.shading.params.at("light-distance"), ParamValue{7.0f});
    EXPECT_FLOAT_EQ(three.light(box, three.frame(box)).intensity, 1.0f);  // not twice
    r.shading = "mtoon";
    r.light_type = LightType::Point;
    const Scene mtoon = make_scene(r);
    EXPECT_TRUE(mtoon.light(box, mtoon.frame(box)).physical_falloff);  // its threejs convention
    r.sets = {"convention=seeds"};
    EXPECT_FALSE(make_scene(r).light(box, make_scene(r).frame(box)).physical_falloff);

    EXPECT_EQ(error_of([](SceneRequest& q) { q.light_intensity = -1.0f; }),
              "--light-intensity: expected a number in [0, 1e+06]");
    EXPECT_EQ(error_of([](SceneRequest& q) { q.light_decay = NAN; }, OptionNames::Keywords),
              "light_decay: expected a number in [0, 16]");
    EXPECT_NE(error_of([](SceneRequest& q) {
                  q.shading = "threejs-lambert";
                  q.light_distance = -2.0f;
              }).rfind("--light-distance: ", 0),
              std::string::npos);
}

TEST(Scene, LineDrawingTakesTheStylesObjectSpaceTypesElseTheDefaultList) {
    SceneRequest r;
    r.outputs = {.image = false, .line_drawing = true};
    r.style = "anime";  // hull, rim contour and image-space suggestive contours only
    EXPECT_EQ(types_of(make_scene(r).vector_lines), default_vector_lines());
    r.style = "ink-vector";
    const Scene ink = make_scene(r);
    EXPECT_EQ(types_of(ink.vector_lines), (std::vector<std::string>{"contour", "suggestive", "crease", "border"}));
    EXPECT_EQ(ink.vector_lines.at(0).params.at("width"), ParamValue{2.0f});  // the style's parameters
    EXPECT_EQ(ink.style.lines.size(), ink.vector_lines.size());
}

TEST(Scene, LinesOptionSelectsTypesAndOverridesReachThem) {
    SceneRequest r;
    r.outputs = {.image = false, .line_drawing = true};
    r.vector_lines = std::vector<std::string>{"ridge", "contour"};
    r.hidden = true;
    r.sets = {"ridge.width=3", "contour.hidden=0"};
    const Scene s = make_scene(r);
    ASSERT_EQ(types_of(s.vector_lines), (std::vector<std::string>{"ridge", "contour"}));
    EXPECT_EQ(s.vector_lines[0].params.at("width"), ParamValue{3.0f});
    EXPECT_EQ(s.vector_lines[0].params.at("hidden"), ParamValue{1.0f});
    EXPECT_EQ(s.vector_lines[1].params.at("hidden"), ParamValue{0.0f});  // --set wins over hidden

    auto lines_error = [](std::vector<std::string> types) {
        return error_of([&](SceneRequest& q) {
            q.outputs = {.image = false, .line_drawing = true};
            q.vector_lines = types;
        });
    };
    EXPECT_EQ(lines_error({"hull"}).rfind("--lines: 'hull' is drawn in the image", 0), 0u);
    EXPECT_EQ(lines_error({"contour", "contour"}), "--lines: 'contour' is listed twice");
    EXPECT_EQ(lines_error({}), "--lines: no line type given");
    EXPECT_EQ(lines_error({""}), "--lines: empty line type name");
    EXPECT_NE(lines_error({"nope"}).find("unknown line type 'nope'"), std::string::npos);
    EXPECT_NE(lines_error({"contuor"}).find("(did you mean 'contour'?)"), std::string::npos);
    EXPECT_EQ(lines_error({"contour", "Contour"}), "--lines: 'contour' is listed twice");
}

TEST(Scene, NamesIgnoreCase) {
    SceneRequest r;
    r.outputs = {.image = false, .line_drawing = true};
    r.vector_lines = std::vector<std::string>{"Ridge", "CONTOUR"};
    EXPECT_EQ(types_of(make_scene(r).vector_lines), (std::vector<std::string>{"ridge", "contour"}));
    SceneRequest shaded;
    shaded.shading = "Gooch";
    EXPECT_EQ(make_scene(shaded).style.shading.model, "gooch");
    SceneRequest styled;
    styled.style = "INK";
    EXPECT_EQ(make_scene(styled).style.name, "ink");
}

TEST(Scene, StyleDataGivesItsLightsToANamedStyle) {
    Style data = load_style("threejs-lambert");
    data.light_color = glm::vec3(0.25f);
    data.ambient = glm::vec3(0.5f);
    data.background = glm::vec4(0.1f, 0.2f, 0.3f, 1.0f);
    data.shading.params["light-intensity"] = {3.0f};
    SceneRequest r;
    r.style_data = data;
    EXPECT_EQ(make_scene(r).style.shading.params.at("light-intensity"), ParamValue{3.0f});  // the data itself
    r.shading = "threejs-phong";
    const Scene s = make_scene(r);
    EXPECT_EQ(s.style.shading.model, "threejs-phong");
    EXPECT_EQ(s.style.light_color, glm::vec3(0.25f));
    EXPECT_EQ(s.style.ambient, glm::vec3(0.5f));
    EXPECT_EQ(s.options.background, data.background);
    EXPECT_EQ(s.style.shading.params.at("light-intensity"), ParamValue{3.0f});
}

TEST(Scene, CameraAndLightAreTheDefaultsWithTheRequestsValues) {
    const BoundingBox box{glm::vec3(-1.0f), glm::vec3(1.0f)};
    SceneRequest r;
    r.size = {200, 100};
    r.camera.azimuth_degrees = 60.0f;
    const Scene s = make_scene(r);
    const Camera cam = s.frame(box);
    const Camera expected = frame_camera(box, r.camera, 2.0f);
    EXPECT_EQ(cam.eye, expected.eye);
    EXPECT_EQ(cam.near_plane, expected.near_plane);
    // A mesh is framed by its vertices: a tetrahedron inside the box comes closer than its box.
    Mesh tetra;
    tetra.positions = {{-1, -1, -1}, {1, 1, -1}, {1, -1, 1}, {-1, 1, 1}};
    tetra.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}};
    ASSERT_EQ(tetra.bounds().min, box.min);
    ASSERT_EQ(tetra.bounds().max, box.max);
    const Camera by_vertices = s.frame(tetra);
    const Camera want_vertices = frame_camera(box, r.camera, 2.0f, tetra.positions);
    EXPECT_EQ(by_vertices.eye, want_vertices.eye);
    EXPECT_LT(glm::length(by_vertices.eye - by_vertices.target), glm::length(cam.eye - cam.target));
    Light want = default_light(box, cam);
    apply_style_light(s.style, want);
    const Light got = s.light(box, cam);
    EXPECT_EQ(got.position, want.position);
    EXPECT_EQ(got.color, want.color);
    EXPECT_EQ(got.type, LightType::Directional);

    r.light_type = LightType::Point;
    r.light_position = glm::vec3(1.0f, 2.0f, 3.0f);
    r.light_target = glm::vec3(0.5f);
    r.light_color = glm::vec3(0.25f);
    const Scene p = make_scene(r);
    const Light l = p.light(box, cam);
    EXPECT_EQ(l.type, LightType::Point);
    EXPECT_EQ(l.position, glm::vec3(1.0f, 2.0f, 3.0f));
    EXPECT_EQ(l.target, glm::vec3(0.5f));
    EXPECT_EQ(l.color, glm::vec3(0.25f));

    r.light_type = LightType::Directional;
    r.light_position = r.light_target = glm::vec3(0.0f);
    EXPECT_THROW(
        {
            try {
                make_scene(r).light(box, cam);
            } catch (const InputError& e) {
                EXPECT_STREQ(e.what(),
                             "--light-pos: equals the light's target, so a directional light has no direction");
                throw;
            }
        },
        InputError);
}

TEST(Scene, OptionTextParsesOrNamesTheOption) {
    EXPECT_EQ(parse_image_size("--size", "96x64"), glm::ivec2(96, 64));
    EXPECT_EQ(parse_vec3("--eye", "1,-2,3.5"), glm::vec3(1.0f, -2.0f, 3.5f));
    EXPECT_EQ(parse_color("--background", "transparent").a, 0.0f);
    EXPECT_EQ(parse_light_type("light_type", "point"), LightType::Point);
    auto message = [](auto&& f) {
        try {
            f();
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(message([] { parse_image_size("--size", "big"); }),
              "--size: expected WxH with each side in 1..16384, got 'big'");
    EXPECT_EQ(message([] { parse_vec3("--eye", "1,2"); }), "--eye: expected x,y,z but got '1,2'");
    EXPECT_EQ(message([] { parse_vec3("--eye", "1,2,inf"); }), "--eye: expected x,y,z but got '1,2,inf'");
    EXPECT_EQ(message([] { parse_light_type("--light-type", "spot"); }),
              "--light-type: expected directional or point, got 'spot'");
    EXPECT_EQ(message([] { parse_color("--base-color", "nope"); }).rfind("--base-color: ", 0), 0u);
}

TEST(Scene, AddedLinesJoinTheImageStyleBeforeTheOverrides) {
    SceneRequest r;
    r.style = "mtoon";  // draws no lines of its own
    r.added_lines = {"hull", "Contour"};
    r.sets = {"hull.width=5"};
    const Scene s = make_scene(r);
    ASSERT_EQ(types_of(s.style.lines), (std::vector<std::string>{"hull", "contour"}));
    EXPECT_EQ(s.style.lines[0].params.at("width"), ParamValue{5.0f});
    // A type the style draws keeps its parameters and its place.
    r.style = "ink-vector";
    r.added_lines = {"suggestive", "hull"};
    r.sets = {};
    const Scene ink = make_scene(r);
    EXPECT_EQ(types_of(ink.style.lines),
              (std::vector<std::string>{"contour", "suggestive", "crease", "border", "hull"}));
    EXPECT_EQ(ink.style.lines[1].params.at("width"), ParamValue{1.5f});
    EXPECT_EQ(error_of([](SceneRequest& q) { q.added_lines = {"hull", "hull"}; }), "--lines: 'hull' is listed twice");
    EXPECT_EQ(error_of(
                  [](SceneRequest& q) {
        q.added_lines = {"hull", "hull"};
                  },
                  OptionNames::Keywords),
              "lines: 'hull' is listed twice");
    EXPECT_NE(error_of([](SceneRequest& q) { q.added_lines = {"hul"}; }).find("did you mean 'hull'?"),
              std::string::npos);
}

}  // namespace
}  // namespace inkshade
