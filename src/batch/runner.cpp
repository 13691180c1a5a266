// run_batch (inkshade/batch.hpp): the jobs of a batch in model order through one renderer,
// the next model loaded on a worker thread while the current one renders.
#include <chrono>
#include <filesystem>
#include <future>
#include <map>
#include <memory>
#include <set>

#include "batch/job_style.hpp"
#include "batch/mesh_export.hpp"
#include "batch/metadata.hpp"
#include "batch/transforms_json.hpp"
#include "batch/view_roll.hpp"
#include "batch/webdataset_shards.hpp"
#include "inkshade/batch.hpp"
#include "inkshade/error.hpp"
#include "inkshade/image.hpp"
#include "inkshade/io.hpp"
#include "inkshade/line_drawing.hpp"
#include "inkshade/renderer.hpp"
#include "inkshade/scene.hpp"
#include "inkshade/style.hpp"
#include "io/atomic_file.hpp"

namespace inkshade {

namespace {

using batch::model_bytes;
using batch::resolve_style;
using batch::ResolvedStyle;
using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// A model ready to render: loaded, and with its line extractor when a job writes SVG (its
// construction copies and checks the mesh: CPU work that overlaps the previous model's renders).
struct LoadedModel {
    std::unique_ptr<Mesh> mesh;
    std::unique_ptr<LineExtractor> extractor;
    std::string error;
    double milliseconds = 0.0;
};

LoadedModel load_model(const std::string& path, bool lines, LoadOptions options) {
    LoadedModel m;
    const auto start = Clock::now();
    try {
        m.mesh = std::make_unique<Mesh>(load_mesh(path, options));
        if (m.mesh->triangles.empty()) throw InputError(path, "the mesh has no triangles");
        if (lines) m.extractor = std::make_unique<LineExtractor>(*m.mesh);
    } catch (const std::bad_alloc&) {
        m.mesh.reset();
        m.error = "out of memory";
    } catch (const std::exception& e) {
        m.mesh.reset();
        m.error = e.what();
    }
    if (!m.error.empty() && !m.error.starts_with(path)) m.error = path + ": " + m.error;
    m.milliseconds = ms_since(start);
    return m;
}

// The jobs of one model, in batch order.
struct ModelGroup {
    std::string model;
    LoadOptions load;  // the jobs' auto-smooth, normal weighting and pose: one load per set
    int64_t bytes = -1;
    std::vector<size_t> jobs;     // indices into the ordered job list
    std::vector<size_t> pending;  // those to render
    bool svg = false;             // a pending job writes SVG
    bool png = false;             // a pending job writes PNG or AOVs (needs the renderer)
};

class BatchRun {
public:
    BatchRun(const std::vector<BatchJob>& jobs, const BatchOptions& options, const BatchProgress& progress)
        : jobs_(batch_order(jobs)), options_(options), progress_(progress) {}

    BatchSummary run() {
        summary_.total = jobs_.size();
        std::error_code ec;
        std::filesystem::create_directories(options_.output_dir, ec);
        std::error_code dir_ec;
        if (!std::filesystem::is_directory(options_.output_dir, dir_ec))
            throw RuntimeError(options_.output_dir + ": cannot create the output directory" +
                               (ec ? " (" + ec.message() + ")" : ""));
        if (options_.layout == BatchLayout::WebDataset) {
            check_webdataset_keys(jobs_);
            shards_ = std::make_unique<batch::WebDatasetShards>(options_.output_dir, options_.shard_prefix,
                                                                options_.shard_size);
        }
        plan();

        // One load ahead: while the current model renders, the next one with work loads.
        std::future<LoadedModel> next;
        size_t next_group = groups_.size();
        auto prefetch_after = [&](size_t g) {
            for (size_t n = g + 1; n < groups_.size(); ++n) {
                if (groups_[n].pending.empty()) continue;
                next_group = n;
                next = std::async(std::launch::async, load_model, groups_[n].model, groups_[n].svg, groups_[n].load);
                return;
            }
        };
        for (size_t g = 0; g < groups_.size() && !stopping(); ++g) {
            ModelGroup& group = groups_[g];
            report_settled(group);
            if (group.pending.empty()) continue;
            LoadedModel model;
            if (next.valid() && next_group == g)
                model = next.get();
            else
                model = load_model(group.model, group.svg, group.load);
            prefetch_after(g);
            render_model(group, model);
        }
        if (shards_) {  // the jobs written so far are complete: the open shard is closed, not lost
            shards_->close();
            std::filesystem::remove_all(shards_->staging(), ec);
        }
        if (options_.transforms_json && !shards_) batch::write_transforms_json(options_.output_dir, jobs_, hashes_);
        summary_.interrupted = stopping() && settled_ < jobs_.size();
        summary_.seconds = ms_since(start_) / 1000.0;
        return summary_;  // `next` waits here for a load still running (interrupted)
    }

private:
    bool stopping() const { return options_.stop && options_.stop->load(); }

