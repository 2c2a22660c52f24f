#pragma once
// Runs a cost-vs-accuracy sweep off the UI thread: each sweep gets a thread with its own headless EGL context (the
// sweep's renderer, meter and bare draw live and die on it). The UI reads the points so far (the chart fills in
// live), the progress and stage, and cancels; the scene travels as shared_ptr<const Scene>, so a scene switch on the
// UI thread cannot free what the sweep reads. Destruction cancels and joins.
#include "scene/scene.h"
#include "sweep/sweep_runner.h"

#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

namespace shadowlab::editor {

class SweepWorker {
public:
    // `changed` runs on the sweep's thread after each finished point and when the sweep ends (the editor wakes its
    // host with it, so the chart fills in and the result shows without a timer).
    explicit SweepWorker(std::function<void()> changed = {}) : changedCallback_(std::move(changed)) {}
    ~SweepWorker();
    SweepWorker(const SweepWorker&) = delete;
    SweepWorker& operator=(const SweepWorker&) = delete;

    // Starts the sweep (the plan must have no error); false while one still runs.
    bool start(std::shared_ptr<const Scene> scene, const Settings& base, SweepPlan plan, SweepRunOptions options);
    void cancel() { progress_.cancel = true; }
    bool running() const;  // started and its result not yet polled
    float progress() const { return progress_.fraction.load(); }
    std::string stage() const { return progress_.stage(); }
    // The points measured so far, with the front over them.
    SweepResult snapshot() const;
    // The finished sweep, once (ok, cancelled with the points so far, or failed); then running() is false.
    std::optional<SweepResult> poll();

private:
    void join();

    const std::function<void()> changedCallback_;
    mutable std::mutex mutex_;
    std::thread thread_;
    bool busy_ = false;
    SweepResult live_;                    // the points so far
    std::optional<SweepResult> finished_;
    AccuracyProgress progress_;
};

}  // namespace shadowlab::editor
