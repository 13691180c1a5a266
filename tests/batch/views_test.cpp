// View lists of batch jobs: orbit sets, turntables, single views and explicit cameras, with
// stable names; model names in stems.
#include <gtest/gtest.h>

#include "inkshade/batch.hpp"
#include "inkshade/error.hpp"

namespace inkshade {
namespace {

std::vector<std::string> names(const std::vector<BatchView>& views) {
    std::vector<std::string> n;
    for (const BatchView& v : views) n.push_back(v.name);
    return n;
}

TEST(BatchViews, Orbit8x3IsEightAzimuthsAtThreeElevations) {
    const auto views = parse_views("orbit8x3");
    ASSERT_EQ(views.size(), 24u);
    for (int k = 0; k < 3; ++k)
        for (int i = 0; i < 8; ++i) {
            const BatchView& v = views[size_t(k * 8 + i)];
            EXPECT_FLOAT_EQ(v.camera.azimuth_degrees.value(), 45.0f * float(i));
            EXPECT_FLOAT_EQ(v.camera.elevation_degrees.value(), 30.0f * float(k));
            EXPECT_FALSE(v.camera.distance.has_value());
            EXPECT_FALSE(v.camera.eye.has_value());
        }
    EXPECT_EQ(views[0].name, "az000_el00");
    EXPECT_EQ(views[9].name, "az045_el30");
    EXPECT_EQ(views[23].name, "az315_el60");
}

TEST(BatchViews, TurntableSpacesAzimuthsEvenlyAtOneElevation) {
    EXPECT_EQ(names(parse_views("turntable:4")),
              (std::vector<std::string>{"az000_el20", "az090_el20", "az180_el20", "az270_el20"}));
    EXPECT_EQ(names(parse_views("turntable:3:-12.5")),
              (std::vector<std::string>{"az000_el-12.5", "az120_el-12.5", "az240_el-12.5"}));
    const auto seven = parse_views("turntable:7");
    EXPECT_EQ(seven[1].name, "az051.429_el20");  // 360/7 to three decimals in the name only
    EXPECT_FLOAT_EQ(seven[1].camera.azimuth_degrees.value(), 360.0f / 7.0f);
}

TEST(BatchViews, ListsMixItemsAndExplicitCameras) {
    const auto views = parse_views(" 5:0, 22.5:-15:3 ; eye=0,1,5 up=0,0,1; eye=4,0,0 target=1,0,0 name=side;orbit2x1");
    EXPECT_EQ(names(views),
              (std::vector<std::string>{"az005_el00", "az022.5_el-15_d3", "cam1", "side", "az000_el00", "az180_el00"}));
    EXPECT_FLOAT_EQ(views[1].camera.distance.value(), 3.0f);
    EXPECT_EQ(views[2].camera.eye.value(), glm::vec3(0, 1, 5));
    EXPECT_EQ(views[2].camera.up.value(), glm::vec3(0, 0, 1));
    EXPECT_FALSE(views[2].camera.target.has_value());  // auto: the model centre
    EXPECT_EQ(views[3].camera.target.value(), glm::vec3(1, 0, 0));
}

TEST(BatchViews, FileCamerasAreNamedForTheirCameras) {
    const auto views = parse_views("camera=Main, 35:20; camera=0;camera=Side cam/2");
    EXPECT_EQ(names(views), (std::vector<std::string>{"camera-Main", "az035_el20", "camera-0", "camera-Side_cam_2"}));
    EXPECT_EQ(views[0].file_camera, "Main");
    EXPECT_FALSE(views[0].camera.eye.has_value());
    EXPECT_EQ(views[1].file_camera, "");
    EXPECT_EQ(views[3].file_camera, "Side cam/2");
    EXPECT_THROW(parse_views("camera="), InputError);
    EXPECT_THROW(parse_views("camera=a,camera=a"), InputError);  // one name twice
}

TEST(BatchViews, BadListsAreOneLineInputErrors) {
    for (const std::string bad : {"",
                                  " ; ",
                                  "orbit",
                                  "orbit8",
                                  "orbit0x3",
                                  "orbit8x91",
                                  "orbit8x3x",
                                  "turntable",
                                  "turntable:0",
                                  "turntable:4:95",
                                  "turntable:x",
                                  "1:2:3:4",
                                  "10",
                                  "a:b",
                                  "0:91",
                                  "0:0:0",
                                  "0:0:-1",
                                  "0::0",
                                  "nan:0",
                                  "eye=1,2",
                                  "eye=1,2,3 target=1,2,3",
                                  "eye=0,0,1 up=0,0,0",
                                  "eye=0,0,1 zoom=2",
                                  "eye=0,0,1 eye=0,0,2",
                                  "target=0,0,0",
                                  "0:0,eye=0,0,1",
                                  "eye=0,0,1 name=a/b",
                                  "0:0,0:0",
                                  "eye=0,0,1 name=x;eye=1,0,0 name=x"}) {
        try {
            parse_views(bad);
            ADD_FAILURE() << "accepted '" << bad << "'";
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
        }
    }
}

TEST(BatchViews, ModelNamesComeFromFileNamesAndBuiltinSpecs) {
    EXPECT_EQ(model_name("data/chairs/chair_01.obj"), "chair_01");
    EXPECT_EQ(model_name("scan.tar.ply"), "scan.tar");
    EXPECT_EQ(model_name("builtin:teapot"), "teapot");
    EXPECT_EQ(model_name("builtin:torus:major=1,minor=0.3"), "torus-major=1-minor=0.3");
    EXPECT_EQ(model_name("my model (1).stl"), "my-model--1-");
}

}  // namespace
}  // namespace inkshade