    // Styles, groups, hashes and which jobs are complete, before any work.
    void plan() {
        for (const BatchJob& job : jobs_)
            if (!styles_.count(job.style)) styles_.emplace(job.style, resolve_style(job.style));
        hashes_.resize(jobs_.size());
        complete_.assign(jobs_.size(), false);
        for (size_t i = 0; i < jobs_.size(); ++i) {
            const BatchJob& job = jobs_[i];
            const ResolvedStyle& style = styles_.at(job.style);
            // The angle and weighting make_scene resolves for the job (Scene::load_options): a
            // model is loaded once for each pair its jobs use (jobs are style-major, so at most
            // once a style).
            const SceneRequest& o = job.options;
            const LoadOptions load{
                .smooth_angle = o.smooth_angle.value_or(style.smooth_angle.value_or(LoadOptions{}.smooth_angle)),
                .normal_weighting = style.normal_weighting,
                .pose = {.animation = o.animation,
                         .time = o.time.value_or(0.0f),
                         .expressions = o.expressions,
                         .morphs = o.morphs,
                         .spring_bones = o.spring_bones}};
            if (groups_.empty() || groups_.back().model != job.model ||
                groups_.back().load.smooth_angle != load.smooth_angle ||
                groups_.back().load.normal_weighting != load.normal_weighting ||
                groups_.back().load.pose != load.pose) {
                groups_.emplace_back();
                groups_.back().model = job.model;
                groups_.back().load = load;
                groups_.back().bytes = model_bytes(job.model);
            }
            ModelGroup& group = groups_.back();
            group.jobs.push_back(i);
            if (style.error.empty()) hashes_[i] = job_hash(job, style.toml, group.bytes);
        }
        find_complete();
        for (ModelGroup& group : groups_)
            for (size_t i : group.jobs) {
                // A job whose style failed is reported as failed when the group comes up.
                if (complete_[i] || !styles_.at(jobs_[i].style).error.empty()) continue;
                group.pending.push_back(i);
                group.svg |= jobs_[i].outputs.svg || jobs_[i].outputs.lines_json;
                group.png |= jobs_[i].outputs.png || !jobs_[i].options.aovs.empty();
                ++to_render_;
            }
    }

    // Folders: the job's metadata and outputs on disk; WebDataset: its sample in a kept shard.
    void find_complete() {
        if (!shards_) {
            for (size_t i = 0; i < jobs_.size(); ++i)
                complete_[i] = !hashes_[i].empty() && !options_.force &&
                               batch::job_complete(options_.output_dir, jobs_[i], hashes_[i]);
            return;
        }
        std::map<std::string, std::string> current;  // key -> job hash
        for (size_t i = 0; i < jobs_.size(); ++i)
            if (!hashes_[i].empty()) current[webdataset_key(jobs_[i].stem)] = hashes_[i];
        const std::set<std::string> kept = shards_->resume(current, options_.force);
        for (size_t i = 0; i < jobs_.size(); ++i) complete_[i] = kept.count(webdataset_key(jobs_[i].stem)) > 0;
    }

    void emit(BatchStatus status, size_t job, size_t count, const std::string& reason, bool model_failed) {
        settled_ += count;
        BatchEvent e;
        e.status = status;
        e.job = &jobs_[job];
        e.jobs = count;
        e.reason = reason;
        e.model_failed = model_failed;
        e.finished = settled_;
        e.total = jobs_.size();
        e.rendered = summary_.done;
        e.to_render = to_render_;
        e.seconds = ms_since(start_) / 1000.0;
        if (progress_) progress_(e);
    }

