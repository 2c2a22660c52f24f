#include "sweep/played_point.h"

#include "frame/renderer.h"
#include "scene/scene_animation.h"

#include <algorithm>
#include <chrono>

namespace shadowlab {

PlayedPoint playPoint(AccuracyMeter& meter, Scene& animated, const Settings& settings, const Camera& camera,
                      int width, int height, int frames, double step, AccuracyProgress* progress) {
    PlayedPoint out;
    std::string error;
    const std::optional<std::vector<int>> chosen = chosenAnimations(animated, settings.animation.play, error);
    if (!chosen) {
        out.error = error;
        return out;
    }
    if (chosen->empty()) {
        out.error = "--play: the scene " + animated.name + " has no animation to play (animation.play " +
                    settings.animation.play + ")";
        return out;
    }
    frames = std::max(frames, 2);
    Renderer renderer;  // the point's own maps and cached depths, from an empty start
    struct Restore {
        AccuracyMeter& meter;
        ~Restore() { meter.setToolRenderer(nullptr); }
    } restore{meter};
    meter.setToolRenderer(&renderer);
    std::vector<double> shadow, main;
    double views = 0.0;
    const auto start = std::chrono::steady_clock::now();
    double playedMs = 0.0;  // frames 0..K-2 (the last one's wall time is mostly the measurement)
    for (int f = 0; f < frames; ++f) {
        Settings s = settings;
        s.animation.time = float(double(settings.animation.time) + double(f) * step);
        poseScene(animated, *chosen, s.animation.time);
        FrameStats stats;
        if (f + 1 == frames) playedMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        if (f + 1 < frames) {
            stats = meter.drawToolFrame(animated, s, camera, width, height);
        } else {
            out.report = meter.measure(animated, s, camera, width, height, progress);
            out.measuredTime = s.animation.time;
            if (!out.report.ok) {
                out.error = out.report.error;
                return out;
            }
            stats = meter.lastToolFrame();
        }
        if (!stats.ok) {
            out.error = "--play frame " + std::to_string(f) + ": " + stats.error;
            return out;
        }
        renderer.waitForTimings(stats);
        if (f > 0) {
            shadow.push_back(stats.shadowPass.ran ? stats.shadowPass.milliseconds.value_or(0.0) : 0.0);
            main.push_back(stats.mainPass.milliseconds.value_or(0.0));
            views += double(std::count_if(stats.views.begin(), stats.views.end(),
                                          [](const ShadowViewStats& v) { return v.ran; }));
        }
        out.timed.last = std::move(stats);
    }
    TimedFrames& t = out.timed;
    t.ok = true;
    // The mean, not the median: everyNthFrame's cost is its update frames spread over the frames that reuse.
    auto mean = [](const std::vector<double>& v) {
        double sum = 0.0;
        for (double x : v) sum += x;
        return sum / double(v.size());
    };
    t.shadowMs = mean(shadow);
    t.mainMs = mean(main);
    t.shadowMinMs = *std::min_element(shadow.begin(), shadow.end());
    t.mainMinMs = *std::min_element(main.begin(), main.end());
    t.wallMsPerFrame = playedMs / double(frames - 1);
    t.timingSource = t.last.timingSource;
    out.viewsRenderedPerFrame = views / double(frames - 1);
    return out;
}

}  // namespace shadowlab
