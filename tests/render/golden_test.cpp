// Golden images: every built-in style (builtin_style_names(), so new styles are covered as they
// land) on the teapot, the torus knot and the sphere, rendered at 256x256 the way
// `inkshade render MODEL --style NAME --size 256x256` renders them (auto-framed camera, default
// light with the style's light colours, the style's background and line types, 4x MSAA), compared
// with tests/golden/STYLE--MODEL.png. A failure writes the actual image and an amplified
// difference into BUILD/golden-failures/ and names both.
//
// INKSHADE_UPDATE_GOLDENS=1 (`make update-goldens`) writes the references instead of comparing
// (atomically; an unchanged image is left alone) and removes goldens of styles that are gone.
// The references are llvmpipe's output: on another GL implementation the cases are skipped.
// Thresholds and the update procedure: docs/testing.md.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <ostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "inkshade/camera.hpp"
#include "inkshade/error.hpp"
#include "inkshade/image.hpp"
#include "inkshade/io.hpp"
#include "inkshade/renderer.hpp"
#include "inkshade/style.hpp"
#include "render/render_fixture.hpp"

namespace inkshade::test {
namespace {

namespace fs = std::filesystem;

constexpr int kGoldenSize = 256;
// llvmpipe renders these images bit-identically run to run, with any LP_NUM_THREADS and core
// count, so a match is exact in practice. The thresholds leave room only for last-bit rounding
// (another LLVM's code generation): no channel of any pixel may differ by more than
// kMaxChannelDiff, and the mean absolute difference over all RGBA channels must stay within
// kMaxMeanDiff (about 500 channel values off by one in a 256x256 image). Blinn-Phong's default
// exponent 128 -> 120 gives a mean of 0.005 to 0.01 with a max of 2 to 3 and fails both.
constexpr int kMaxChannelDiff = 1;
constexpr double kMaxMeanDiff = 0.002;
constexpr int kDiffGain = 16;  // the diff image shows 16 x |actual - golden|, so 1/255 is visible

const std::vector<std::string>& golden_models() {
    static const std::vector<std::string> models = {"teapot", "torus-knot", "sphere"};
    return models;
}

bool update_mode() {
    const char* v = std::getenv("INKSHADE_UPDATE_GOLDENS");
    return v && std::string(v) == "1";
}

fs::path golden_dir() { return fs::path(INKSHADE_SOURCE_DIR) / "tests" / "golden"; }
// The build directory is where the inkshade binary lives.
fs::path failure_dir() { return fs::path(INKSHADE_BIN).parent_path() / "golden-failures"; }
std::string file_stem(const std::string& style, const std::string& model) { return style + "--" + model; }

struct GoldenCase {
    std::string style, model;
};
void PrintTo(const GoldenCase& c, std::ostream* os) { *os << c.style << " on builtin:" << c.model; }

// The binary's one renderer (render_fixture.hpp). The cases run model by model (the style
// varies fastest) and a suite's cases run together even when shuffled, so each model's mesh is
// uploaded once per suite and its line-extraction state is reused across the styles.
class BuiltinStyle : public ::testing::TestWithParam<GoldenCase> {
protected:
    struct Scene {
        Camera camera;
        BoundingBox box;
    };

    static std::string& current_model() {
        static std::string model;
        return model;
    }
    // Other tests set their own meshes on the shared renderer.
    static void SetUpTestSuite() { current_model().clear(); }

    static Renderer& renderer() { return shared_renderer(); }

    // Sets `model` as the renderer's mesh unless it is already; returns its framing.
    static const Scene& use_model(const std::string& model) {
        static std::map<std::string, Scene> scenes;
        if (current_model() != model) {
            const Mesh mesh = load_mesh("builtin:" + model);
            renderer().set_mesh(mesh);
            current_model() = model;
            Scene s;
            s.box = mesh.bounds();
            s.camera = frame_camera(s.box, CameraOptions{}, 1.0f, mesh.positions);  // Scene::frame(mesh)
            scenes[model] = s;
        }
        return scenes.at(model);
    }

