// Batch manifests: CSV and JSON Lines into jobs, defaults, stems, and one-line errors that
// name SOURCE:LINE; find_models for --models DIR.
#include <gtest/gtest.h>

#include <filesystem>

#include "inkshade/batch.hpp"
#include "inkshade/error.hpp"
#include "support/temp_dir.hpp"

namespace inkshade {
namespace {

std::vector<std::string> stems(const std::vector<BatchJob>& jobs) {
    std::vector<std::string> s;
    for (const BatchJob& j : jobs) s.push_back(j.stem);
    return s;
}

// The message of the InputError that `f` throws ("" when it throws none).
template <class F>
std::string input_error(F&& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(BatchManifest, CsvLineGivesViewsTimesStylesJobs) {
    const auto jobs = parse_manifest("model,views,styles\nbuiltin:teapot,orbit2x1,\"anime,toon\"\n", "m.csv");
    EXPECT_EQ(stems(jobs), (std::vector<std::string>{"teapot/anime/az000_el00", "teapot/anime/az180_el00",
                                                     "teapot/toon/az000_el00", "teapot/toon/az180_el00"}));
    for (const BatchJob& j : jobs) {
        EXPECT_EQ(j.model, "builtin:teapot");
        EXPECT_EQ(j.source, "m.csv:2");
        EXPECT_EQ(j.options.size.x, 512);
        EXPECT_TRUE(j.outputs.png);
        EXPECT_FALSE(j.outputs.svg);
    }
    EXPECT_EQ(jobs[1].view.camera.azimuth_degrees.value(), 180.0f);
    EXPECT_EQ(jobs[1].view.camera.elevation_degrees.value(), 0.0f);
}

TEST(BatchManifest, CsvQuotingKeepsCommasAndQuotes) {
    const auto jobs = parse_manifest(
        "model , name, views\n"
        "\"builtin:torus:major=1,minor=0.3\", \"ring \"\"a\"\"\", \"eye=0,0,5 target=0,0,0 name=front\"\n",
        "m.csv");
    ASSERT_EQ(jobs.size(), 1u);
    EXPECT_EQ(jobs[0].model, "builtin:torus:major=1,minor=0.3");
    EXPECT_EQ(jobs[0].stem, "ring \"a\"/lambert/front");
    EXPECT_EQ(jobs[0].view.camera.eye.value(), glm::vec3(0, 0, 5));
    EXPECT_EQ(jobs[0].view.camera.target.value(), glm::vec3(0, 0, 0));
}

TEST(BatchManifest, JsonLinesTakesStringsListsNumbersAndBooleans) {
    const auto jobs = parse_manifest(
        "{\"model\": \"a/chair.obj\", \"views\": [\"0:0\", \"eye=1,2,3\"], \"styles\": [\"ink\"], "
        "\"size\": [64, 32], \"format\": \"png,svg\", \"fov\": 45, \"ortho\": true}\n"
        "{\"model\": \"b/lamp.ply\", \"style\": \"toon\", \"size\": \"16x16\", \"format\": [\"svg\"]}\n",
        "jobs.jsonl");
    ASSERT_EQ(jobs.size(), 3u);
    EXPECT_EQ(stems(jobs),
              (std::vector<std::string>{"chair/ink/az000_el00", "chair/ink/cam1", "lamp/toon/az035_el20"}));
    EXPECT_EQ(jobs[0].options.size.x, 64);
    EXPECT_EQ(jobs[0].options.size.y, 32);
    EXPECT_TRUE(jobs[0].outputs.png && jobs[0].outputs.svg);
    EXPECT_EQ(job_request(jobs[0]).camera.fov_degrees, 45.0f);
    EXPECT_TRUE(job_request(jobs[1]).camera.orthographic);
    EXPECT_EQ(jobs[1].view.camera.eye.value(), glm::vec3(1, 2, 3));
    EXPECT_FALSE(jobs[2].outputs.png);
    EXPECT_TRUE(jobs[2].outputs.svg);
    EXPECT_EQ(jobs[2].source, "jobs.jsonl:2");
}

TEST(BatchManifest, DefaultsFillWhatALineLeavesOut) {
    BatchDefaults d;
    d.views = "turntable:3";
    d.styles = "anime";
    d.options.size = {100, 50};
    d.outputs = {false, true};
    const auto jobs = parse_manifest("model,styles\nx.stl,\ny.stl,toon\n", "m.csv", d);
    EXPECT_EQ(stems(jobs), (std::vector<std::string>{"x/anime/az000_el20", "x/anime/az120_el20", "x/anime/az240_el20",
                                                     "y/toon/az000_el20", "y/toon/az120_el20", "y/toon/az240_el20"}));
    EXPECT_EQ(jobs[0].options.size.x, 100);
    EXPECT_EQ(jobs[0].options.size.y, 50);
    EXPECT_TRUE(jobs[0].outputs.svg);
    EXPECT_FALSE(jobs[0].outputs.png);
}

TEST(BatchManifest, UpAxisColumnAndDefaultTurnTheViews) {
    BatchDefaults d;
    d.options.camera.up_axis = UpAxis::PosX;
    const auto jobs = parse_manifest("model,up-axis\nx.stl,z\ny.stl,\n", "m.csv", d);
    ASSERT_EQ(jobs.size(), 2u);
    EXPECT_EQ(job_request(jobs[0]).camera.up_axis, UpAxis::PosZ);
    EXPECT_EQ(job_request(jobs[1]).camera.up_axis, UpAxis::PosX);  // an empty cell takes the default
    // A z-up job hashes differently from the same job y-up; a y-up job's hash is unchanged.
    BatchJob y_up = jobs[0];
    y_up.options.camera.up_axis = UpAxis::PosY;
    EXPECT_NE(job_hash(jobs[0], "", -1), job_hash(y_up, "", -1));
}

TEST(BatchManifest, LightsColumnAndFileCamerasKeepTheirOwnProjection) {
    BatchDefaults d;
    d.options.camera.fov_degrees = 50.0f;
    d.options.camera.orthographic = true;
    const auto jobs = parse_manifest("model,views,lights\na.glb,camera=Main;20:10,file\nb.glb,,\n", "m.csv", d);
    ASSERT_EQ(jobs.size(), 3u);
    EXPECT_EQ(jobs[0].options.lights, LightSource::File);
    EXPECT_EQ(jobs[0].view.file_camera, "Main");
    EXPECT_EQ(job_request(jobs[0]).camera.fov_degrees, CameraOptions{}.fov_degrees);  // the file's camera projects
    EXPECT_FALSE(job_request(jobs[0]).camera.orthographic);
    EXPECT_EQ(job_request(jobs[1]).camera.fov_degrees, 50.0f);  // an orbit view takes the line's camera
    EXPECT_TRUE(job_request(jobs[1]).camera.orthographic);
    EXPECT_EQ(jobs[2].options.lights, LightSource::Style);
    EXPECT_THROW(parse_manifest("model,lights\na.glb,sun\n", "m.csv"), InputError);
    // Each changes the job's hash; a job with neither hashes as before.
    BatchJob plain = jobs[0];
    plain.options.lights = LightSource::Style;
    EXPECT_NE(job_hash(jobs[0], "", -1), job_hash(plain, "", -1));
    BatchJob orbit = plain;
    orbit.view.file_camera.clear();
    EXPECT_NE(job_hash(plain, "", -1), job_hash(orbit, "", -1));
}

TEST(BatchManifest, MarginColumnAndDefaultReachTheCamera) {
    BatchDefaults d;
    d.options.camera.margin = 0.1f;
    const auto jobs = parse_manifest("model,margin,fov\nx.stl,0.25,40\ny.stl,,\n", "m.csv", d);
    ASSERT_EQ(jobs.size(), 2u);
    EXPECT_EQ(job_request(jobs[0]).camera.margin, 0.25f);
    EXPECT_EQ(job_request(jobs[0]).camera.fov_degrees, 40.0f);  // one column does not reset the other
    EXPECT_EQ(job_request(jobs[1]).camera.margin, 0.1f);
    const auto json = parse_manifest("{\"model\": \"x.stl\", \"fov\": 50, \"margin\": 0}\n", "m.jsonl");
    EXPECT_EQ(job_request(json[0]).camera.margin, 0.0f);
    EXPECT_EQ(job_request(json[0]).camera.fov_degrees, 50.0f);
    EXPECT_NE(job_hash(jobs[0], "", -1), job_hash(jobs[1], "", -1));
}

// A .vrma animation's bytes are part of the hash: a changed file renders again.
TEST(BatchManifest, VrmAnimationFileBytesEnterTheHash) {
    test::TempDir dir;
    const std::string clip = dir.write("clip.vrma", "first");
    const auto jobs = parse_manifest("model,animation\na.vrm," + clip + "\nb.vrm,wave\n", "m.csv");
    ASSERT_EQ(jobs.size(), 2u);
    EXPECT_EQ(jobs[0].options.animation, clip);
    const std::string before = job_hash(jobs[0], "", -1), named = job_hash(jobs[1], "", -1);
    dir.write("clip.vrma", "second");
    EXPECT_NE(job_hash(jobs[0], "", -1), before);
    EXPECT_EQ(job_hash(jobs[1], "", -1), named);  // an animation inside the model: no file read
}

TEST(BatchManifest, LightIntensityColumnAndDefaultReachTheJob) {
    BatchDefaults d;
    d.options.light_intensity = 2.0f;
    const auto jobs = parse_manifest("model,light-intensity\nx.stl,3.5\ny.stl,\n", "m.csv", d);
    ASSERT_EQ(jobs.size(), 2u);
    EXPECT_EQ(jobs[0].options.light_intensity, 3.5f);
    EXPECT_EQ(jobs[1].options.light_intensity, 2.0f);
    const auto json = parse_manifest("{\"model\": \"x.stl\", \"light-intensity\": 0.5}\n", "m.jsonl");
    EXPECT_EQ(json[0].options.light_intensity, 0.5f);
    EXPECT_NE(job_hash(jobs[0], "", -1), job_hash(jobs[1], "", -1));
    try {
        parse_manifest("model,light-intensity\nx.stl,-1\n", "m.csv");
        ADD_FAILURE() << "a negative intensity was accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "m.csv:2: light-intensity: expected a number in [0, 1e+06], got '-1'");
    }
}

TEST(BatchManifest, OcclusionLevelsColumnAndDefaultReachTheJob) {
    BatchDefaults d;
    d.options.occlusion_levels = OcclusionLevels{0, 1};
    const auto jobs = parse_manifest("model,occlusion-levels\nx.stl,1-\ny.stl,\n", "m.csv", d);
    ASSERT_EQ(jobs.size(), 2u);
    ASSERT_TRUE(jobs[0].options.occlusion_levels && jobs[1].options.occlusion_levels);
    EXPECT_EQ(jobs[0].options.occlusion_levels->min, 1);
    EXPECT_EQ(jobs[0].options.occlusion_levels->max, kMaxOcclusionLevel);
    EXPECT_EQ(jobs[1].options.occlusion_levels->max, 1);  // the default
    const auto json = parse_manifest("{\"model\": \"x.stl\", \"occlusion-levels\": 2}\n", "m.jsonl");
    ASSERT_TRUE(json[0].options.occlusion_levels);
    EXPECT_EQ(json[0].options.occlusion_levels->min, 2);
    EXPECT_EQ(json[0].options.occlusion_levels->max, 2);
    // Part of the job hash when given (other SVG layers), absent otherwise (earlier jobs keep
    // their hashes).
    EXPECT_NE(job_hash(jobs[0], "", -1), job_hash(jobs[1], "", -1));
    BatchJob plain = jobs[1];
    plain.options.occlusion_levels.reset();
    EXPECT_EQ(job_hash(plain, "", -1).size(), job_hash(jobs[1], "", -1).size());
    EXPECT_NE(job_hash(plain, "", -1), job_hash(jobs[1], "", -1));
    EXPECT_EQ(input_error([] { parse_manifest("model,occlusion-levels\nx.stl,2-1\n", "m.csv"); }),
              "m.csv:2: occlusion levels: expected A-B with 0 <= A <= B <= 253 (0 = visible), A, or A- for A and "
              "deeper; got '2-1'");
}

TEST(BatchManifest, PoseColumnsAndDefaultsReachTheJob) {
    BatchDefaults d;
    d.options.time = 0.5f;
    d.options.animation = "wave";
    d.options.morphs = {{"blink", 1.0f}};
    const auto jobs = parse_manifest(
        "model,time,animation,morph,expression\n"
        "a.vrm,1.25,hop,\"happy=0.5;blink=0\",happy=1\n"
        "b.vrm,,,,\n",
        "m.csv", d);
    ASSERT_EQ(jobs.size(), 2u);
    EXPECT_EQ(jobs[0].options.time, 1.25f);
    EXPECT_EQ(jobs[0].options.animation, "hop");
    EXPECT_EQ(jobs[0].options.morphs, (std::vector<NamedWeight>{{"happy", 0.5f}, {"blink", 0.0f}}));
    EXPECT_EQ(jobs[0].options.expressions, (std::vector<NamedWeight>{{"happy", 1.0f}}));
    EXPECT_EQ(jobs[1].options.time, 0.5f);  // the defaults
    EXPECT_EQ(jobs[1].options.animation, "wave");
    EXPECT_EQ(jobs[1].options.morphs, (std::vector<NamedWeight>{{"blink", 1.0f}}));
    EXPECT_TRUE(jobs[1].options.expressions.empty());
    const auto json =
        parse_manifest(R"({"model": "a.vrm", "time": 2, "animation": "0", "expression": "sad=0.25"})", "m.jsonl");
    EXPECT_EQ(json[0].options.time, 2.0f);
    EXPECT_EQ(json[0].options.expressions, (std::vector<NamedWeight>{{"sad", 0.25f}}));
    // Each part of the pose is in the job hash when given; a job without a pose keeps its hash.
    BatchJob plain = jobs[1];
    plain.options.time.reset();
    plain.options.animation.clear();
    plain.options.morphs.clear();
    const std::string base = job_hash(plain, "", -1);
    BatchJob other = plain;
    other.options.time = 1.0f;
    const std::string at_one = job_hash(other, "", -1);
    other.options.time = 2.0f;
    EXPECT_NE(at_one, base);
    EXPECT_NE(job_hash(other, "", -1), at_one);  // a dataset's frames are separate jobs
    other = plain;
    other.options.animation = "wave";
    EXPECT_NE(job_hash(other, "", -1), base);
    other = plain;
    other.options.expressions = {{"happy", 1.0f}};
    EXPECT_NE(job_hash(other, "", -1), base);
    other = plain;
    other.options.morphs = {{"happy", 1.0f}};
    EXPECT_NE(job_hash(other, "", -1), base);
    EXPECT_EQ(input_error([] { parse_manifest("model,time\nx.glb,soon\n", "m.csv"); }),
              "m.csv:2: time: expected seconds, got 'soon'");
    EXPECT_EQ(input_error([] { parse_manifest("model,morph\nx.glb,happy\n", "m.csv"); }),
              "m.csv:2: morph: expected NAME=WEIGHT, got 'happy'");
    EXPECT_EQ(input_error([] { parse_manifest("model,expression\nx.glb,happy=3\n", "m.csv"); }),
              "m.csv:2: expression: happy: expression weights are in [0, 1], got 3");
}

TEST(BatchManifest, FormatFromExtensionElseFromFirstCharacter) {
    // No extension: '{' means JSON Lines, anything else CSV.
    EXPECT_EQ(parse_manifest("{\"model\": \"a.obj\"}\n", "-").size(), 1u);
    EXPECT_EQ(parse_manifest("# jobs\n\nmodel\na.obj\n", "-").size(), 1u);
    // A .csv whose line starts with '{' is still CSV (and here a bad header).
    EXPECT_NE(input_error([] { parse_manifest("{\"model\": \"a.obj\"}\n", "m.csv"); }).find("m.csv:1: quote inside"),
              std::string::npos);
}

TEST(BatchManifest, CommentsBlankLinesAndCrLfKeepLineNumbers) {
    const auto jobs = parse_manifest("\xEF\xBB\xBF# dataset\r\nmodel,output\r\n\r\n# skip\r\na.obj,x/one\r\n", "m.csv");
    ASSERT_EQ(jobs.size(), 1u);
    EXPECT_EQ(jobs[0].stem, "x/one");
    EXPECT_EQ(jobs[0].source, "m.csv:5");
}

TEST(BatchManifest, EveryBadLineIsAnInputErrorNamingSourceAndLine) {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"model,views\na.obj,0:0\nb.obj,sideways\n", "m.csv:3: view 'sideways'"},
        {"model,colour\na.obj,red\n", "m.csv:1: unknown column 'colour'"},
        {"views\n0:0\n", "m.csv:1: the header line has no 'model' column"},
        {"model,model\na.obj,b.obj\n", "m.csv:1: column 'model' is given twice"},
        {"model,views\na.obj,0:0,1:1\n", "m.csv:2: expected 2 fields"},
        {"model,views\na.obj,\"0:0\n", "m.csv:2: unterminated quoted field"},
        {"model,views\na.obj,0:0\"x\"\n", "m.csv:2: quote inside an unquoted field"},
        {"model,size\na.obj,big\n", "m.csv:2: size: expected WxH"},
        {"model,size\na.obj,0x10\n", "m.csv:2: size:"},
        {"model,format\na.obj,gif\n", "m.csv:2: format: unknown output format 'gif'"},
        {"model,fov\na.obj,180\n", "m.csv:2: fov:"},
        {"model,ortho\na.obj,maybe\n", "m.csv:2: ortho:"},
        {"model,margin\na.obj,0.5\n", "m.csv:2: margin: expected a fraction of the image in [0, 0.5)"},
        {"model,time\na.obj,-1\n", "m.csv:2: time: expected seconds >= 0, got '-1'"},
        {"model,margin\na.obj,wide\n", "m.csv:2: margin: expected a fraction of the image, got 'wide'"},
        {"model,up-axis\na.obj,w\n", "m.csv:2: up-axis: expected x, y, z, -x, -y or -z, got 'w'"},
        {"model,output\na.obj,/abs\n", "m.csv:2: output: '/abs' must be relative"},
        {"model,output\na.obj,x/../../y\n", "m.csv:2: output: 'x/../../y' must stay inside"},
        {"model,views,output\na.obj,orbit2x1,x\n", "m.csv:2: output: names one job"},
        {"model,name\na.obj,..\n", "m.csv:2: name:"},
        {"model,views\n,0:0\n", "m.csv:2: model: empty"},
        {"model,styles\na.obj,\"anime,anime\"\n", "m.csv:2: styles: 'anime' and 'anime'"},
        {"model,views\na.obj,\"0:0,0:0\"\n", "m.csv:2: view az000_el00 is listed twice"},
        {"model\na.obj\na.obj\n", "m.csv:3: output a/lambert/az035_el20 (a.obj, lambert) is also written by m.csv:2"},
        {"model\n", "m.csv: no jobs"},
        {"", "m.csv: no jobs"},
    };
    for (const auto& [text, expected] : cases) {
        const std::string what = input_error([&] { parse_manifest(text, "m.csv"); });
        EXPECT_NE(what.find(expected), std::string::npos) << "manifest:\n" << text << "\ngave: " << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
    const std::vector<std::pair<std::string, std::string>> json_cases = {
        {"{\"model\": \"a.obj\"}\n{\"model\": \"b.obj\",\n", "j.jsonl:2: not valid JSON"},
        {"[\"a.obj\"]\n", "j.jsonl:1: expected a JSON object"},
        {"{\"views\": \"0:0\"}\n", "j.jsonl:1: no \"model\" given"},
        {"{\"model\": 7}\n", "j.jsonl:1: model: unexpected JSON number"},
        {"{\"model\": \"a.obj\", \"size\": [1, 2, 3]}\n", "j.jsonl:1: size: expected"},
        {"{\"model\": \"a.obj\", \"views\": [1]}\n", "j.jsonl:1: views: expected a list of strings"},
        {"{\"model\": \"a.obj\", \"camera\": 1}\n", "j.jsonl:1: unknown column 'camera'"},
        {"{\"model\": \"a.obj\", \"margin\": \"\"}\n", "j.jsonl:1: margin: empty value"},
        {"{\"model\": \"a.obj\", \"time\": -1}\n", "j.jsonl:1: time: expected seconds >= 0, got '-1'"},
        {"{\"model\": \"a.obj\", \"view\": \"0:0\", \"views\": \"1:1\"}\n", "j.jsonl:1: column 'views' is given twice"},
    };
    for (const auto& [text, expected] : json_cases) {
        const std::string what = input_error([&] { parse_manifest(text, "j.jsonl"); });
        EXPECT_NE(what.find(expected), std::string::npos) << "manifest:\n" << text << "\ngave: " << what;
    }
}

// A lone carriage return inside a field is kept in the value (CSV lines end at '\n'); an error
// quoting that value shows it as '?' (found by fuzzing: two models' stems collided).
TEST(BatchManifest, ErrorsQuotingControlCharactersStayOneLine) {
    try {
        parse_manifest("model,output\nbuiltin:sphere,out/one\nbuil\rtin:sphere,out/one\n", "jobs.csv", BatchDefaults{});
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.find('\r'), std::string::npos) << what;
        EXPECT_NE(what.find("output out/one (buil?tin:sphere"), std::string::npos) << what;
    }
}

TEST(BatchManifest, LoadManifestReportsAMissingFile) {
    EXPECT_NE(input_error([] { load_manifest("/nonexistent/jobs.csv"); }).find("/nonexistent/jobs.csv: cannot open"),
              std::string::npos);
    test::TempDir dir;
    const std::string path = dir.write("jobs.jsonl", "{\"model\": \"builtin:sphere\"}\n");
    const auto jobs = load_manifest(path);
    ASSERT_EQ(jobs.size(), 1u);
    EXPECT_EQ(jobs[0].source, path + ":1");
}

TEST(BatchManifest, FindModelsListsMeshFilesRecursivelyInPathOrder) {
    test::TempDir dir;
    std::filesystem::create_directories(dir.path() / "chairs");
    dir.write("b.PLY", "x");
    dir.write("a.obj", "x");
    dir.write("chairs/c.stl", "x");
    dir.write("chairs/c.mtl", "x");
    dir.write("texture.png", "x");
    const auto models = find_models(dir.path().string());
    ASSERT_EQ(models.size(), 3u);
    EXPECT_EQ(models[0].name, "a");
    EXPECT_EQ(models[1].name, "b");
    EXPECT_EQ(models[2].name, "chairs/c");
    EXPECT_EQ(models[2].path, (dir.path() / "chairs" / "c.stl").string());
    BatchDefaults d;
    d.views = "0:0";
    d.styles = "ink,toon";
    EXPECT_EQ(stems(expand_jobs(models, d)),
              (std::vector<std::string>{"a/ink/az000_el00", "a/toon/az000_el00", "b/ink/az000_el00",
                                        "b/toon/az000_el00", "chairs/c/ink/az000_el00", "chairs/c/toon/az000_el00"}));
    // The same name from two files is refused, not silently overwritten.
    dir.write("a.stl", "x");
    EXPECT_NE(input_error([&] { expand_jobs(find_models(dir.path().string()), d); }).find("is also written by"),
              std::string::npos);
    EXPECT_NE(input_error([&] { find_models(dir.file("a.obj")); }).find("not a directory"), std::string::npos);
}

}  // namespace
}  // namespace inkshade
