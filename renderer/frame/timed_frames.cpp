#include "frame/timed_frames.h"

#include <algorithm>
#include <chrono>

namespace shadowlab {

double medianOf(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

RepeatedTiming timeRepeated(int frames, const std::function<std::string(std::vector<double>& ms)>& frame) {
    RepeatedTiming result;
    std::vector<std::vector<double>> slots;
    double wallTotal = 0.0;
    for (int run = -kWarmUpFrames; run < frames; ++run) {
        std::vector<double> ms;
        const auto start = std::chrono::steady_clock::now();
        result.error = frame(ms);
        const double wall =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        if (!result.error.empty()) return result;
        if (run < 0) continue;
        wallTotal += wall;
        if (slots.size() < ms.size()) slots.resize(ms.size());
        for (std::size_t i = 0; i < ms.size(); ++i) slots[i].push_back(ms[i]);
    }
    for (std::vector<double>& slot : slots) {
        result.minMs.push_back(slot.empty() ? 0.0 : *std::min_element(slot.begin(), slot.end()));
        result.medianMs.push_back(medianOf(std::move(slot)));
    }
    result.wallMsPerRun = wallTotal / std::max(frames, 1);
    return result;
}

TimedFrames timeFrames(Renderer& renderer, const Scene& scene, const Settings& settings, const Camera& camera,
                       RenderTarget& target, int frames) {
    TimedFrames result;
    const RepeatedTiming timing = timeRepeated(frames, [&](std::vector<double>& ms) -> std::string {
        renderer.invalidateShadowMap();
        FrameStats stats = renderer.render(scene, settings, camera, target);
        renderer.waitForTimings(stats);
        if (!stats.ok) return stats.error;
        ms = {stats.shadowPass.milliseconds.value_or(0.0), stats.mainPass.milliseconds.value_or(0.0)};
        result.last = std::move(stats);
        return "";
    });
    result.error = timing.error;
    result.ok = timing.error.empty();
    if (!result.ok) return result;
    result.shadowMs = timing.medianMs.size() > 0 ? timing.medianMs[0] : 0.0;
    result.mainMs = timing.medianMs.size() > 1 ? timing.medianMs[1] : 0.0;
    result.shadowMinMs = timing.minMs.size() > 0 ? timing.minMs[0] : 0.0;
    result.mainMinMs = timing.minMs.size() > 1 ? timing.minMs[1] : 0.0;
    result.wallMsPerFrame = timing.wallMsPerRun;
    result.timingSource = result.last.timingSource;
    return result;
}

}  // namespace shadowlab
