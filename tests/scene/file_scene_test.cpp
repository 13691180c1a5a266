// Scene::apply_file_scene: a model file's camera as camera options (`--camera`), the image's
// aspect from it, its first light in the units of the style's shading model (`--lights file`),
// and the one-line errors naming the option.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "inkshade/error.hpp"
#include "inkshade/scene.hpp"

namespace inkshade {
namespace {

// A 2 x 2 x 2 cube's worth of bounds (two triangles spanning it) with two cameras and lights.
Mesh model_with_cameras_and_lights() {
    Mesh m;
    m.positions = {{-1, -1, -1}, {1, -1, -1}, {1, 1, 1}, {-1, 1, 1}};
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    FileCamera main;
    main.name = "Main";
    main.yfov_degrees = 40.0f;
    main.aspect_ratio = 1.5f;
    main.znear = 0.25f;
    main.zfar = 40.0f;
    main.placement = {{0, 0, 8}, {0, 0, -1}, {0, 1, 0}};
    FileCamera top;
    top.name = "Top";
    top.orthographic = true;
    top.xmag = 1.0f;
    top.ymag = 2.0f;
    top.znear = 0.0f;
    top.zfar = 30.0f;
    top.placement = {{0, 10, 0}, {0, -1, 0}, {0, 0, -1}};
    m.cameras = {main, top};
    FileLight sun;
    sun.name = "Sun";
    sun.color = {1.0f, 0.5f, 0.25f};
    sun.intensity = 3.0f;
    sun.placement.forward = {0, -1, 0};
    FileLight spot;
    spot.name = "Spot";
    spot.type = FileLightType::Spot;
    spot.intensity = 50.0f;
    spot.range = 12.0f;
    spot.inner_cone_angle = 0.25f;
    spot.outer_cone_angle = 0.5f;
    spot.placement = {{0, 3, 0}, {0, -1, 0}, {0, 0, 1}};
    m.lights = {sun, spot};
    return m;
}

Scene scene_of(const std::function<void(SceneRequest&)>& edit) {
    SceneRequest r;
    r.model = "model.gltf";
    edit(r);
    return make_scene(r);
}

std::string apply_error(Scene s, const Mesh& m) {
    try {
        s.apply_file_scene(m);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

std::string request_error(const std::function<void(SceneRequest&)>& edit) {
    try {
        scene_of(edit);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(FileScene, CameraBecomesTheCameraOptionsFlagsWouldGive) {
    const Mesh m = model_with_cameras_and_lights();
    Scene s = scene_of([](SceneRequest& r) { r.file_camera = "Main"; });
    EXPECT_TRUE(s.apply_file_scene(m).empty());
    const CameraOptions& o = s.camera;
    ASSERT_TRUE(o.eye && o.target && o.up && o.near_plane && o.far_plane);
    EXPECT_EQ(*o.eye, glm::vec3(0, 0, 8));
    EXPECT_EQ(*o.target, glm::vec3(0, 0, 0));  // the view axis' point nearest the model's centre
    EXPECT_EQ(*o.up, glm::vec3(0, 1, 0));
    EXPECT_FLOAT_EQ(o.fov_degrees, 40.0f);
    EXPECT_FALSE(o.orthographic);
    EXPECT_FLOAT_EQ(*o.near_plane, 0.25f);
    EXPECT_FLOAT_EQ(*o.far_plane, 40.0f);
    EXPECT_EQ(s.options.width, 1024);  // size_from_camera is off: the size stays
    EXPECT_EQ(s.options.height, 1024);

    SceneRequest flags;
    flags.model = "model.gltf";
    flags.camera.eye = glm::vec3(0, 0, 8);
    flags.camera.target = glm::vec3(0);
    flags.camera.up = glm::vec3(0, 1, 0);
    flags.camera.fov_degrees = 40.0f;
    flags.camera.near_plane = 0.25f;
    flags.camera.far_plane = 40.0f;
    const Camera a = s.frame(m.bounds()), b = make_scene(flags).frame(m.bounds());
    EXPECT_EQ(a.view(), b.view());
    EXPECT_EQ(a.projection(1.0f), b.projection(1.0f));
}

TEST(FileScene, OrthographicCameraByIndexTakesItsAspectWithoutASize) {
    const Mesh m = model_with_cameras_and_lights();
    Scene s = scene_of([](SceneRequest& r) {
        r.file_camera = "1";
        r.size_from_camera = true;
        r.size = {600, 400};
    });
    s.apply_file_scene(m);
    EXPECT_TRUE(s.camera.orthographic);
    EXPECT_FLOAT_EQ(*s.camera.ortho_height, 4.0f);  // 2 ymag
    EXPECT_FLOAT_EQ(*s.camera.near_plane, 0.0f);
    EXPECT_EQ(*s.camera.up, glm::vec3(0, 0, -1));
    // xmag / ymag = 0.5: the longer side keeps 600.
    EXPECT_EQ(s.options.width, 300);
    EXPECT_EQ(s.options.height, 600);
    const Camera c = s.frame(m.bounds());
    EXPECT_FLOAT_EQ(c.ortho_height, 4.0f);
    EXPECT_EQ(c.eye, glm::vec3(0, 10, 0));

    Scene wide = scene_of([](SceneRequest& r) {
        r.file_camera = "main";  // names match ignoring case when none matches exactly
        r.size_from_camera = true;
    });
    wide.apply_file_scene(m);
    EXPECT_EQ(wide.options.width, 1024);
    EXPECT_EQ(wide.options.height, 683);  // 1024 / 1.5, rounded
}

TEST(FileScene, UpAxisLeavesTheFileCameraAsItIs) {
    const Mesh m = model_with_cameras_and_lights();
    Scene y = scene_of([](SceneRequest& r) { r.file_camera = "Main"; });
    Scene z = scene_of([](SceneRequest& r) {
        r.file_camera = "Main";
        r.camera.up_axis = UpAxis::PosZ;
    });
    y.apply_file_scene(m);
    z.apply_file_scene(m);
    const Camera a = y.frame(m.bounds()), b = z.frame(m.bounds());
    EXPECT_EQ(a.eye, b.eye);
    EXPECT_EQ(a.target, b.target);
    EXPECT_EQ(a.up, b.up);
}

TEST(FileScene, MissingCamerasAndLightsAreOneLineErrors) {
    const Mesh m = model_with_cameras_and_lights();
    EXPECT_EQ(apply_error(scene_of([](SceneRequest& r) { r.file_camera = "Mian"; }), m),
              "--camera: model.gltf has no camera 'Mian' (did you mean 'Main'?); its cameras: 0 'Main', 1 'Top'");
    EXPECT_EQ(apply_error(scene_of([](SceneRequest& r) { r.file_camera = "2"; }), m),
              "--camera: model.gltf has no camera 2; its cameras: 0 'Main', 1 'Top'");
    Mesh bare = m;
    bare.cameras.clear();
    bare.lights.clear();
    EXPECT_EQ(apply_error(scene_of([](SceneRequest& r) { r.file_camera = "0"; }), bare),
              "--camera: model.gltf has no cameras");
    EXPECT_EQ(apply_error(scene_of([](SceneRequest& r) {
                              r.lights = LightSource::File;
                              r.names = OptionNames::Keywords;
                          }),
                          bare),
              "lights file: model.gltf has no lights (glTF KHR_lights_punctual)");
}

TEST(FileScene, CameraAndLightOptionsBesideThemAreRefused) {
    EXPECT_EQ(request_error([](SceneRequest& r) {
                  r.file_camera = "Main";
                  r.camera.eye = glm::vec3(1.0f);
              }),
              "--camera and --eye are alternatives: the file's camera places and projects the view");
    EXPECT_EQ(request_error([](SceneRequest& r) {
                  r.file_camera = "Main";
                  r.camera.fov_degrees = 50.0f;
              }),
              "--camera and --fov are alternatives: the file's camera places and projects the view");
    EXPECT_EQ(request_error([](SceneRequest& r) {
                  r.lights = LightSource::File;
                  r.light_position = glm::vec3(1.0f);
                  r.names = OptionNames::Keywords;
              }),
              "lights file and light_pos are alternatives: the file's light is placed by its node");
    EXPECT_EQ(request_error([](SceneRequest& r) {
                  r.file_camera = "Main";
                  r.camera.up_axis = UpAxis::PosZ;  // the file's frame is the model's: allowed
                  r.lights = LightSource::File;
                  r.light_color = glm::vec3(0.5f);  // the strength of a display model's light
              }),
              "");
}

TEST(FileScene, DisplayModelsTakeTheLightsPlaceAndTintAtTheStylesStrength) {
    const Mesh m = model_with_cameras_and_lights();
    Scene s = scene_of([](SceneRequest& r) {
        r.lights = LightSource::File;
        r.shading = "lambert";
    });
    const std::vector<std::string> warnings = s.apply_file_scene(m);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0], "model.gltf: 2 lights; Inkshade shades with one, the first: 'Sun' (directional)");
    const BoundingBox box = m.bounds();
    const Light l = s.light(box, s.frame(box));
    EXPECT_EQ(l.type, LightType::Directional);
    EXPECT_EQ(l.target, box.center());
    const glm::vec3 to_light = glm::normalize(l.position - l.target);
    EXPECT_NEAR(to_light.y, 1.0f, 1e-6f);                                // it shines down
    EXPECT_EQ(l.color, glm::vec3(0.9f) * glm::vec3(1.0f, 0.5f, 0.25f));  // default strength 0.9, the file's tint
    EXPECT_FALSE(l.physical_falloff);
    EXPECT_EQ(s.shading().params, s.style.shading.params);  // no light parameters to set
}

TEST(FileScene, ThreejsModelsTakeIntensityRangeAndConeAsGltfLoaderDoes) {
    Mesh m = model_with_cameras_and_lights();
    std::swap(m.lights[0], m.lights[1]);  // the spot first
    Scene s = scene_of([](SceneRequest& r) {
        r.lights = LightSource::File;
        r.shading = "threejs-lambert";
    });
    s.apply_file_scene(m);
    const BoundingBox box = m.bounds();
    const Light l = s.light(box, s.frame(box));
    EXPECT_EQ(l.type, LightType::Spot);
    EXPECT_EQ(l.position, glm::vec3(0, 3, 0));
    EXPECT_EQ(l.target, glm::vec3(0, 2, 0));  // one unit down its axis
    EXPECT_EQ(l.color, glm::vec3(1.0f));
    EXPECT_FLOAT_EQ(l.cos_inner, std::cos(0.25f));
    EXPECT_FLOAT_EQ(l.cos_outer, std::cos(0.5f));
    const ShadingSelection shading = s.shading();
    EXPECT_EQ(shading.params.at("light-intensity"), ParamValue{50.0f});
    EXPECT_EQ(shading.params.at("light-decay"), ParamValue{2.0f});
    EXPECT_EQ(shading.params.at("light-distance"), ParamValue{12.0f});
    EXPECT_FALSE(s.style.shading.params.count("light-intensity"));  // the style itself stays
}

TEST(FileScene, MtoonInThreejsConventionTakesPhysicalUnits) {
    Mesh m = model_with_cameras_and_lights();
    std::swap(m.lights[0], m.lights[1]);
    Scene s = scene_of([](SceneRequest& r) {
        r.lights = LightSource::File;
        r.shading = "mtoon";
        r.sets = {"convention=threejs"};
    });
    s.apply_file_scene(m);
    const BoundingBox box = m.bounds();
    const Light l = s.light(box, s.frame(box));
    EXPECT_EQ(l.color, glm::vec3(1.0f));  // the file's colour, its intensity apart
    EXPECT_FLOAT_EQ(l.intensity, 50.0f);
    EXPECT_FLOAT_EQ(l.decay, 2.0f);  // GLTFLoader's
    EXPECT_TRUE(l.physical_falloff);
    EXPECT_FLOAT_EQ(l.range, 12.0f);

    Scene seeds = scene_of([](SceneRequest& r) {
        r.lights = LightSource::File;
        r.style = "mtoon";  // the preset: convention seeds
    });
    seeds.apply_file_scene(m);
    const Light d = seeds.light(box, seeds.frame(box));
    // The default convention shades on the display's scale: the style's light colour (0.85 for
    // the mtoon style), the spot's white tint.
    ASSERT_TRUE(seeds.style.light_color);
    EXPECT_EQ(d.color, *seeds.style.light_color);
    EXPECT_FALSE(d.physical_falloff);
}

}  // namespace
}  // namespace inkshade
