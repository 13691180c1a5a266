// The inputs shading models declare (ShadingModel::inputs) and what the renderer makes of a
// declaration alone: vertex attributes at locations from 6 on in declaration order, their GLSL
// generated from the same declaration, and the parameters that switch inputs on.
#include <gtest/gtest.h>

#include <algorithm>

#include "inkshade/error.hpp"
#include "inkshade/shading.hpp"
#include "render/shading_inputs.hpp"

namespace inkshade {
namespace {

using render::declared_attributes;

TEST(ShadingInputs, EveryDeclarationNamesAProviderAndAParameterThatExist) {
    for (const ShadingModel* m : shading_models())
        for (const ShadingInput& input : m->inputs) {
            if (input.kind == ShadingInputKind::VertexAttribute) {
                EXPECT_NO_THROW(render::vertex_attribute_provider(input.name)) << m->name;
            }
            if (input.when.empty()) continue;
            const ParamSpec* p = m->param(input.when);
            ASSERT_NE(p, nullptr) << m->name << ": " << input.when;
            if (input.when_choice.empty())
                EXPECT_EQ(p->type, ParamType::Bool) << m->name << ": " << input.when;
            else
                EXPECT_NE(std::find(p->choices.begin(), p->choices.end(), input.when_choice), p->choices.end())
                    << m->name << ": " << input.when;
        }
}

TEST(ShadingInputs, ExaggeratedDeclaresItsScaleNormalsAndNothingElse) {
    const ShadingModel& m = shading_model("exaggerated");
    ASSERT_EQ(m.inputs.size(), 1u);
    EXPECT_EQ(m.inputs[0].kind, ShadingInputKind::VertexAttribute);
    EXPECT_EQ(m.inputs[0].name, "multiscale-normals");
    // scales + 1 vec3 normals from location 6, declared in both stages from that alone.
    const auto attributes = declared_attributes(m, {{"scales", {3.0f}}});
    ASSERT_EQ(attributes.size(), 1u);
    EXPECT_EQ(attributes[0].layout.location, 6u);
    EXPECT_EQ(attributes[0].layout.count, 4);
    EXPECT_EQ(attributes[0].layout.components, 3);
    EXPECT_EQ(render::attribute_defines(attributes),
              "#define INKSHADE_MULTISCALE_NORMALS 1\n"
              "#define INKSHADE_VERTEX_ATTRIBUTES layout(location = 6) in vec3 a_scale_normal[4]; out vec3 "
              "v_scale_normal[4]; \n"
              "#define INKSHADE_PASS_VERTEX_ATTRIBUTES for (int i = 0; i < 4; ++i) v_scale_normal[i] = "
              "u_normal_matrix * a_scale_normal[i]; \n");
    EXPECT_EQ(render::attribute_fragment_inputs(attributes), "in vec3 v_scale_normal[4];\n");
    // The default, 6 scales; at most 9 normals (locations 6-14).
    EXPECT_EQ(declared_attributes(m, {})[0].layout.count, 7);
    EXPECT_EQ(declared_attributes(m, {{"scales", {8.0f}}})[0].layout.count, 9);
}

TEST(ShadingInputs, AttributesTakeLocationsInDeclarationOrder) {
    ShadingModel m{.name = "both",
                   .inputs = {vertex_attribute_input("radial-curvature"), vertex_attribute_input("multiscale-normals")},
                   .params = shading_model("exaggerated").params};
    const auto attributes = declared_attributes(m, {{"scales", {2.0f}}});
    ASSERT_EQ(attributes.size(), 2u);
    EXPECT_EQ(attributes[0].layout.location, 6u);
    EXPECT_EQ(attributes[0].layout.count, 1);
    EXPECT_EQ(attributes[1].layout.location, 7u);
    EXPECT_EQ(attributes[1].layout.count, 3);
    EXPECT_EQ(render::attribute_fragment_inputs(attributes), "in float v_kr;\nin vec3 v_scale_normal[3];\n");
    EXPECT_TRUE(render::reads_view_attributes(m, {}));  // radial curvature is per view
    EXPECT_FALSE(render::reads_view_attributes(shading_model("exaggerated"), {}));

    // Past location 15, or naming no provider: the model's mistake, said at once.
    m.inputs.push_back(vertex_attribute_input("multiscale-normals"));
    EXPECT_THROW(declared_attributes(m, {{"scales", {8.0f}}}), RuntimeError);
    m.inputs = {vertex_attribute_input("nope")};
    EXPECT_THROW(declared_attributes(m, {}), RuntimeError);
}

TEST(ShadingInputs, ParametersSwitchInputsOn) {
    const ShadingModel& mtoon = shading_model("mtoon");
    EXPECT_TRUE(mtoon.reads(ShadingInputKind::ShadowMap, {}));
    EXPECT_FALSE(mtoon.reads(ShadingInputKind::ShadowMap, {{"shadows", {0.0f}}}));
    EXPECT_TRUE(mtoon.reads(ShadingInputKind::LinearLight, {}));                         // threejs
    EXPECT_FALSE(mtoon.reads(ShadingInputKind::LinearLight, {{"convention", {0.0f}}}));  // seeds
    EXPECT_TRUE(shading_model("threejs-phong").reads(ShadingInputKind::LinearLight, {}));
    EXPECT_FALSE(shading_model("phong").reads(ShadingInputKind::LinearLight, {}));
    EXPECT_TRUE(declared_attributes(shading_model("phong"), {}).empty());
}

}  // namespace
}  // namespace inkshade
