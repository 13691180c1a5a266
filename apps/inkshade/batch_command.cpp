// `inkshade batch MANIFEST -o DIR` / `inkshade batch --models DIR --views V --styles S -o DIR`:
// models x views x styles into images, SVGs and metadata, in folders or WebDataset tar shards;
// resumable, shardable and verifiable
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
#include "scene_options.hpp"

namespace inkshade::cli {

namespace {

struct BatchArgs {
    std::string manifest;
    std::string models;
    std::string output;
    std::string views = BatchDefaults{}.views;
    std::string styles = BatchDefaults{}.styles;
    std::string format = "png";
    SceneOptions scene;  // the option table's batch options: the defaults of the manifest's columns
    std::string shard;
    std::string layout = "folder", shard_size = "1GB", shard_prefix = "shard", verify;
    bool force = false, dry_run = false, quiet = false, transforms_json = false;
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
BatchDefaults defaults_from(const BatchArgs& a, const CLI::App& cmd) {
    BatchDefaults d;
    auto named = [](const char* option, auto&& check) {
        try {
            check();
        } catch (const InputError& e) {
            // "format: ..." from the manifest parser reads "--format: ..." here.
            std::string what = e.what(), bare = std::string(option).substr(2) + ": ";
            if (what.starts_with(bare)) what.erase(0, bare.size());
            throw InputError(std::string(option) + ": " + what);
        }
    };
    named("--views", [&] { parse_views(a.views); });
    d.views = a.views;
    named("--styles", [&] {
        if (cmd.count("--styles") && batch::split_list(a.styles, ",;").empty()) throw InputError("no style given");
    });
    d.styles = a.styles;
    named("--format", [&] { d.outputs = batch::parse_formats(a.format); });
    // The options every job shares, checked as every front end checks them.
    d.options = a.scene.to_request(cmd);
    check_request(d.options);
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
    std::string out;
    for (auto [on, name] : {std::pair{o.png, "png"}, std::pair{o.svg, "svg"}, std::pair{o.lines_json, "lines-json"}})
        if (on) out += (out.empty() ? "" : ",") + std::string(name);
    return out;
}

// Where the jobs go: the layout, and for WebDataset the shard size and prefix; with --shard K/N
// the prefix gains "-KofN", so the workers of one manifest write distinct shard files.
BatchOptions layout_options(const BatchArgs& args, const CLI::App& cmd) {
    BatchOptions o;
    o.layout = parse_layout(args.layout);
    if (o.layout != BatchLayout::WebDataset) {
        for (const char* option : {"--shard-size", "--shard-prefix"})
            if (cmd.count(option)) throw InputError(std::string(option) + ": only with --layout webdataset");
        return o;
    }
    // transforms.json names image files beside it; a shard's images are inside tar files.
    if (args.transforms_json) throw InputError("--transforms-json: only with --layout folder");
    o.shard_size = parse_shard_size(args.shard_size);
    int k = 0, n = 0;
    if (!args.shard.empty()) parse_shard(args.shard, k, n);
    o.shard_prefix = webdataset_shard_prefix(args.shard_prefix, k, n);
    return o;
}

// --verify DIR: one line per problem on stdout, a summary line; exit 1 when there is any.
int verify_command(const std::vector<BatchJob>& jobs, BatchOptions options, const std::string& dir) {
    options.output_dir = dir;
    const std::vector<std::string> problems = verify_batch(jobs, options);
    for (const std::string& p : problems) std::printf("%s\n", p.c_str());
    std::printf("verify: %zu jobs, %zu problem%s\n", jobs.size(), problems.size(), problems.size() == 1 ? "" : "s");
    return problems.empty() ? 0 : 1;
}

int run_batch_command(const BatchArgs& args, const CLI::App& cmd) {
    if (args.manifest.empty() == args.models.empty())
        throw InputError("give a MANIFEST or --models DIR (one of the two)");
    if (!args.verify.empty() && !args.output.empty()) throw InputError("--verify DIR: give it instead of -o DIR");
    if (args.output.empty() && !args.dry_run && args.verify.empty())
        throw InputError("-o DIR: the output directory is required");
    const BatchDefaults defaults = defaults_from(args, cmd);
    BatchOptions options = layout_options(args, cmd);
    std::vector<BatchJob> jobs =
        args.models.empty() ? load_manifest(args.manifest, defaults) : expand_jobs(find_models(args.models), defaults);
    check_styles(jobs);
    if (options.layout == BatchLayout::WebDataset) check_webdataset_keys(jobs);  // across every shard's jobs
    const size_t all = jobs.size();
    if (!args.shard.empty()) {
        int k = 1, n = 1;
        parse_shard(args.shard, k, n);
        jobs = shard(jobs, k, n);
    } else {
        jobs = batch_order(std::move(jobs));
    }
    if (!args.verify.empty()) return verify_command(jobs, options, args.verify);

    if (args.dry_run) {
        for (const BatchJob& j : jobs)
            std::printf("%s\t%s\t%s\t%s\t%dx%d\t%s\n", j.stem.c_str(), j.model.c_str(), j.style.c_str(),
                        j.view.name.c_str(), j.options.size.x, j.options.size.y, formats(j.outputs).c_str());
        std::fprintf(stderr, "inkshade: dry run: %zu of %zu jobs%s\n", jobs.size(), all,
                     args.shard.empty() ? "" : (" (shard " + args.shard + ")").c_str());
        return 0;
    }
    check_output_dir(args.output);

    options.output_dir = args.output;
    options.force = args.force;
    options.transforms_json = args.transforms_json;
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
    cmd->add_option("--styles", args->styles,
                    "styles where the manifest gives none, comma-separated (default: each model's own, as "
                    "`render` without --style: vrm for a glTF with MToon materials, else lambert)");
    cmd->add_option("--format", args->format, "outputs where the manifest gives none: png, svg or png,svg")
        ->capture_default_str();
    args->scene.add_to(*cmd, kBatch, /*model=*/false, false, " (where the manifest gives none)");
    cmd->add_option("--shard", args->shard, "render only shard K of N (K = 1..N; contiguous blocks of the job list)");
    cmd->add_option("--layout", args->layout,
                    "folder (DIR/STEM.png, ...) or webdataset (tar shards DIR/PREFIX-000000.tar, one sample a job)")
        ->capture_default_str();
    cmd->add_option("--shard-size", args->shard_size,
                    "webdataset: close a shard before it passes this size (1GB, 256MiB, bytes)")
        ->capture_default_str();
    cmd->add_option("--shard-prefix", args->shard_prefix,
                    "webdataset: shard file names PREFIX-000000.tar (with --shard K/N: PREFIX-KofN-000000.tar)")
        ->capture_default_str();
    cmd->add_option("--verify", args->verify,
                    "check DIR against the jobs instead of rendering: every job present and its files readable");
    cmd->add_flag("--force", args->force, "render complete jobs again (default: skip them)");
    cmd->add_flag("--transforms-json", args->transforms_json,
                  "at the end, write transforms.json (instant-ngp / nerfstudio cameras) in each output directory, "
                  "listing its complete jobs");
    cmd->add_flag("--dry-run", args->dry_run, "list the jobs (stem, model, style, view, size, formats) and exit");
    cmd->add_flag("-q,--quiet", args->quiet, "print failures and the summary only");
    return [args, cmd] { return run_batch_command(*args, *cmd); };
}

}  // namespace inkshade::cli
