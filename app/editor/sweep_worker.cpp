#include "editor/sweep_worker.h"

#include "context/headless_context.h"

#include <exception>

namespace shadowlab::editor {

SweepWorker::~SweepWorker() {
    progress_.cancel = true;
    join();
}

void SweepWorker::join() {
    if (thread_.joinable()) thread_.join();
}

bool SweepWorker::start(std::shared_ptr<const Scene> scene, const Settings& base, SweepPlan plan,
                        SweepRunOptions options) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (busy_) return false;
        busy_ = true;
        finished_.reset();
        live_ = SweepResult{};
        live_.axes = plan.axes;
        live_.width = options.width;
        live_.height = options.height;
        live_.frames = options.frames;
        live_.presetPoint = plan.basePoint;
    }
    join();  // the previous sweep's thread has finished (its result was polled)
    progress_.cancel = false;
    progress_.fraction = 0.0f;
    progress_.base = 0.0f;
    progress_.span = 1.0f;
    progress_.setStage("starting the sweep's GL context");
    const std::size_t pointCount = plan.points.size();
    thread_ = std::thread([this, scene = std::move(scene), base, plan = std::move(plan), options, pointCount] {
        SweepResult result;
        try {
            HeadlessContext context;
            result = runSweep(*scene, base, plan, options,
                              [this, pointCount](const SweepPointResult& point, std::size_t, std::size_t) {
                                  {
                                      std::lock_guard<std::mutex> lock(mutex_);
                                      if (point.index >= pointCount)
                                          live_.preset = point;  // the preset's own extra point (the marker)
                                      else
                                          live_.points.push_back(point);
                                      markParetoFront(live_);
                                  }
                                  if (changedCallback_) changedCallback_();
                              },
                              &progress_);
        } catch (const std::exception& e) {
            result.ok = false;
            result.error = std::string("sweep: ") + e.what();
        }
        {
            std::lock_guard<std::mutex> lock(mutex_);
            if (!result.ok) {
                // Keep what was measured: a cancelled sweep still charts its points.
                SweepResult partial = live_;
                partial.ok = false;
                partial.cancelled = result.cancelled;
                partial.error = result.error;
                result = std::move(partial);
            }
            live_ = result;
            finished_ = std::move(result);
        }
        if (changedCallback_) changedCallback_();
    });
    return true;
}

bool SweepWorker::running() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return busy_;
}

SweepResult SweepWorker::snapshot() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return live_;
}

std::optional<SweepResult> SweepWorker::poll() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!finished_) return std::nullopt;
    std::optional<SweepResult> result = std::move(finished_);
    finished_.reset();
    busy_ = false;
    return result;
}

}  // namespace shadowlab::editor
