#include "frame/timed_frames.h"

namespace shadowlab {

TimedFrames timeFrames(Renderer& renderer, const Scene& scene, const Settings& settings, const Camera& camera,
                       RenderTarget& target, int frames) {
    TimedFrames result;
    const RepeatedTiming timing = timeRepeated(frames, [&](std::vector<double>& ms) -> std::string {
        renderer.invalidateShadowMap();
        FrameStats stats = renderer.render(scene, settings, camera, target);
        renderer.waitForTimings(stats);
        if (!stats.ok) return stats.error;
        ms = {stats.shadowPass.milliseconds.value_or(0.0), stats.mainPass.milliseconds.value_or(0.0),
              stats.momentsPass.milliseconds.value_or(0.0), stats.blurPass.milliseconds.value_or(0.0),
              stats.mipsPass.milliseconds.value_or(0.0)};
        result.last = std::move(stats);
        return "";
    }, renderer.glInfo().softwareRasterizer ? 0.0 : kGpuWarmUpMs);
    result.error = timing.error;
    result.ok = timing.error.empty();
    if (!result.ok) return result;
    result.shadowMs = timing.medianMs.size() > 0 ? timing.medianMs[0] : 0.0;
    result.mainMs = timing.medianMs.size() > 1 ? timing.medianMs[1] : 0.0;
    result.momentsMs = timing.medianMs.size() > 2 ? timing.medianMs[2] : 0.0;
    result.blurMs = timing.medianMs.size() > 3 ? timing.medianMs[3] : 0.0;
    result.mipsMs = timing.medianMs.size() > 4 ? timing.medianMs[4] : 0.0;
    result.shadowMinMs = timing.minMs.size() > 0 ? timing.minMs[0] : 0.0;
    result.mainMinMs = timing.minMs.size() > 1 ? timing.minMs[1] : 0.0;
    result.wallMsPerFrame = timing.wallMsPerRun;
    result.timingSource = result.last.timingSource;
    return result;
}

PerViewTimes timeEveryView(Renderer& renderer, const Scene& scene, const Settings& settings, const Camera& camera,
                           RenderTarget& target, int frames) {
    PerViewTimes result;
    WarmUp warmUp(renderer.glInfo().softwareRasterizer ? 0.0 : kGpuWarmUpMs);
    for (int f = 0; f < frames;) {
        const bool thrownAway = warmUp.running();
        renderer.invalidateShadowMap();
        result.last = renderer.render(scene, settings, camera, target);
        if (!result.last.ok) {
            result.error = result.last.error;
            return result;
        }
        renderer.waitForTimings(result.last);
        if (thrownAway) continue;
        ++f;
        for (const ShadowViewStats& v : result.last.views)
            if (v.ran && v.milliseconds) result.viewMs[v.name].push_back(*v.milliseconds);
        if (result.last.mainPass.milliseconds) result.mainMs.push_back(*result.last.mainPass.milliseconds);
    }
    return result;
}

}  // namespace shadowlab
