// Dataset rendering: jobs (one model, view and style -> STEM.png / STEM.svg + STEM.json),
// manifests (CSV or JSON Lines), named view sets, deterministic shards and the runner behind
// `inkshade batch` (docs/cli.md#batch). Everything but run_batch needs no OpenGL.
#pragma once
#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "inkshade/aov.hpp"
#include "inkshade/camera.hpp"
#include "inkshade/options.hpp"
#include "inkshade/scene.hpp"

namespace inkshade {

// One camera placement; what CameraOptions leaves unset is auto-framed as `inkshade render`
// does (so a batch image equals the render of the same options).
struct BatchView {
    std::string name;  // the file-name part of the job's stem: "az045_el30", "cam1", "front"
    CameraOptions camera;
    std::string file_camera;  // a camera of the model file instead (SceneRequest::file_camera)
    // An orbit view turned about its view axis (roll_view); unset: none.
    std::optional<float> roll_degrees;
};

struct BatchOutputs {
    bool png = true;   // the style rendered by the GPU, as `inkshade render`
    bool svg = false;  // object-space lines with hidden parts removed, as `inkshade lines`
    // STEM.lines.json: the same drawing's polylines as `inkshade lines --lines-json` writes them
    // (with the job's lines-json-detail).
    bool lines_json = false;
};

struct BatchJob {
    std::string model;  // mesh file or builtin:NAME, as load_mesh takes it
    std::string style;  // built-in style name or .toml style file
    BatchView view;
    BatchOutputs outputs;
    std::string stem;    // outputs without extension, relative to the output directory
    std::string name;    // the model part of the stems (NAME), and of NAME.mesh.EXT (export-mesh)
    std::string source;  // where the job comes from, for messages: "jobs.csv:7", "--models"
    // The job's scene options: those of the option table that batch takes (inkshade/options.hpp:
    // size, samples, projection and framing, up axis, smooth angle, lights, AOVs, occlusion
    // levels of STEM.svg, pose, ...), as a manifest line or the defaults give them. The view's
    // placement is not in it: job_request joins the two.
    SceneRequest options = default_request(kBatch);
};

// The request that renders the job, as `inkshade render` and `inkshade lines` take it: its
// options with the view's placement (or the model file's camera, which projects by itself).
SceneRequest job_request(const BatchJob& job);

// The AOV files beside the job's image (its `aov` option; docs/aov.md).
AovSet job_aovs(const BatchJob& job);

// What a manifest line (or --models) leaves out.
struct BatchDefaults {
    std::string views = "35:20";     // parse_views; the auto-framing default view
    // Comma-separated; empty: each model's own, default_style_name (scene.hpp): `vrm` for a glTF
    // with MToon materials, else `lambert`, as `inkshade render` without --style.
    std::string styles;
    BatchOutputs outputs;
    SceneRequest options = default_request(kBatch);  // the table's batch options (--size, --fov, ...)
};

// A view list: items separated by ',' or ';' —
//   orbit:AxE, orbitAxE  A azimuths i*360/A (from 0) at each of E elevations k*90/E (from 0):
//                     orbit8x3 = 24 views at elevations 0, 30, 60
//   turntable:N[:EL]  N azimuths i*360/N at elevation EL (default 20)
//   fibonacci:N       the Fibonacci lattice's N directions (docs/cli.md), fibN_III
//   ico:LEVEL         an icosahedron's vertices subdivided LEVEL (0..4) times, icoL_III
//   random:N:SEED[:roll=DEG][:dist=LO-HI]  N uniform directions from SplitMix64(SEED), with a
//                     roll in [-DEG, DEG] and a distance in [LO, HI] when given, rndSEED_III
//   AZ:EL[:DIST]      one orbit view (degrees; distance in world units, default auto-framed)
//   camera=NAME       the model file's camera NAME (or index; glTF), as `render --camera`
// and, separated from other items by ';' only (its vectors hold commas), an explicit camera
//   eye=X,Y,Z [target=X,Y,Z] [up=X,Y,Z] [name=NAME]   (target default: the model centre)
// Views are named azAAA_elEE[_dD] (azimuth zero-padded to 3 digits), the sets on the sphere
// PREFIX_III (view index zero-padded to the digits of N - 1, at least 3), explicit cameras camN
// (N counts them from 1) unless named, file cameras camera-NAME (characters other than
// letters, digits, - _ . as _). Throws InputError("view 'ITEM': problem") for a bad
// item, and for a duplicate name or an empty list.
std::vector<BatchView> parse_views(const std::string& text);

// The name of a model in output stems: the file name without extension, or the builtin name
// with its options ("builtin:teapot:subdivisions=4" -> "teapot-subdivisions=4").
std::string model_name(const std::string& model);

// Manifest text, one job group per line: CSV with a header line (comma-separated, fields may
// be double-quoted) or JSON Lines (one object per line). The format is chosen by the extension
// of `source` (.csv; .jsonl, .ndjson, .json) and otherwise by the first character ('{' = JSON
// Lines). Blank lines and lines starting with '#' are skipped. Columns / keys: model (required),
// name, views (or view), styles (or style), format, output, and every option of the option
// table that batch takes (size, fov, margin, time, ...; inkshade/options.hpp); docs/cli.md#batch.
// Each line gives views x styles jobs with stems NAME/STYLE/VIEW (or `output` for one job).
// Throws InputError("SOURCE:LINE: problem") at the first bad line, and for a stem that two
// jobs share.
std::vector<BatchJob> parse_manifest(std::string_view text, const std::string& source,
                                     const BatchDefaults& defaults = {});

// Reads a manifest file and parses it (InputError when it cannot be read).
std::vector<BatchJob> load_manifest(const std::string& path, const BatchDefaults& defaults = {});

struct BatchModel {
    std::string path;  // as load_mesh takes it
    std::string name;  // the model part of the stems
};

// The mesh files (.obj .stl .ply .off .gltf .glb .vrm) under `directory`, recursively, sorted
// by path; named by their path relative to the directory without extension ("chairs/a").
// Throws InputError when the directory cannot be read.
std::vector<BatchModel> find_models(const std::string& directory);

// models x views x styles (defaults.views, defaults.styles), stems NAME/STYLE/VIEW. Throws
// InputError for a bad view list or style list, or a stem that two jobs share.
std::vector<BatchJob> expand_jobs(const std::vector<BatchModel>& models, const BatchDefaults& defaults,
                                  const std::string& source = "--models");

// The canonical job order: grouped by model (sorted by model path), in the given order
// within a model. run_batch renders in this order, so each model is loaded once.
std::vector<BatchJob> batch_order(std::vector<BatchJob> jobs);

// Shard k of n (1 <= k <= n): the k-th of n contiguous blocks of batch_order(jobs), block
// sizes differing by at most one (jobs [floor((k-1)*J/n), floor(k*J/n))). Contiguous, so a
// model's jobs stay in as few shards as possible and each shard loads few models. The shards
// of one job list partition it. Throws InputError for k or n out of range.
std::vector<BatchJob> shard(const std::vector<BatchJob>& jobs, int k, int n);

// "K/N" as --shard takes it. Throws InputError naming the problem.
void parse_shard(const std::string& text, int& k, int& n);

// 16 hex digits (FNV-1a 64) over everything that decides a job's files: model path and size
// in bytes (-1 when unknown), the style's full TOML text, view, image size, samples, outputs.
// Stored in the metadata: a changed style file, view or size gives a new hash, and the job is
// rendered again on resume.
std::string job_hash(const BatchJob& job, std::string_view style_text, int64_t model_bytes);

enum class BatchStatus { Done, Skipped, Failed };

// What run_batch reports after each job (and once per model that fails to load).
struct BatchEvent {
    BatchStatus status = BatchStatus::Done;
    // The job (for a model that failed to load, its first job); valid during the callback only.
    const BatchJob* job = nullptr;
    size_t jobs = 1;            // jobs this event settles (a failed model: all of its jobs)
    std::string reason;         // Failed: one line
    bool model_failed = false;  // the model could not be loaded (or drawn at all)
    size_t finished = 0;        // jobs settled so far, this event included
    size_t total = 0;           // jobs in the batch
    size_t rendered = 0;        // jobs rendered so far (Done)
    size_t to_render = 0;       // jobs that needed rendering when the batch started
    double seconds = 0.0;       // since the batch started
};
using BatchProgress = std::function<void(const BatchEvent&)>;

// How run_batch lays out the jobs' files in the output directory (docs/cli.md#batch).
enum class BatchLayout {
    Folder,      // DIR/STEM.png, DIR/STEM.json, ... as the stems name them
    WebDataset,  // tar shards DIR/PREFIX-000000.tar, ...: one sample per job, KEY.png, KEY.json, ...
};

// "folder" or "webdataset" as --layout takes it. Throws InputError naming the choices.
BatchLayout parse_layout(const std::string& text);

// A job's WebDataset sample key: its stem with every '.' as '_' (WebDataset splits a file name
// into key and extension at the first dot of its last path component): "box/toon/az022.5_el30"
// -> "box/toon/az022_5_el30".
std::string webdataset_key(const std::string& stem);

// Throws InputError("SOURCE: ...") when two jobs' stems give the same key.
void check_webdataset_keys(const std::vector<BatchJob>& jobs);

// A shard's size as --shard-size takes it: bytes, or a number with a unit, SI (kB, MB, GB,
// TB: powers of 1000) or binary (KiB, MiB, GiB, TiB), case ignored: "1GB", "256MiB",
// "1.5GB", "1000000". Throws InputError for zero, a negative or a malformed size.
uint64_t parse_shard_size(const std::string& text);

// The shard file prefix of worker K of N (--shard K/N; Python shard=(K, N)): PREFIX-KofN, K
// zero-padded to N's digits ("shard-03of16"), so workers sharing a directory write distinct
// shards; PREFIX alone for n = 0 (no --shard). Throws InputError for an empty prefix, one with
// a '/' or one starting with '.' (the temporaries' mark).
std::string webdataset_shard_prefix(const std::string& prefix, int k, int n);

// PREFIX-NNNNNN.tar (index zero-padded to 6 digits, WebDataset's shard naming).
std::string webdataset_shard_name(const std::string& prefix, size_t index);

struct BatchOptions {
    std::string output_dir;  // created when missing
    bool force = false;      // render complete jobs again
    BatchLayout layout = BatchLayout::Folder;
    // WebDataset layout: a shard is closed before the sample that would take it past this many
    // bytes (a sample bigger than it gets a shard of its own); shards are PREFIX-000000.tar, ...
    uint64_t shard_size = 1'000'000'000;
    std::string shard_prefix = "shard";
    // At the end of the run, each directory of the jobs' images gets transforms.json, listing
    // its complete jobs (a resumed run's too; docs/cli.md#batch).
    bool transforms_json = false;
    // Checked between jobs: once true, run_batch returns after the job in progress (a signal
    // handler may set it). Nothing partial is left: every file is written atomically.
    const std::atomic<bool>* stop = nullptr;
};

struct BatchFailure {
    std::string stem, model, reason;
};

struct BatchSummary {
    size_t total = 0, done = 0, skipped = 0, failed = 0;
    bool interrupted = false;  // options.stop ended it; total - done - skipped - failed not run
    double seconds = 0.0;
    std::vector<BatchFailure> failures;
};

// Renders the jobs into options.output_dir: per job STEM.png and/or STEM.svg, then STEM.json
// (metadata; docs/cli.md#batch), each written atomically. A job is complete when its metadata
// and all its outputs exist and the metadata's job hash is the job's: complete jobs are
// skipped unless options.force. One renderer (one GL context) for the whole batch; each model
// is loaded once, the next one on a worker thread while the current one renders. A model that
// cannot be loaded fails its jobs and the batch goes on; so does a job that fails. Throws
// RuntimeError only when no OpenGL context can be made or the output directory cannot be.
// In the WebDataset layout the jobs are written into a staging folder, then packed one sample a
// job into the open shard (a temporary, renamed when the shard is closed); a job is complete
// when a closed shard holds its sample with its job hash. Shards holding a sample that is no
// longer a job with that hash are removed with every later one, and their jobs rendered again;
// the last shard is reopened (copied, then extended) while the next sample still fits in it.
// Last, with options.transforms_json (folder layout only), each directory of the jobs' images
// gets transforms.json.
BatchSummary run_batch(const std::vector<BatchJob>& jobs, const BatchOptions& options,
                       const BatchProgress& progress = {});

// Checks a batch's output (options.output_dir, in options.layout) against its jobs: every job
// present with its metadata's job hash, every file its metadata lists present, and each file
// readable (PNG signature and IEND chunk, JSON parses, EXR magic and every chunk inside the file,
// SVG closed); in the WebDataset layout also every shard readable and no sample twice or
// unknown. One line per problem ("STEM: what is wrong", "SHARD: what is wrong"), none when the
// output is complete.
std::vector<std::string> verify_batch(const std::vector<BatchJob>& jobs, const BatchOptions& options);

}  // namespace inkshade