    void fail(size_t job, const std::string& reason) {
        ++summary_.failed;
        summary_.failures.push_back({jobs_[job].stem, jobs_[job].model, reason});
        emit(BatchStatus::Failed, job, 1, reason, false);
    }

    // Complete jobs and jobs whose style could not be loaded, as the group comes up.
    void report_settled(const ModelGroup& group) {
        for (size_t i : group.jobs) {
            const ResolvedStyle& style = styles_.at(jobs_[i].style);
            if (!style.error.empty()) {
                fail(i, style.error);
            } else if (complete_[i]) {
                ++summary_.skipped;
                emit(BatchStatus::Skipped, i, 1, "", false);
            }
        }
    }

    void fail_model(const ModelGroup& group, const std::string& reason) {
        summary_.failed += group.pending.size();
        for (size_t i : group.pending) summary_.failures.push_back({jobs_[i].stem, jobs_[i].model, reason});
        emit(BatchStatus::Failed, group.pending.front(), group.pending.size(), reason, true);
    }

    void render_model(const ModelGroup& group, LoadedModel& model) {
        if (!model.mesh) return fail_model(group, model.error);
        try {
            batch::write_mesh_files(options_.output_dir, jobs_, group.pending, *model.mesh);  // export-mesh
        } catch (const std::exception& e) {
            return fail_model(group, e.what());
        }
        if (group.model != sequences_model_) {  // jobs are model-major: a model's sequences end here
            sequences_.clear();
            sequences_model_ = group.model;
        }
        if (group.png) {
            try {
                if (!renderer_) renderer_ = std::make_unique<Renderer>();  // throws without OpenGL
                renderer_->set_mesh(*model.mesh);
            } catch (const InputError& e) {
                return fail_model(group, group.model + ": " + e.what());
            }
            gl_renderer_ = renderer_->gl_renderer();
        }
        const BoundingBox bounds = model.mesh->bounds();
        // Job i's files are encoded and written on a worker while job i+1 renders; its event
        // follows once they are (the metadata last), always from this thread.
        std::future<void> writing;
        size_t written = 0;
        auto finish_write = [&] {
            if (!writing.valid()) return;
            try {
                writing.get();
                ++summary_.done;
                emit(BatchStatus::Done, written, 1, "", false);
            } catch (const std::bad_alloc&) {
                fail(written, "out of memory");
            } catch (const std::exception& e) {
                fail(written, e.what());
            }
        };
        for (size_t i : group.pending) {
            if (stopping()) break;
            try {
                auto files = std::make_shared<JobFiles>(render_job(i, group, model, bounds));
                finish_write();
                written = i;
                writing = std::async(std::launch::async, [this, files] { write_job(*files); });
            } catch (const std::bad_alloc&) {
                finish_write();
                fail(i, "out of memory");
            } catch (const std::exception& e) {
                finish_write();
                fail(i, e.what());
            }
        }
        finish_write();
    }

    // What one job writes, made on the GL thread, written by write_job.
    struct JobFiles {
        batch::JobRecord record;
        Image image;          // when the job writes PNG
        LineDrawing drawing;  // when it writes SVG
        glm::vec4 background{1.0f};
        AovImages aovs;  // when it writes AOVs
        CameraRecord camera;
    };

