#include "timing/repeated_timing.h"

#include <algorithm>
#include <chrono>

namespace shadowlab {

double medianOf(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

namespace {
double nowMs() {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
}  // namespace

WarmUp::WarmUp(double minimumMs) : minimumMs_(minimumMs) {}

bool WarmUp::running() {
    if (startMs_ < 0.0) startMs_ = nowMs();
    const bool enough = frames_ >= kMaxWarmUpFrames ||
                        (frames_ >= kWarmUpFrames && nowMs() - startMs_ >= minimumMs_);
    if (!enough) ++frames_;
    return !enough;
}

RepeatedTiming timeRepeated(int frames, const std::function<std::string(std::vector<double>& ms)>& frame,
                            double warmUpMs) {
    RepeatedTiming result;
    std::vector<std::vector<double>> slots;
    double wallTotal = 0.0;
    WarmUp warmUp(warmUpMs);
    for (int run = 0; run < frames;) {
        const bool thrownAway = warmUp.running();
        std::vector<double> ms;
        const auto start = std::chrono::steady_clock::now();
        result.error = frame(ms);
        const double wall =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        if (!result.error.empty()) return result;
        if (thrownAway) {
            ++result.warmUpRuns;
            continue;
        }
        ++run;
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

}  // namespace shadowlab
