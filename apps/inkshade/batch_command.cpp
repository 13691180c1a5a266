// `inkshade batch MANIFEST -o DIR` / `inkshade batch --models DIR --views V --styles S -o DIR`:
// models x views x styles into images, SVGs and metadata; resumable and shardable
// (docs/cli.md#batch, docs/cluster.md).
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>

#include "batch/jobs.hpp"
#include "batch_progress.hpp"
#include "commands.hpp"
#include "inkshade/batch.hpp"
#include "inkshade/error.hpp"
#include "inkshade/scene.hpp"
#include "inkshade/style.hpp"

namespace inkshade::cli {

namespace {

struct BatchArgs {
    std::string manifest;
    std::string models;
    std::string output;
    std::string views = "35:20";
    std::string styles = "lambert";
    std::string size = "512x512";
    std::string format = "png";
    float fov = 30.0f;
    bool ortho = false;
    std::string up_axis;
    std::optional<float> smooth_angle;
    std::optional<float> light_intensity;
    std::string occlusion_levels;
    std::optional<float> time;
    std::string animation;
    std::vector<std::string> morphs, expressions;  // NAME=W each
    std::string lights = "style";
    std::string aov;
    float margin = 0.05f;
    int samples = 4;
    std::string shard;
    bool force = false, dry_run = false, quiet = false;
};

// Set by SIGINT/SIGTERM; run_batch checks it between jobs. Lock-free, so the handler may.
std::atomic<bool> g_stop{false};
volatile std::sig_atomic_t g_signal = 0;
static_assert(std::atomic<bool>::is_always_lock_free);

extern "C" void on_stop_signal(int signal) {
    g_signal = signal;
    g_stop.store(true);
}

// Catches SIGINT and SIGTERM for its lifetime. SA_RESETHAND: a second signal ends the process
// at once (a file being written then leaves only its hidden temporary, never a partial output).
class StopSignals {
public:
    StopSignals() {
        struct sigaction sa {};
        sa.sa_handler = on_stop_signal;
        sigemptyset(&sa.sa_mask);
        sa.sa_flags = SA_RESETHAND | SA_RESTART;  // RESTART: writes go on while we finish the job
        sigaction(SIGINT, &sa, &old_int_);
        sigaction(SIGTERM, &sa, &old_term_);
    }
    ~StopSignals() {
        sigaction(SIGINT, &old_int_, nullptr);
        sigaction(SIGTERM, &old_term_, nullptr);
    }
    StopSignals(const StopSignals&) = delete;
    StopSignals& operator=(const StopSignals&) = delete;

private:
    struct sigaction old_int_ {
    }, old_term_{};
};

// The options' values, checked with the option's name in the message.
BatchDefaults defaults_from(const BatchArgs& a) {
    BatchDefaults d;
    auto named = [](const char* option, auto&& check) {
        try {
            check();
        } catch (const InputError& e) {
            // "size: ..." from the manifest parser reads "--size: ..." here.
            std::string what = e.what(), bare = std::string(option).substr(2) + ": ";
            if (what.starts_with(bare)) what.erase(0, bare.size());
            throw InputError(std::string(option) + ": " + what);
        }
    };
    named("--views", [&] { parse_views(a.views); });
    d.views = a.views;
    named("--styles", [&] {
        if (batch::split_list(a.styles, ",;").empty()) throw InputError("no style given");
    });
    d.styles = a.styles;
    // The options every job shares, checked as every front end checks them.
    SceneRequest shared;
    shared.size = parse_image_size("--size", a.size);
    shared.samples = a.samples;
    shared.camera.fov_degrees = a.fov;
    shared.camera.orthographic = a.ortho;
    if (!a.up_axis.empty()) shared.camera.up_axis = parse_up_axis("--up-axis", a.up_axis);
    shared.smooth_angle = a.smooth_angle;
    shared.light_intensity = a.light_intensity;
    shared.camera.margin = a.margin;
    shared.time = a.time;
    for (const std::string& m : a.morphs) shared.morphs.push_back(parse_named_weight("--morph", m));
    for (const std::string& e : a.expressions) shared.expressions.push_back(parse_named_weight("--expression", e));
    make_scene(shared);
    d.width = shared.size.x, d.height = shared.size.y;
    named("--format", [&] { d.outputs = batch::parse_formats(a.format); });
    d.fov_degrees = a.fov;
    d.orthographic = a.ortho;
    d.up_axis = shared.camera.up_axis;  // unset: each style's up-axis, else y
    d.smooth_angle = a.smooth_angle;
    d.light_intensity = a.light_intensity;
    d.lights = parse_light_source("--lights", a.lights);
    d.margin = a.margin;
    d.aovs = parse_aov_list("--aov", a.aov);
    if (!a.occlusion_levels.empty()) d.occlusion_levels = parse_occlusion_levels(a.occlusion_levels);
    d.time = a.time;
    d.animation = a.animation;
    d.morphs = shared.morphs;
    d.expressions = shared.expressions;
    return d;
}

// Every style the jobs name loads (bad input is exit 2 before any work, not a failed job).
void check_styles(const std::vector<BatchJob>& jobs) {
    std::set<std::string> checked;
    for (const BatchJob& job : jobs) {
        if (!checked.insert(job.style).second) continue;
        try {
            load_style(job.style);
        } catch (const InputError& e) {
            throw InputError(job.source + ": " + e.what());  // load_style's message names the style
        }
    }
}

void check_output_dir(const std::string& dir) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (dir.empty()) throw InputError("-o: empty path");
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec)) throw InputError(dir + ": output is not a directory");
    fs::create_directories(dir, ec);
    if (!fs::is_directory(dir, ec))
        throw InputError(dir + ": cannot create the output directory (" + ec.message() + ")");
    if (::access(dir.c_str(), W_OK) != 0) throw InputError(dir + ": output directory is not writable");
}

