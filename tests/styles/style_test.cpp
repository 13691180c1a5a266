// Style files: parsing, errors, round trip, the built-in presets.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <functional>

#include "inkshade/error.hpp"
#include "inkshade/io.hpp"
#include "inkshade/style.hpp"
#include "render/render_fixture.hpp"
#include "support/temp_dir.hpp"
#include "styles/style_error.hpp"

namespace inkshade {
namespace {

// Parameters with defaults filled in, so styles that spell defaults out compare equal.
ParamValues full_params(const Style& s) {
    ParamValues all = s.shading.params;
    for (const ParamSpec& p : shading_model(s.shading.model).params) all.try_emplace(p.name, p.default_value);
    return all;
}

using test::style_error;

TEST(Style, ParsesEveryKindOfValue) {
    Style s = parse_style(R"(
description = "test"
background = "#000000"
base-color = [0.5, 0.25, 1.0]
[light]
color = "1,1,1"
ambient = "0.2"
intensity = 3
decay = 1.5
distance = 20
[shading]
model = "phong"
shininess = 64
specular = "#ff0000"
)",
                          "test.toml");
    EXPECT_EQ(s.name, "test");
    EXPECT_EQ(s.description, "test");
    EXPECT_EQ(s.background, glm::vec4(0, 0, 0, 1));
    EXPECT_EQ(s.shading.base_color, glm::vec3(0.5f, 0.25f, 1.0f));
    EXPECT_EQ(*s.ambient, glm::vec3(0.2f));
    EXPECT_EQ(s.light_intensity, 3.0f);
    EXPECT_EQ(s.light_decay, 1.5f);
    EXPECT_EQ(s.light_distance, 20.0f);
    const Style saved = parse_style(format_style(s), "saved.toml");  // --save-style keeps them
    EXPECT_EQ(saved.light_intensity, 3.0f);
    EXPECT_EQ(saved.light_decay, 1.5f);
    EXPECT_EQ(saved.light_distance, 20.0f);
    Light l;
    apply_style_light(s, l);
    EXPECT_FLOAT_EQ(l.intensity, 3.0f);
    EXPECT_FLOAT_EQ(l.decay, 1.5f);
    EXPECT_FLOAT_EQ(l.range, 20.0f);
    EXPECT_EQ(s.shading.model, "phong");
    EXPECT_EQ(s.shading.params.at("shininess"), ParamValue{64});
    EXPECT_EQ(s.shading.params.at("specular"), (ParamValue{1, 0, 0}));
}

TEST(Style, BadFilesGiveOneLineErrorsNamingTheProblem) {
    const std::pair<const char*, const char*> cases[] = {
        {"[shading\nmodel = 'phong'", "line 1"},
        {"colour = 1\n[shading]\nmodel = 'phong'", "unknown key 'colour'"},
        {"description = 'x'", "missing [shading]"},
        {"[shading]\nshininess = 3", "needs model"},
        {"[shading]\nmodel = 'glossy'", "unknown shading model 'glossy' (choose"},
        {"[shading]\nmodel = 'phong'\ngloss = 3", "has no parameter 'gloss' (it has shininess, specular)"},
        {"[shading]\nmodel = 'phong'\nshininess = 0", "outside [1, 4096]"},
        {"[shading]\nmodel = 'phong'\nshininess = 'big'", "is not a number"},
        {"[shading]\nmodel = 'phong'\nspecular = [1, 2]", "needs 3 values"},
        {"background = 'nope'\n[shading]\nmodel = 'phong'", "background"},
        {"[light]\nsun = 1\n[shading]\nmodel = 'phong'", "unknown key 'sun' in [light]"},
        {"[light]\nintensity = -1\n[shading]\nmodel = 'phong'", "light.intensity: expected a number in [0, 1e+06]"},
        {"[light]\ndecay = 'x'\n[shading]\nmodel = 'phong'", "light.decay: expected a number in [0, 16]"},
        {"[shading]\nmodel = 'phong'\n[[lines]]\ntype = 'no-such-line'", "unknown line type 'no-such-line'"},
    };
    for (const auto& [text, phrase] : cases) {
        std::string e = style_error(text);
        EXPECT_EQ(e.rfind("my.toml: ", 0), 0u) << text << " -> " << e;
        EXPECT_NE(e.find(phrase), std::string::npos) << text << " -> " << e;
        EXPECT_EQ(e.find('\n'), std::string::npos) << e;
    }
    EXPECT_NE(style_error(std::string(2 << 20, '#')).find("larger than 1 MiB"), std::string::npos);
}

TEST(Style, UnknownStyleNameListsBuiltins) {
    try {
        load_style("no-such-style");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("cel-000"), std::string::npos) << e.what();
    }
}

