// The shading-model registry and parameter parsing (no GL needed).
#include <gtest/gtest.h>

#include "inkshade/error.hpp"
#include "inkshade/shading.hpp"

namespace inkshade {
namespace {

TEST(ShadingRegistry, HasClassicModelsAndDebugViews) {
    for (const char* name : {"flat", "gouraud", "lambert", "phong", "blinn-phong"})
        EXPECT_FALSE(shading_model(name).debug_view) << name;
    for (const char* name : {"normal", "view", "w", "ndotv"}) EXPECT_TRUE(shading_model(name).debug_view) << name;
}

TEST(ShadingRegistry, UnknownNameListsChoices) {
    try {
        shading_model("nope");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("blinn-phong"), std::string::npos);
    }
}

TEST(ShadingRegistry, DefaultsLieInTheirRanges) {
    for (const ShadingModel* m : shading_models())
        for (const ParamSpec& p : m->params) {
            int n = p.type == ParamType::Color ? 3 : 1;
            for (int i = 0; i < n; ++i) {
                EXPECT_GE(p.default_value[i], p.min) << m->name << "." << p.name;
                EXPECT_LE(p.default_value[i], p.max) << m->name << "." << p.name;
            }
            EXPECT_FALSE(p.doc.empty()) << m->name << "." << p.name;
        }
}

TEST(ParseParamValue, ChecksTypeAndRange) {
    ParamSpec f{"shininess", ParamType::Float, glm::vec4(32, 0, 0, 0), 1, 100, "exp"};
    EXPECT_EQ(parse_param_value(f, "64").x, 64.0f);
    EXPECT_THROW(parse_param_value(f, "0.5"), InputError);
    EXPECT_THROW(parse_param_value(f, "abc"), InputError);
    EXPECT_THROW(parse_param_value(f, "inf"), InputError);
    ParamSpec i{"bands", ParamType::Int, glm::vec4(3, 0, 0, 0), 1, 8, "n"};
    EXPECT_EQ(parse_param_value(i, "5").x, 5.0f);
    EXPECT_THROW(parse_param_value(i, "2.5"), InputError);
    ParamSpec b{"rim", ParamType::Bool, glm::vec4(0), 0, 1, "b"};
    EXPECT_EQ(parse_param_value(b, "true").x, 1.0f);
    EXPECT_THROW(parse_param_value(b, "maybe"), InputError);
    ParamSpec c{"specular", ParamType::Color, glm::vec4(1), 0, 1, "c"};
    EXPECT_EQ(parse_param_value(c, "#ff0000"), glm::vec4(1, 0, 0, 1));
    EXPECT_THROW(parse_param_value(c, "2,0,0"), InputError);
}

}  // namespace
}  // namespace inkshade
