#pragma once
// Runs accuracy measurements and bias searches off the UI thread. The worker thread starts with the first job and
// then owns, for the editor's lifetime, its own headless EGL context and AccuracyMeter (whose caches make the next
// measurement of the same view cost one tool frame). The UI thread starts a job, reads its progress and the search's
// path while it runs, and polls for the result; the scene travels as shared_ptr<const Scene>, so a scene switch on
// the UI thread cannot free or change what the worker reads. Destruction cancels the job and joins the thread.
#include "accuracy/accuracy_meter.h"
#include "accuracy/bias_tuner.h"
#include "accuracy/flicker.h"
#include "frame/camera.h"
#include "scene/scene.h"
#include "settings/settings.h"

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace shadowlab::editor {

// Live: the numbers alone, counted on the GPU against the reference an earlier Measure cached (AccuracyMeter::
// remeasure): one tool frame, for Auto while a slider moves. Flicker: the view played under a motion (flicker.h).
enum class AccuracyJobKind { Measure, SuggestBias, Live, Flicker };

struct AccuracyJob {
    AccuracyJobKind kind = AccuracyJobKind::Measure;
    std::shared_ptr<const Scene> scene;
    Settings settings;     // the whole picture's settings; the job describes `light` of them
    std::size_t light = 0; // in the effective lights: measured, tuned or moved (Flicker) alone
    Camera camera;
    int width = 0, height = 0;
    double maxAcnePercent = 0.1;  // SuggestBias: the acne limit
    TuneSearch search = TuneSearch::Bias;  // SuggestBias: the bias, the technique's trade-off, both, or auto (tune's --search)
    Motion motion;                // Flicker: what moves, by how much, for how many frames
};

struct AccuracyJobResult {
    std::uint64_t id = 0;
    AccuracyJobKind kind = AccuracyJobKind::Measure;
    AccuracyReport report;            // Measure: the view; SuggestBias: the best setting's measurement
    std::optional<TuneResult> tune;   // SuggestBias only
    std::optional<FlickerReport> flicker;  // Flicker only (report then carries only ok / error)
    double seconds = 0.0;             // wall time of the job on the worker
};

class AccuracyWorker {
public:
    // `finished` runs on the worker thread once a result is ready to poll (the editor wakes its host with it).
    explicit AccuracyWorker(std::function<void()> finished = {});
    ~AccuracyWorker();  // cancels a running job and joins the thread (its GL context ends on it)
    AccuracyWorker(const AccuracyWorker&) = delete;
    AccuracyWorker& operator=(const AccuracyWorker&) = delete;

    // Starts a job; returns its id, or 0 when a job is still running (one at a time).
    std::uint64_t start(AccuracyJob job);
    void cancel();                 // the running job stops soon and reports "cancelled"
    bool running() const;          // a job was started and its result not yet polled
    float progress() const { return progress_.fraction.load(); }
    std::string stage() const { return progress_.stage(); }
    AccuracyJobKind runningKind() const;
    // The bias search's candidates so far (of the running or the newest search).
    std::vector<TuneStep> steps() const;
    // The finished job's result, once; then running() is false.
    std::optional<AccuracyJobResult> poll();
    // For tests: runs on the worker thread after each candidate of a bias search is recorded, before the next one is
    // measured, with the job's progress (a test holds it there until progress.cancel to act while the search
    // certainly runs). Set it while no job runs.
    void setStepHook(std::function<void(const AccuracyProgress&)> hook);

private:
    void loop();
    AccuracyJobResult run(const AccuracyJob& job, std::uint64_t id);

    const std::function<void()> finishedCallback_;
    std::function<void(const AccuracyProgress&)> stepHook_;  // guarded by mutex_

    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::thread thread_;
    bool quit_ = false;
    std::optional<AccuracyJob> pending_;       // handed to the thread
    std::uint64_t pendingId_ = 0, lastId_ = 0;
    bool busy_ = false;                        // started and not yet polled
    AccuracyJobKind kind_ = AccuracyJobKind::Measure;
    std::optional<AccuracyJobResult> finished_;
    std::vector<TuneStep> steps_;
    AccuracyProgress progress_;

    // Worker-thread only: created on the first job, kept until the thread ends.
    struct Gl;
    std::unique_ptr<Gl> gl_;
    std::string glError_;                      // why the context or meter could not start (then every job fails)
    std::shared_ptr<const Scene> measuredScene_;  // keeps the meter's cached scene alive and identifiable
};

}  // namespace shadowlab::editor