    // What `inkshade render builtin:MODEL --style STYLE --size 256x256` writes.
    static Image render(const std::string& style_name, const std::string& model) {
        const Style style = load_style(style_name);
        const Scene& scene = use_model(model);
        Light light = default_light(scene.box, scene.camera);
        apply_style_light(style, light);
        RenderOptions options;
        options.width = options.height = kGoldenSize;
        options.samples = 4;
        options.background = style.background;
        return renderer().render(scene.camera, light, style.shading, style.lines, options);
    }
};

struct Comparison {
    int max_diff = 0;
    double mean_diff = 0.0;
    int over = 0;  // pixels with a channel over kMaxChannelDiff
    int max_x = 0, max_y = 0;
    Image diff;
};

Comparison compare(const Image& actual, const Image& golden) {
    Comparison c;
    c.diff = Image(actual.width, actual.height);
    uint64_t sum = 0;
    for (int y = 0; y < actual.height; ++y)
        for (int x = 0; x < actual.width; ++x) {
            const uint8_t *a = actual.pixel(x, y), *g = golden.pixel(x, y);
            uint8_t* d = c.diff.pixel(x, y);
            int pixel_max = 0;
            for (int ch = 0; ch < 4; ++ch) {
                const int delta = std::abs(int(a[ch]) - int(g[ch]));
                sum += uint64_t(delta);
                pixel_max = std::max(pixel_max, delta);
                if (ch < 3) d[ch] = uint8_t(std::min(255, delta * kDiffGain));
            }
            d[3] = 255;
            // An alpha-only difference (transparent backgrounds) shows as grey.
            const int alpha = std::abs(int(a[3]) - int(g[3]));
            if (alpha > 0)
                for (int ch = 0; ch < 3; ++ch) d[ch] = std::max(d[ch], uint8_t(std::min(255, alpha * kDiffGain)));
            if (pixel_max > kMaxChannelDiff) ++c.over;
            if (pixel_max > c.max_diff) {
                c.max_diff = pixel_max;
                c.max_x = x;
                c.max_y = y;
            }
        }
    c.mean_diff = double(sum) / double(actual.rgba.size());
    return c;
}

TEST_P(BuiltinStyle, MatchesGolden) {
    const GoldenCase& gc = GetParam();
    const std::string renderer_name = renderer().gl_renderer();
    if (renderer_name.find("llvmpipe") == std::string::npos)
        GTEST_SKIP() << "golden images are llvmpipe references; GL here is " << renderer_name;
    const Image actual = render(gc.style, gc.model);
    ASSERT_EQ(actual.width, kGoldenSize);
    ASSERT_EQ(actual.height, kGoldenSize);
    const fs::path golden_path = golden_dir() / (file_stem(gc.style, gc.model) + ".png");

    if (update_mode()) {
        fs::create_directories(golden_dir());
        std::error_code ec;
        if (fs::exists(golden_path, ec)) {
            try {
                const Image old = read_png(golden_path.string());
                if (old.width == actual.width && old.height == actual.height && old.rgba == actual.rgba) return;
            } catch (const InputError&) {  // unreadable: rewritten below
            }
        }
        write_png(golden_path.string(), actual);
        std::printf("golden: wrote %s\n", golden_path.string().c_str());
        return;
    }

    const fs::path out = failure_dir();
    const std::string stem = file_stem(gc.style, gc.model);
    const fs::path actual_path = out / (stem + ".actual.png"), diff_path = out / (stem + ".diff.png");
    std::error_code ec;
    fs::remove(actual_path, ec);  // left from an earlier failing run
    fs::remove(diff_path, ec);
    if (!fs::exists(golden_path)) {
        fs::create_directories(out);
        write_png(actual_path.string(), actual);
        FAIL() << "no golden image " << golden_path.string() << " for style " << gc.style << " on builtin:" << gc.model
               << ": run make update-goldens (then look at it and commit it); actual: " << actual_path.string();
    }
    const Image golden = read_png(golden_path.string());
    if (golden.width != actual.width || golden.height != actual.height) {
        fs::create_directories(out);
        write_png(actual_path.string(), actual);
        FAIL() << golden_path.string() << " is " << golden.width << "x" << golden.height << ", the render "
               << actual.width << "x" << actual.height << "; actual: " << actual_path.string()
               << " (run make update-goldens if the change is intended)";
    }
    const Comparison c = compare(actual, golden);
    if (c.max_diff <= kMaxChannelDiff && c.mean_diff <= kMaxMeanDiff) return;
    fs::create_directories(out);
    write_png(actual_path.string(), actual);
    write_png(diff_path.string(), c.diff);
    ADD_FAILURE() << "style " << gc.style << " on builtin:" << gc.model << " differs from " << golden_path.string()
                  << ": max channel difference " << c.max_diff << " (limit " << kMaxChannelDiff << ") at pixel ("
                  << c.max_x << "," << c.max_y << "), mean absolute difference " << c.mean_diff << " (limit "
                  << kMaxMeanDiff << "), " << c.over << " pixels over the limit\n  actual: " << actual_path.string()
                  << "\n  diff (x" << kDiffGain << "): " << diff_path.string()
                  << "\n  if the change is intended: make update-goldens, look at the images, commit them";
}

std::vector<GoldenCase> golden_cases() {
    std::vector<GoldenCase> cases;
    for (const std::string& model : golden_models())
        for (const std::string& style : builtin_style_names()) cases.push_back({style, model});
    return cases;
}

std::string case_name(const ::testing::TestParamInfo<GoldenCase>& info) {
    std::string name = info.param.style + "__" + info.param.model;
    for (char& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '_') ch = '_';
    return name;
}

INSTANTIATE_TEST_SUITE_P(GoldenStyles, BuiltinStyle, ::testing::ValuesIn(golden_cases()), case_name);

// Every golden belongs to a case: a style that was removed or renamed leaves none behind
// (update mode deletes them).
TEST(GoldenFiles, NoneStale) {
    std::set<std::string> expected;
    for (const GoldenCase& gc : golden_cases()) expected.insert(file_stem(gc.style, gc.model) + ".png");
    std::error_code ec;
    if (!fs::is_directory(golden_dir(), ec)) return;  // the cases report the missing goldens
    std::vector<std::string> stale;
    for (const auto& entry : fs::directory_iterator(golden_dir())) {
        const std::string name = entry.path().filename().string();
        if (entry.path().extension() != ".png" || expected.count(name)) continue;
        if (update_mode()) {
            fs::remove(entry.path());
            std::printf("golden: removed %s\n", entry.path().string().c_str());
        } else {
            stale.push_back(name);
        }
    }
    std::ostringstream list;
    for (const auto& s : stale) list << " " << s;
    EXPECT_TRUE(stale.empty()) << "golden images without a built-in style or model in " << golden_dir().string() << ":"
                               << list.str() << " (run make update-goldens to remove them)";
}

}  // namespace
}  // namespace inkshade::test
