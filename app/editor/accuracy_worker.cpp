#include "editor/accuracy_worker.h"

#include "accuracy/light_isolation.h"
#include "context/headless_context.h"

#include <chrono>
#include <exception>

namespace shadowlab::editor {

struct AccuracyWorker::Gl {
    HeadlessContext context;  // declared first: the meter's GL objects go before the context does
    AccuracyMeter meter;
};

AccuracyWorker::AccuracyWorker(std::function<void()> finished) : finishedCallback_(std::move(finished)) {}

AccuracyWorker::~AccuracyWorker() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        quit_ = true;
        progress_.cancel = true;
    }
    wake_.notify_all();
    if (thread_.joinable()) thread_.join();
}

std::uint64_t AccuracyWorker::start(AccuracyJob job) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (busy_) return 0;
        busy_ = true;
        kind_ = job.kind;
        pendingId_ = ++lastId_;
        pending_ = std::move(job);
        finished_.reset();
        if (kind_ == AccuracyJobKind::SuggestBias) steps_.clear();
        progress_.cancel = false;
        progress_.fraction = 0.0f;
        progress_.base = 0.0f;
        progress_.span = 1.0f;
        progress_.setStage(gl_ ? "queued" : "starting the accuracy context");
        if (!thread_.joinable()) thread_ = std::thread([this] { loop(); });
    }
    wake_.notify_all();
    return lastId_;
}

void AccuracyWorker::cancel() { progress_.cancel = true; }

bool AccuracyWorker::running() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return busy_;
}

AccuracyJobKind AccuracyWorker::runningKind() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return kind_;
}

std::vector<TuneStep> AccuracyWorker::steps() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return steps_;
}

void AccuracyWorker::setStepHook(std::function<void(const AccuracyProgress&)> hook) {
    std::lock_guard<std::mutex> lock(mutex_);
    stepHook_ = std::move(hook);
}

std::optional<AccuracyJobResult> AccuracyWorker::poll() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!finished_) return std::nullopt;
    std::optional<AccuracyJobResult> result = std::move(finished_);
    finished_.reset();
    busy_ = false;
    return result;
}

void AccuracyWorker::loop() {
    for (;;) {
        AccuracyJob job;
        std::uint64_t id = 0;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            wake_.wait(lock, [&] { return quit_ || pending_.has_value(); });
            if (quit_) break;
            job = std::move(*pending_);
            pending_.reset();
            id = pendingId_;
        }
        AccuracyJobResult result = run(job, id);
        {
            std::lock_guard<std::mutex> lock(mutex_);
            finished_ = std::move(result);
        }
        if (finishedCallback_) finishedCallback_();
    }
    // The meter and context end on the thread they were current on.
    measuredScene_.reset();
    gl_.reset();
}

AccuracyJobResult AccuracyWorker::run(const AccuracyJob& job, std::uint64_t id) {
    const auto start = std::chrono::steady_clock::now();
    AccuracyJobResult result;
    result.id = id;
    result.kind = job.kind;
    auto fail = [&](std::string why) {
        result.report.ok = false;
        result.report.cancelled = why == "cancelled";
        result.report.error = std::move(why);
        if (job.kind == AccuracyJobKind::SuggestBias) {
            result.tune.emplace();
            result.tune->error = result.report.error;
            result.tune->cancelled = result.report.cancelled;
        }
        return result;
    };

    if (!gl_ && glError_.empty()) {
        try {
            gl_ = std::make_unique<Gl>();
        } catch (const std::exception& e) {
            glError_ = std::string("the accuracy worker could not start: ") + e.what();
        }
    }
    if (!gl_) return fail(glError_);
    if (!job.scene) return fail("no scene to measure");
    if (progress_.cancel.load()) return fail("cancelled");
    // The meter caches by scene address: a different scene drops its caches, and the old one stays alive until then.
    if (measuredScene_ != job.scene) {
        gl_->meter.sceneChanged();
        measuredScene_ = job.scene;
    }

    // The chosen light alone: its shadow factor is the one it has in the full frame (light_isolation.h).
    std::string isolateError;
    const std::optional<Settings> one = isolateLight(job.settings, *job.scene, job.light, isolateError);
    if (!one) return fail(isolateError);

    try {
        if (job.kind == AccuracyJobKind::Live) {
            result.report = gl_->meter.remeasure(*job.scene, *one, job.camera, job.width, job.height);
        } else if (job.kind == AccuracyJobKind::Flicker) {
            progress_.setStage("playing the motion");
            Motion motion = job.motion;
            motion.light = job.light;
            FlickerReport flicker = measureFlicker(gl_->meter, *job.scene, job.settings, job.camera, job.width,
                                                   job.height, motion, &progress_);
            result.report.ok = flicker.ok;
            result.report.cancelled = flicker.cancelled;
            result.report.error = flicker.error;
            result.flicker = std::move(flicker);
        } else if (job.kind == AccuracyJobKind::Measure) {
            progress_.setStage("measuring");
            result.report = gl_->meter.measure(*job.scene, *one, job.camera, job.width, job.height, &progress_);
            result.report.soft.light = job.light;  // the meter saw it as light 0 of `one`
        } else {
            TuneResult tune = tuneBias(gl_->meter, *job.scene, *one, job.camera, job.width, job.height,
                                       job.maxAcnePercent, &progress_, [this](const TuneStep& step) {
                                           std::function<void(const AccuracyProgress&)> hook;
                                           {
                                               std::lock_guard<std::mutex> lock(mutex_);
                                               steps_.push_back(step);
                                               hook = stepHook_;
                                           }
                                           if (hook) hook(progress_);
                                       },
                                       TuneScope{job.search, true});  // one light: its global keys too
            result.report = tune.report;
            if (!tune.ok) {
                result.report.ok = false;
                result.report.cancelled = tune.cancelled;
                result.report.error = tune.error;
            }
            result.tune = std::move(tune);
        }
    } catch (const std::exception& e) {
        return fail(std::string("accuracy: ") + e.what());
    }
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace shadowlab::editor
