// The scene option table (inkshade/options.hpp): every option parses, checks and writes its
// values the same way for every front end; the docs table is the table's; earlier job hashes
// stay as they were.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

#include "inkshade/batch.hpp"
#include "inkshade/error.hpp"
#include "inkshade/options.hpp"
#include "inkshade/style.hpp"

namespace inkshade {
namespace {

std::string error_of(const OptionSpec& spec, const std::string& text) {
    try {
        parse_option(spec, text);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

const OptionSpec& option(const std::string& name) {
    const OptionSpec* spec = find_option(name);
    if (!spec) throw std::runtime_error("no option " + name);
    return *spec;
}

TEST(OptionTable, NamesAreUniqueAndFoundByEitherSpelling) {
    std::set<std::string> names;
    for (const OptionSpec& s : scene_options()) {
        EXPECT_TRUE(names.insert(s.name).second) << s.name;
        EXPECT_FALSE(s.help.empty()) << s.name;
        EXPECT_NE(s.fronts, 0u) << s.name;
        EXPECT_TRUE(s.get && s.put) << s.name;
    }
    EXPECT_EQ(find_option("light_pos"), find_option("light-pos"));
    EXPECT_EQ(find_option("light-pos")->name, "light-pos");
    EXPECT_EQ(find_option("colour"), nullptr);
}

// The default each front end shows is a value the option reads back to the same request.
TEST(OptionTable, EveryDefaultReadsBackToItself) {
    for (unsigned front : {unsigned(kRender), unsigned(kBatch)})
        for (const OptionSpec& s : scene_options()) {
            const std::string text = option_default(s, front);
            if (text.empty() || s.kind == OptionKind::Flag) continue;
            SceneRequest r = default_request(front);
            replace_option(r, s, text, OptionNames::Cli);
            EXPECT_EQ(s.get(r), s.get(default_request(front))) << s.name << " " << text;
        }
}

TEST(OptionTable, EmptyTextIsAnErrorForEveryOption) {
    for (const OptionSpec& s : scene_options())
        EXPECT_EQ(error_of(s, ""), "--" + s.name + ": empty value") << s.name;
}

// A range's bounds as the table states them: a closed bound is taken, an open one refused, and
// a value beyond either end is refused with the range in the message.
TEST(OptionTable, RangesTakeTheirBoundsAsStated) {
    size_t ranged = 0;
    for (const OptionSpec& s : scene_options()) {
        if (!s.has_range() || s.kind != OptionKind::Number) continue;
        ++ranged;
        auto text = [](double v) {
            std::ostringstream out;
            out.precision(9);
            out << v;
            return out.str();
        };
        EXPECT_EQ(error_of(s, text(s.min)).empty(), !s.min_open) << s.name;
        if (!std::isinf(s.max)) {
            EXPECT_EQ(error_of(s, text(s.max)).empty(), !s.max_open) << s.name;
        }
        const std::string below = error_of(s, text(s.min - 1.0));
        EXPECT_NE(below.find("--" + s.name + ": expected "), std::string::npos) << below;
        EXPECT_NE(below.find(", got '"), std::string::npos) << below;
        EXPECT_FALSE(error_of(s, "nan").empty()) << s.name;
        EXPECT_FALSE(error_of(s, "x").empty()) << s.name;
    }
    EXPECT_GE(ranged, 5u);
    EXPECT_EQ(error_of(option("time"), "-1"), "--time: expected seconds >= 0, got '-1'");
    EXPECT_EQ(error_of(option("fov"), "180"), "--fov: expected degrees in (0, 180), got '180'");
    EXPECT_EQ(error_of(option("bit-depth"), "12"), "--bit-depth: expected 8 or 16, got 12");
    EXPECT_EQ(error_of(option("samples"), "0"), "--samples: expected 1..16, got 0");
    EXPECT_EQ(error_of(option("up-axis"), "w"), "--up-axis: expected x, y, z, -x, -y or -z, got 'w'");
}

// A value set through the table is the value the request holds, for every kind of value.
TEST(OptionTable, TextReachesTheRequestField) {
    SceneRequest r;
    set_option(r, option("margin"), "0.2");
    set_option(r, option("up-axis"), "-z");
    set_option(r, option("light-pos"), "1,2,3");
    set_option(r, option("background"), "transparent");
    set_option(r, option("size"), "640x480");
    set_option(r, option("morph"), "a=0.5");
    set_option(r, option("morph"), "b=1");  // repeatable: appends
    set_option(r, option("occlusion-levels"), "1-");
    set_option(r, option("aov"), "depth; mask");
    set_option(r, option("lights"), "file");
    EXPECT_EQ(r.camera.margin, 0.2f);
    EXPECT_EQ(r.camera.up_axis, UpAxis::NegZ);
    EXPECT_EQ(r.light_position, glm::vec3(1, 2, 3));
    EXPECT_EQ(r.background->a, 0.0f);
    EXPECT_EQ(r.size, glm::ivec2(640, 480));
    EXPECT_EQ(r.morphs, (std::vector<NamedWeight>{{"a", 0.5f}, {"b", 1.0f}}));
    EXPECT_EQ(r.occlusion_levels, (OcclusionLevels{1, kMaxOcclusionLevel}));
    EXPECT_EQ(r.aovs, (std::vector<std::string>{"depth", "mask"}));
    EXPECT_EQ(r.lights, LightSource::File);
    replace_option(r, option("morph"), "c=0", OptionNames::Keywords);  // a manifest cell replaces
    EXPECT_EQ(r.morphs, (std::vector<NamedWeight>{{"c", 0.0f}}));
    EXPECT_EQ(format_option(option("morph"), option("morph").get(r)), "c=0");
}

// Hashes of jobs written before the option table (a 20-job batch rendered with --samples 2):
// the same manifest lines still hash to them, so such a folder resumes without rendering again.
TEST(OptionTable, JobHashesOfEarlierBatchesAreKept) {
    const std::string manifest =
        "model,name,views,styles,size,format,fov,ortho,margin,up-axis,smooth-angle,light-intensity,aov,"
        "occlusion-levels,time\n"
        "builtin:sphere,sph,\"turntable:3\",lambert,80x64,png,40,,0.1,,,2.5,\"depth,mask\",,\n"
        "builtin:torus,tor,\"45:20\",ink-vector,96x96,svg,,true,,z,,,,0-1,\n"
        "builtin:torus-knot,knot,\"10:10;200:-20\",anime,96x96,\"png,svg\",25,,0.2,,45,,,,0.5\n"
        "builtin:teapot,tp3,\"orbit3x2\",gooch,48x48,\"png,svg\",35,,0.15,x,30,1.5,\"depth,normal,id,mask\",0-,"
        "1.25\n";
    BatchDefaults d;
    d.options.samples = 2;
    const std::vector<BatchJob> jobs = parse_manifest(manifest, "jobs.csv", d);
    auto hash = [&](const std::string& stem) {
        for (const BatchJob& job : jobs) {
            if (job.stem != stem) continue;
            SceneRequest style;
            style.style = job.style;
            return job_hash(job, format_style(make_scene(style).style), -1);
        }
        return std::string("no job ") + stem;
    };
    EXPECT_EQ(hash("sph/lambert/az120_el20"), "03e233d119332852");
    // ink-vector's resolved style changed since (suggestive.min-length 4 -> 0, as rtsc; then
    // every object-space line type's new hidden-dash parameter, written out with the style): its
    // jobs render again; the other three styles, without object-space lines, are as they were.
    EXPECT_EQ(hash("tor/ink-vector/az045_el20"), "65a9f495ee92dbce");
    EXPECT_EQ(hash("knot/anime/az200_el-20"), "1ddf23c547647244");
    EXPECT_EQ(hash("tp3/gooch/az000_el00"), "bae75ab411d81d9b");
}

// docs/cli.md's option table is the table's own (INKSHADE_UPDATE_DOCS=1 rewrites it).
TEST(OptionTable, DocsTableIsTheTable) {
    const std::string path = std::string(INKSHADE_SOURCE_DIR) + "/docs/cli.md";
    std::ifstream in(path);
    ASSERT_TRUE(in) << path;
    std::stringstream text;
    text << in.rdbuf();
    std::string page = text.str();
    const std::string begin = "<!-- option table: begin -->\n", end = "<!-- option table: end -->";
    const size_t a = page.find(begin), b = page.find(end);
    ASSERT_NE(a, std::string::npos) << "docs/cli.md has no " << begin;
    ASSERT_NE(b, std::string::npos);
    const std::string rows = format_option_table_markdown();
    if (std::getenv("INKSHADE_UPDATE_DOCS")) {
        page.replace(a + begin.size(), b - a - begin.size(), rows);
        std::ofstream(path) << page;
        return;
    }
    EXPECT_EQ(page.substr(a + begin.size(), b - a - begin.size()), rows)
        << "docs/cli.md's option table differs from the option table: run the test with INKSHADE_UPDATE_DOCS=1";
}

}  // namespace
}  // namespace inkshade
