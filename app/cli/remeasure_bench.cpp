#include "cli/remeasure_bench.h"

#include "settings/settings_fields.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

namespace shadowlab::cli {

namespace {

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

// The settings of round i: the bias moves every round (through the key table, like a slider).
Settings withBias(const Settings& settings, double base, double step, int round) {
    Settings s = settings;
    const double bias = base + step * double(1 + round % 2);
    char text[64];
    std::snprintf(text, sizeof text, "shadow.depthBias=%.9g", bias);
    applySettingOverride(s, text);
    return s;
}

bool sameCounts(const AccuracyCounts& a, const AccuracyCounts& b) {
    return a.measured == b.measured && a.lit == b.lit && a.shadowed == b.shadowed && a.acne == b.acne &&
           a.leak == b.leak && a.wrong == b.wrong && a.mismatched == b.mismatched &&
           a.mismatchedWithinK == b.mismatchedWithinK && a.coverageMismatch == b.coverageMismatch;
}

}  // namespace

bool runRemeasureBench(std::ostream& out, AccuracyMeter& meter, const Scene& scene, const Settings& settings,
                       const Camera& camera, int width, int height, int rounds) {
    const SettingsField* field = findSettingsField("shadow.depthBias");
    const double base = field ? field->get(settings).get<double>() : 0.0;
    const double step = std::max(std::abs(base) * 0.1, 1.0);
    using Clock = std::chrono::steady_clock;
    auto ms = [](Clock::time_point start) {
        return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    };

    // The first live count uploads the reference to the GPU: once per reference and light space, timed apart.
    const AccuracyReport first = meter.remeasure(scene, withBias(settings, base, step, 1), camera, width, height);
    if (!first.ok) {
        out << "error: live re-measure failed: " << first.error << "\n";
        return false;
    }
    std::vector<double> gpu, gpuFrame, gpuCount, cpu;
    AccuracyReport lastGpu, lastCpu;
    for (int i = 0; i < rounds; ++i) {
        const auto start = Clock::now();
        lastGpu = meter.remeasure(scene, withBias(settings, base, step, i), camera, width, height);
        gpu.push_back(ms(start));
        if (!lastGpu.ok) {
            out << "error: live re-measure failed: " << lastGpu.error << "\n";
            return false;
        }
        gpuFrame.push_back(lastGpu.cost.toolFrameMs);
        gpuCount.push_back(lastGpu.cost.metricsMs + lastGpu.cost.probeMs);
    }
    // The CPU path is slow: at most 5 rounds of it.
    const int cpuRounds = std::min(rounds, 5);
    for (int i = 0; i < cpuRounds; ++i) {
        const auto start = Clock::now();
        lastCpu = meter.measure(scene, withBias(settings, base, step, rounds - cpuRounds + i), camera, width, height);
        cpu.push_back(ms(start));
        if (!lastCpu.ok) {
            out << "error: re-measure failed: " << lastCpu.error << "\n";
            return false;
        }
    }
    // The same frame on both paths (the last round's settings).
    const bool same = sameCounts(lastGpu.counts, lastCpu.counts);

    char text[512];
    std::snprintf(text, sizeof text,
                  "\nre-measure after a bias change (%dx%d, shadow.depthBias alternating %.6g / %.6g):\n"
                  "  GPU path (live)  median %.1f ms of %d  (tool frame %.1f ms + count %.1f ms)\n"
                  "  CPU path         median %.1f ms of %d  (frame read back, every pixel on the CPU, overlays)\n"
                  "  reference upload %.1f ms, once per reference and light space\n"
                  "  counts: GPU %s CPU (acne %zu / %zu, leak %zu / %zu, wrong %zu / %zu)\n",
                  width, height, base + step, base + 2.0 * step, median(gpu), rounds, median(gpuFrame),
                  median(gpuCount), median(cpu), cpuRounds, first.cost.uploadMs, same ? "==" : "!=",
                  lastGpu.counts.acne, lastCpu.counts.acne, lastGpu.counts.leak, lastCpu.counts.leak,
                  lastGpu.counts.wrong, lastCpu.counts.wrong);
    out << text;
    std::snprintf(text, sizeof text, "REMEASURE %dx%d: %.1f ms GPU (live) vs %.1f ms CPU\n", width, height,
                  median(gpu), median(cpu));
    out << text;
    if (!same) out << "error: the GPU and CPU paths disagree on the same frame\n";
    return same;
}

}  // namespace shadowlab::cli
