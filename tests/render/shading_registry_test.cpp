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

TEST(ShadingRegistry, ShadowCastingModelsSwitchShadowsAtCompileTime) {
    for (const ShadingModel* m : shading_models())
        for (const ShadingInput& input : m->inputs) {
            if (input.kind != ShadingInputKind::ShadowMap) continue;
            EXPECT_EQ(input.when, "shadows") << m->name;
            const ParamSpec* p = m->param("shadows");
            ASSERT_NE(p, nullptr) << m->name;
            EXPECT_TRUE(p->compile_time && p->type == ParamType::Bool) << m->name;
        }
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
            EXPECT_NO_THROW(check_param_value(p, p.default_value)) << m->name << "." << p.name;
            if (p.compile_time) {  // becomes an integer #define
                EXPECT_TRUE(p.type == ParamType::Bool || p.type == ParamType::Choice || p.type == ParamType::Int)
                    << m->name << "." << p.name;
            }
            EXPECT_FALSE(p.doc.empty()) << m->name << "." << p.name;
        }
}

TEST(ParseParamValue, ChecksTypeAndRange) {
    ParamSpec f = float_param("shininess", 32, 1, 100, "exp");
    EXPECT_EQ(parse_param_value(f, "64"), ParamValue{64.0f});
    EXPECT_THROW(parse_param_value(f, "0.5"), InputError);
    EXPECT_THROW(parse_param_value(f, "abc"), InputError);
    EXPECT_THROW(parse_param_value(f, "inf"), InputError);
    ParamSpec i = int_param("bands", 3, 1, 8, "n");
    EXPECT_EQ(parse_param_value(i, "5"), ParamValue{5.0f});
    EXPECT_THROW(parse_param_value(i, "2.5"), InputError);
    ParamSpec b = bool_param("rim", false, "b");
    EXPECT_EQ(parse_param_value(b, "true"), ParamValue{1.0f});
    EXPECT_THROW(parse_param_value(b, "maybe"), InputError);
    ParamSpec c = color_param("specular", glm::vec3(1), "c");
    EXPECT_EQ(parse_param_value(c, "#ff0000"), (ParamValue{1, 0, 0}));
    EXPECT_THROW(parse_param_value(c, "2,0,0"), InputError);
}

TEST(ParseParamValue, ChoicesAndListsRoundTripThroughText) {
    ParamSpec d = choice_param("driver", {"ndotl", "half-lambert"}, 1, "d");
    EXPECT_EQ(parse_param_value(d, "ndotl"), ParamValue{0.0f});
    EXPECT_EQ(format_param_value(d, {1.0f}), "half-lambert");
    try {
        parse_param_value(d, "nope");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("ndotl, half-lambert"), std::string::npos);
    }
    ParamSpec l = list_param("thresholds", {0.8f, 0.6f}, 4, 0, 1, "t");
    ParamValue v = parse_param_value(l, "0.8,0.6,0.4,0.2");
    EXPECT_EQ(v, (ParamValue{0.8f, 0.6f, 0.4f, 0.2f}));
    EXPECT_EQ(parse_param_value(l, format_param_value(l, v)), v);
    EXPECT_THROW(parse_param_value(l, "0.1,0.2,0.3,0.4,0.5"), InputError);  // more than 4
    EXPECT_THROW(parse_param_value(l, "0.1,,0.3"), InputError);
    EXPECT_THROW(parse_param_value(l, "0.1,1.5"), InputError);
    EXPECT_THROW(check_param_value(l, {}), InputError);
}

}  // namespace
}  // namespace inkshade