    JobFiles render_job(size_t i, const ModelGroup& group, LoadedModel& model, const BoundingBox& bounds) {
        const BatchJob& job = jobs_[i];
        // The job as `inkshade render` and `inkshade lines` take it: the same request path.
        SceneRequest request = job_request(job);
        request.model = job.model;
        request.style = job.style;
        request.outputs = {.image = true, .line_drawing = true};
        Scene scene = make_scene(request);
        if (job.view.roll_degrees) batch::roll_view(scene.camera, *job.view.roll_degrees);  // random:...:roll=
        scene.apply_file_scene(*model.mesh);  // a bad camera fails the job; its warnings are not kept
        const Camera camera = scene.frame(*model.mesh);
        JobFiles files;
        batch::JobRecord& record = files.record;
        record.job = &job;
        record.hash = hashes_[i];
        record.model_bytes = group.bytes;
        record.vertices = model.mesh->vertex_count();
        record.triangles = model.mesh->triangle_count();
        record.camera = camera;
        record.style_toml = styles_.at(job.style).toml;
        for (const LineSettings& l : scene.style.lines) record.lines.push_back(l.type);
        for (const LineSettings& l : scene.vector_lines) record.svg_lines.push_back(l.type);
        record.timings_ms.emplace_back("load", model.milliseconds);
        files.background = scene.style.background;
        // The job's frame of its sequence: the views and animation times of one model, style and
        // size, in batch order (docs/lines.md, "Temporal coherence"; only `coherence` layers read it).
        Sequences& sequence =
            sequences_[job.style + "\n" + std::to_string(request.size.x) + "x" + std::to_string(request.size.y)];
        scene.options.stroke_sequence = &sequence.image;
        if (job.outputs.png || !scene.aovs.empty()) {
            const auto start = Clock::now();
            const Light light = scene.light(bounds, camera);
            if (scene.aovs.empty()) {
                files.image = render_scene(*renderer_, scene, camera, light);
            } else {
                files.image = render_scene(*renderer_, scene, camera, light, files.aovs);
                files.camera = camera_record(scene, camera, bounds);
            }
            record.timings_ms.emplace_back("render", ms_since(start));
            record.gl_renderer = gl_renderer_;
        }
        if (job.outputs.svg || job.outputs.lines_json) {
            const auto start = Clock::now();
            files.drawing = draw_scene_lines(*model.extractor, scene, camera, nullptr, &sequence.svg);
            record.timings_ms.emplace_back("svg", ms_since(start));
        }
        return files;
    }

    // Into the output directory, or the staging folder whose files are then packed into a shard
    // (the same files: a sample holds the bytes the folder layout would).
    void write_job(JobFiles& files) const {
        const BatchJob& job = *files.record.job;
        const std::string& root = shards_ ? shards_->staging() : options_.output_dir;
        const auto start = Clock::now();
        std::filesystem::create_directories(std::filesystem::path(batch::job_file(root, job, "")).parent_path());
        if (job.outputs.png) write_png(batch::job_file(root, job, ".png"), files.image, job.options.bit_depth);
        if (const AovSet aovs = job_aovs(job); !aovs.empty()) {
            files.record.aov_files =
                write_aov_files(batch::job_file(root, job, ".png"), aovs, files.aovs, files.camera);
            files.record.fields = files.aovs.field_scales;
        }
        if (job.outputs.svg) write_svg(batch::job_file(root, job, ".svg"), files.drawing, files.background);
        if (job.outputs.lines_json)
            io::write_file_atomic(batch::job_file(root, job, ".lines.json"),
                                  format_lines_json(files.drawing, job.options.lines_json_detail));
        files.record.timings_ms.emplace_back("write", ms_since(start));
        // Last: the metadata marks the job complete (batch::job_complete).
        io::write_file_atomic(batch::job_file(root, job, ".json"), batch::format_metadata(files.record));
        if (shards_) shards_->add(batch::take_staged_sample(root, job.stem));
    }

    const std::vector<BatchJob> jobs_;
    const BatchOptions& options_;
    const BatchProgress& progress_;
    const Clock::time_point start_ = Clock::now();
    std::map<std::string, ResolvedStyle> styles_;
    std::vector<ModelGroup> groups_;
    std::vector<std::string> hashes_;
    std::vector<bool> complete_;
    size_t to_render_ = 0, settled_ = 0;
    std::unique_ptr<Renderer> renderer_;
    std::string gl_renderer_;
    std::unique_ptr<batch::WebDatasetShards> shards_;  // the WebDataset layout's shards
    // The previous frame's strokes per sequence of the current model, for the image and the SVG
    // (drawn by two extractors, each its own sequence).
    struct Sequences {
        StrokeSequence image, svg;
    };
    std::map<std::string, Sequences> sequences_;
    std::string sequences_model_;
    BatchSummary summary_;
};

}  // namespace

BatchSummary run_batch(const std::vector<BatchJob>& jobs, const BatchOptions& options, const BatchProgress& progress) {
    return BatchRun(jobs, options, progress).run();
}

}  // namespace inkshade