std::string formats(const BatchOutputs& o) {
    return std::string(o.png ? "png" : "") + (o.png && o.svg ? "," : "") + (o.svg ? "svg" : "");
}

int run_batch_command(const BatchArgs& args) {
    if (args.manifest.empty() == args.models.empty())
        throw InputError("give a MANIFEST or --models DIR (one of the two)");
    if (args.output.empty() && !args.dry_run) throw InputError("-o DIR: the output directory is required");
    const BatchDefaults defaults = defaults_from(args);
    std::vector<BatchJob> jobs =
        args.models.empty() ? load_manifest(args.manifest, defaults) : expand_jobs(find_models(args.models), defaults);
    check_styles(jobs);
    const size_t all = jobs.size();
    if (!args.shard.empty()) {
        int k = 1, n = 1;
        parse_shard(args.shard, k, n);
        jobs = shard(jobs, k, n);
    } else {
        jobs = batch_order(std::move(jobs));
    }

    if (args.dry_run) {
        for (const BatchJob& j : jobs)
            std::printf("%s\t%s\t%s\t%s\t%dx%d\t%s\n", j.stem.c_str(), j.model.c_str(), j.style.c_str(),
                        j.view.name.c_str(), j.width, j.height, formats(j.outputs).c_str());
        std::fprintf(stderr, "inkshade: dry run: %zu of %zu jobs%s\n", jobs.size(), all,
                     args.shard.empty() ? "" : (" (shard " + args.shard + ")").c_str());
        return 0;
    }
    check_output_dir(args.output);

    BatchOptions options;
    options.output_dir = args.output;
    options.force = args.force;
    options.samples = args.samples;
    options.stop = &g_stop;
    BatchProgressPrinter printer(::isatty(STDERR_FILENO) != 0, args.quiet);
    BatchSummary summary;
    {
        StopSignals signals;
        summary = run_batch(jobs, options, [&](const BatchEvent& e) { printer(e); });
    }
    printer.finish();
    std::string line = "batch: " + summary_line(summary);
    if (summary.interrupted) {
        const size_t left = summary.total - summary.done - summary.skipped - summary.failed;
        line += "; stopped by " + std::string(g_signal == SIGINT ? "SIGINT" : "SIGTERM") + ", " + std::to_string(left) +
                " not run (run the same command again to resume)";
    }
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
    if (summary.interrupted) return 128 + int(g_signal);  // 130 SIGINT, 143 SIGTERM, as a shell reports
    return summary.failed > 0 ? 1 : 0;
}

}  // namespace