TEST(Style, UnknownNamesSuggestTheClosestOne) {
    auto error = [](const std::function<void()>& f) {
        try {
            f();
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    const std::string style = error([] { load_style("anmie"); });
    EXPECT_EQ(style.rfind("anmie: no such style file or built-in style (built-in: anime, ", 0), 0u) << style;
    EXPECT_TRUE(style.ends_with(") (did you mean 'anime'?)")) << style;
    const std::string model = error([] { shading_model("phnog"); });
    EXPECT_EQ(model.rfind("unknown shading model 'phnog' (choose ", 0), 0u) << model;
    EXPECT_TRUE(model.ends_with(") (did you mean 'phong'?)")) << model;
    const std::string line = error([] { line_type("contuor"); });
    EXPECT_EQ(line.rfind("unknown line type 'contuor' (choose ", 0), 0u) << line;
    EXPECT_TRUE(line.ends_with(") (did you mean 'contour'?)")) << line;
    // Nothing close: the list alone.
    for (const std::string& e : {error([] { load_style("glossy"); }), error([] { shading_model("glossy"); }),
                                 error([] { line_type("squiggle"); })}) {
        EXPECT_FALSE(e.empty());
        EXPECT_EQ(e.find("did you mean"), std::string::npos) << e;
    }
    EXPECT_NE(style_error("[shading]\nmodel = 'lambret'").find("(did you mean 'lambert'?)"), std::string::npos);
    EXPECT_NE(style_error("[shading]\nmodel = 'phong'\n[[lines]]\ntype = 'crese'").find("(did you mean 'crease'?)"),
              std::string::npos);
}

TEST(Style, NamesIgnoreCaseAndKeepTheirCanonicalSpelling) {
    EXPECT_EQ(shading_model("PHONG").name, "phong");
    EXPECT_EQ(shading_model("Blinn-Phong").name, "blinn-phong");
    EXPECT_EQ(line_type("Contour").name, "contour");
    EXPECT_EQ(line_type("RIM-contour").name, "rim-contour");
    const Style anime = load_style("Anime");
    EXPECT_EQ(anime.name, "anime");
    EXPECT_EQ(anime.shading.model, load_style("anime").shading.model);
    const Style phong = load_style("PHONG");  // a model's default style
    EXPECT_EQ(phong.name, "phong");
    EXPECT_EQ(phong.shading.model, "phong");
    const Style file = parse_style("[shading]\nmodel = 'Phong'\n[[lines]]\ntype = 'Hull'\n", "my.toml");
    EXPECT_EQ(file.shading.model, "phong");
    ASSERT_EQ(file.lines.size(), 1u);
    EXPECT_EQ(file.lines[0].type, "hull");
    Style over = load_style("phong");
    apply_override(over, "PHONG.shininess=8");
    EXPECT_EQ(over.shading.params.at("shininess"), ParamValue{8.0f});
}

TEST(Style, AStylePathStaysAPath) {
    // A file spelt like a built-in but for case is the file, not the built-in.
    test::TempDir dir;
    const std::string path = dir.write("Toon", "[shading]\nmodel = 'gooch'\n");
    const auto cwd = std::filesystem::current_path();
    std::filesystem::current_path(dir.path());
    Style s;
    EXPECT_NO_THROW(s = load_style("Toon"));
    std::filesystem::current_path(cwd);
    EXPECT_EQ(s.shading.model, "gooch");
    EXPECT_EQ(load_style(path).shading.model, "gooch");
    EXPECT_EQ(load_style("toon").name, "toon");              // the built-in when spelt exactly
    EXPECT_THROW(load_style(dir.file("TOON")), InputError);  // no such file: a path is not a name
}

TEST(Style, BuiltinsIncludePresetsAndOneStylePerModel) {
    std::vector<std::string> names = builtin_style_names();
    auto has = [&](const std::string& n) { return std::find(names.begin(), names.end(), n) != names.end(); };
    for (const ShadingModel* m : shading_models()) EXPECT_TRUE(has(m->name)) << m->name;
    for (const char* preset : {"cel-000", "cel-002", "cel-004", "toon"}) EXPECT_TRUE(has(preset)) << preset;
    for (const char* composite : {"anime", "ink"}) EXPECT_TRUE(has(composite)) << composite;
}

// Qu, Chen & Zwicker 2022, "Non-Photorealistic Shading Techniques for Anime-Style Rendering",
// eq. 4: half-Lambert > 0.8 -> 1, > 0.6 -> 0.75, > 0.4 -> 0.5, > 0.2 -> 0.25, else 0.
TEST(Style, Cel000PresetHoldsFiveBandNumbers) {
    Style s = load_style("cel-000");
    ASSERT_EQ(s.shading.model, "cel");
    const ParamValues p = full_params(s);
    EXPECT_EQ(format_param_value(*shading_model("cel").param("driver"), p.at("driver")), "half-lambert");
    EXPECT_EQ(p.at("thresholds"), (ParamValue{0.8f, 0.6f, 0.4f, 0.2f}));
    EXPECT_EQ(p.at("levels"), (ParamValue{1.0f, 0.75f, 0.5f, 0.25f, 0.0f}));
}

// A style's base colour tints only meshes without colours of their own; mesh-colors = false
// makes it the whole fill (ink).
TEST(Style, BaseColourIsATintUnlessMeshColoursAreOff) {
    const std::string model = "[shading]\nmodel = 'lambert'\n";
    EXPECT_EQ(parse_style(model, "a.toml").shading.base_color_use, BaseColorUse::Fallback);
    EXPECT_EQ(parse_style("mesh-colors = true\n" + model, "a.toml").shading.base_color_use, BaseColorUse::Fallback);
    EXPECT_EQ(parse_style("mesh-colors = false\n" + model, "a.toml").shading.base_color_use, BaseColorUse::Only);
    EXPECT_EQ(style_error("mesh-colors = 'no'\n" + model), "my.toml: mesh-colors: expected true or false");
    EXPECT_EQ(style_error("mesh-colors = 0\n" + model), "my.toml: mesh-colors: expected true or false");
    for (const char* name : {"ink", "ink-vector"})
        EXPECT_EQ(load_style(name).shading.base_color_use, BaseColorUse::Only);
    for (const char* name : {"anime", "toon", "lambert"})
        EXPECT_EQ(load_style(name).shading.base_color_use, BaseColorUse::Fallback) << name;
    EXPECT_NE(format_style(load_style("ink")).find("\nmesh-colors = false\n"), std::string::npos);
    EXPECT_EQ(format_style(load_style("anime")).find("mesh-colors"), std::string::npos);
}

TEST(Style, EveryBuiltinRoundTripsThroughItsFile) {
    test::TempDir dir;
    for (const std::string& name : builtin_style_names()) {
        Style a = load_style(name);
        const std::string path = dir.file(name + ".toml");
        save_style(path, a);
        Style b = load_style(path);
        EXPECT_EQ(a.shading.model, b.shading.model) << name;
        EXPECT_EQ(full_params(a), full_params(b)) << name;
        EXPECT_EQ(a.shading.base_color, b.shading.base_color) << name;
        EXPECT_EQ(a.shading.base_color_use, b.shading.base_color_use) << name;
        EXPECT_EQ(a.background, b.background) << name;
        EXPECT_EQ(a.light_color, b.light_color) << name;
        EXPECT_EQ(a.ambient, b.ambient) << name;
        EXPECT_EQ(a.description, b.description) << name;
    }
}

// Every built-in style renders a lit sphere: no error, and the model is not one flat colour.
TEST(Style, EveryBuiltinStyleRenders) {
    Renderer& r = test::shared_renderer();
    Mesh sphere = load_mesh("builtin:sphere");
    r.set_mesh(sphere);
    for (const std::string& name : builtin_style_names()) {
        Style s = load_style(name);
        RenderOptions o;
        o.width = o.height = 64;
        o.background = s.background;
        Light light;
        light.position = glm::vec3(1, 1, 2);
        Image img = r.render(test::ortho_camera(), light, s.shading, o);
        int lo = 255, hi = 0;
        for (int y = 24; y < 40; ++y)
            for (int x = 24; x < 40; ++x) {
                const uint8_t* p = img.pixel(x, y);
                lo = std::min(lo, int(p[0]) + p[1] + p[2]);
                hi = std::max(hi, int(p[0]) + p[1] + p[2]);
            }
        EXPECT_GT(hi, 0) << name << " renders black";
        if (name != "view") {  // v is constant under an orthographic camera
            EXPECT_GT(hi - lo, 0) << name << " renders one flat colour";
        }
    }
}

// The composite styles: anime = cel-000 + hull + rim contour + image-space suggestive contours
// (the anime look of Qu, Chen & Zwicker 2022), toon = cel-004's bands and highlight + hull
// outline, ink = white fill + every raster line type; technical = gooch + object-space
// contours and creases, ink-vector = white fill + the object-space line types as strokes.
// Each renders the teapot with its lines: dark line pixels, and more of them than the same
// style without lines.
TEST(Style, CompositeStylesCarryTheirLinesAndRender) {
    auto types_of = [](const Style& s) {
        std::vector<std::string> t;
        for (const LineSettings& l : s.lines) t.push_back(l.type);
        return t;
    };
    EXPECT_EQ(types_of(load_style("anime")), (std::vector<std::string>{"hull", "rim-contour", "suggestive-image"}));
    EXPECT_EQ(types_of(load_style("toon")), (std::vector<std::string>{"hull"}));
    EXPECT_EQ(types_of(load_style("ink")),
              (std::vector<std::string>{"hull", "rim-contour", "edges", "suggestive-image"}));
    EXPECT_EQ(types_of(load_style("technical")), (std::vector<std::string>{"contour", "crease", "border"}));
    EXPECT_EQ(load_style("technical").shading.model, "gooch");
    EXPECT_EQ(types_of(load_style("ink-vector")),
              (std::vector<std::string>{"contour", "suggestive", "crease", "border"}));
    EXPECT_EQ(load_style("anime").shading.params, load_style("cel-000").shading.params);
    // sketch and manga: the hatching model's strokes under tapered object-space contours,
    // sketch's drawn twice with jitter, manga's with a calligraphic nib.
    for (const char* name : {"sketch", "manga"}) {
        const Style st = load_style(name);
        EXPECT_EQ(st.shading.model, "hatching") << name;
        ASSERT_FALSE(st.lines.empty());
        EXPECT_EQ(st.lines.front().type, "contour");
        EXPECT_GT(line_param(st.lines.front(), "taper-in").at(0), 0.0f) << name;
        EXPECT_GT(line_param(st.lines.front(), "taper-out").at(0), 0.0f) << name;
    }
    EXPECT_EQ(line_param(load_style("sketch").lines.front(), "sketch-passes").at(0), 2.0f);
    EXPECT_GT(line_param(load_style("sketch").lines.front(), "sketch-jitter").at(0), 0.0f);
    EXPECT_GT(line_param(load_style("manga").lines.front(), "calligraphy").at(0), 0.0f);

    Renderer& r = test::shared_renderer();
    const Mesh teapot = load_mesh("builtin:teapot");
    r.set_mesh(teapot);
    CameraOptions co;
    const Camera camera = frame_camera(teapot.bounds(), co, 1.0f);
    for (const char* name : {"anime", "toon", "ink", "technical", "ink-vector", "sketch", "manga"}) {
        Style s = load_style(name);
        RenderOptions o;
        o.width = o.height = 192;
        o.background = s.background;
        Light light = default_light(teapot.bounds(), camera);
        apply_style_light(s, light);
        auto dark_pixels = [&](const std::vector<LineSettings>& lines) {
            Image img = r.render(camera, light, s.shading, lines, o);
            int n = 0;
            // Pencil-grey contours (sketch) are darker than its hatching, not black.
            const int dark = s.shading.model == "hatching" ? 200 : 60;
            for (size_t i = 0; i < img.rgba.size(); i += 4) n += img.rgba[i] + img.rgba[i + 1] + img.rgba[i + 2] < dark;
            return n;
        };
        const int with = dark_pixels(s.lines), without = dark_pixels({});
        EXPECT_GT(with, without + 300) << name;
    }
}

// One override path for --set and the viewer: model parameters, parameters of drawn line
// types; anything else is an error that leaves the style unchanged.
TEST(Style, ApplyOverrideSetsModelAndLineParameters) {
    Style s = load_style("toon");
    apply_override(s, "shininess=8");
    apply_override(s, "cel.specular=false");
    apply_override(s, "hull.width=4.5");
    EXPECT_EQ(s.shading.params.at("shininess"), ParamValue{8.0f});
    EXPECT_EQ(s.shading.params.at("specular"), ParamValue{0.0f});
    EXPECT_EQ(s.lines.at(0).params.at("width"), ParamValue{4.5f});
    const Style before = s;
    for (const char* bad : {"edges.width=2", "hull.gloss=1", "phong.shininess=3", "shininess", "hull.width=-1"}) {
        EXPECT_THROW(apply_override(s, bad), InputError) << bad;
        EXPECT_EQ(format_style(s), format_style(before)) << bad;
    }
    try {
        apply_override(s, "edges.width=2");
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("draws no 'edges' lines (it draws hull)"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace inkshade