Command add_batch_command(CLI::App& app) {
    auto args = std::make_shared<BatchArgs>();
    CLI::App* cmd = app.add_subcommand(
        "batch", "render models x views x styles into a dataset (resumable, shardable; docs/cli.md#batch)");
    cmd->add_option("MANIFEST", args->manifest, "jobs file: CSV with a header line, or JSON Lines (.jsonl)");
    cmd->add_option("--models", args->models, "instead of a manifest: every model file under DIR (recursively)");
    cmd->add_option("-o,--out,--output", args->output, "output directory (created when missing)");
    cmd->add_option("--views", args->views,
                    "views where the manifest gives none: orbitAxE, turntable:N[:EL], AZ:EL[:DIST], camera=NAME "
                    "(the model file's camera), 'eye=X,Y,Z target=X,Y,Z' (explicit cameras separated by ';')")
        ->capture_default_str();
    cmd->add_option("--styles", args->styles, "styles where the manifest gives none, comma-separated")
        ->capture_default_str();
    cmd->add_option("--size", args->size, "image size WxH where the manifest gives none")->capture_default_str();
    cmd->add_option("--format", args->format, "outputs where the manifest gives none: png, svg or png,svg")
        ->capture_default_str();
    cmd->add_option("--fov", args->fov, "vertical field of view in degrees where the manifest gives none")
        ->capture_default_str();
    cmd->add_flag("--ortho", args->ortho, "orthographic projection where the manifest gives none");
    cmd->add_option("--margin", args->margin,
                    "auto-framing's margin, a fraction of the image on each side, where the manifest gives none")
        ->capture_default_str();
    cmd->add_option("--up-axis", args->up_axis,
                    "the models' up axis where the manifest gives none (x, y, z, -x, -y, -z; default: the "
                    "style's up-axis, else y)");
    cmd->add_option("--smooth-angle", args->smooth_angle,
                    "auto-smooth angle in degrees for models without normals where the manifest gives none "
                    "(default: the style's, else 30)");
    cmd->add_option("--lights", args->lights,
                    "style or file (the model file's glTF light) where the manifest gives none")
        ->capture_default_str();
    cmd->add_option("--light-intensity", args->light_intensity,
                    "light intensity (E = light colour x intensity, as render --light-intensity) where the "
                    "manifest gives none");
    cmd->add_option("--occlusion-levels", args->occlusion_levels,
                    "occlusion levels of each SVG where the manifest gives none, A-B as `lines --occlusion-levels` "
                    "(default 0-0 = visible only; levels above 0 are dashed layers TYPE-hidden-N; the PNG draws "
                    "visible lines)");
    cmd->add_option("--time", args->time,
                    "seconds into --animation (glTF/VRM models) where the manifest gives no time (default 0)");
    cmd->add_option("--animation", args->animation,
                    "glTF animation (name or index) posing the models where the manifest gives none (default: none)");
    cmd->add_option("--morph", args->morphs,
                    "morph target weight NAME=W where the manifest gives no morph column (repeatable)")
        ->allow_extra_args(false);
    cmd->add_option("--expression", args->expressions,
                    "VRM expression NAME=W, W in [0, 1], where the manifest gives no expression column (repeatable)")
        ->allow_extra_args(false);
    cmd->add_option("--aov", args->aov,
                    "AOVs beside each image where the manifest gives none: depth, normal, id, material, mask, lines, "
                    "camera (docs/aov.md)");
    cmd->add_option("--samples", args->samples, "MSAA samples (1 = off)")->capture_default_str();
    cmd->add_option("--shard", args->shard, "render only shard K of N (K = 1..N; contiguous blocks of the job list)");
    cmd->add_flag("--force", args->force, "render complete jobs again (default: skip them)");
    cmd->add_flag("--dry-run", args->dry_run, "list the jobs (stem, model, style, view, size, formats) and exit");
    cmd->add_flag("-q,--quiet", args->quiet, "print failures and the summary only");
    return [args] { return run_batch_command(*args); };
}

}  // namespace inkshade::cli
