#include "sweep/sweep_runner.h"

#include "frame/timed_frames.h"
#include "accuracy/light_isolation.h"
#include "scene/scene_animation.h"
#include "settings/settings_fields.h"
#include "sweep/pareto_front.h"
#include "sweep/played_point.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>

namespace shadowlab {

namespace {

using Clock = std::chrono::steady_clock;
double wallMsSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

std::string frontStepText(const SweepPointResult& from, const SweepPointResult& to) {
    char text[300];
    if (from.soft.measured && to.soft.measured)
        std::snprintf(text, sizeof text,
                      "+%.3g ms: soft mean |S-V| %.5f -> %.5f, bleeding %.3g %% -> %.3g %%, over-darkening %.3g %% -> "
                      "%.3g %%",
                      to.costMs - from.costMs, from.soft.meanError, to.soft.meanError, from.soft.bleedingPercent,
                      to.soft.bleedingPercent, from.soft.overDarkeningPercent, to.soft.overDarkeningPercent);
    else
        std::snprintf(text, sizeof text, "+%.3g ms: wrong pixels %.3g %% -> %.3g %%, mean |S-V| %.4f -> %.4f",
                      to.costMs - from.costMs, from.accuracy.wrongPercent, to.accuracy.wrongPercent,
                      from.accuracy.meanError, to.accuracy.meanError);
    return text;
}

bool sweepSoftError(const SweepResult& result) {
    bool any = false;
    for (const SweepPointResult& p : result.points) {
        if (p.failed()) continue;
        if (!p.soft.measured) return false;
        any = true;
    }
    return any;
}

double sweepError(const SweepPointResult& point, bool soft) {
    return soft ? point.soft.meanError : point.accuracy.wrongPercent;
}

std::string sweepErrorName(bool soft) { return soft ? "mean |S-V| against the soft reference" : "wrong pixels %"; }

void markParetoFront(SweepResult& result) {
    std::vector<double> cost, error;
    std::vector<std::size_t> measured;  // the points with numbers; the front is over them only
    const bool soft = sweepSoftError(result);
    for (std::size_t i = 0; i < result.points.size(); ++i) {
        const SweepPointResult& p = result.points[i];
        if (p.failed()) continue;
        measured.push_back(i);
        cost.push_back(p.costMs);
        error.push_back(sweepError(p, soft));
    }
    result.front = paretoFront(cost, error);
    for (std::size_t& k : result.front) k = measured[k];
    for (SweepPointResult& p : result.points) p.onFront = false;
    for (std::size_t i : result.front) result.points[i].onFront = true;
}

SweepResult runSweep(const Scene& scene, const Settings& base, const SweepPlan& plan, const SweepRunOptions& options,
                     const SweepPointCallback& onPoint, AccuracyProgress* progress) {
    const auto start = Clock::now();
    SweepResult result;
    result.axes = plan.axes;
    result.width = options.width;
    result.height = options.height;
    result.frames = options.frames;
    result.playFrames = options.playFrames;
    result.playStep = options.playFrames > 0 ? options.playStep : 0.0;
    result.triangles = scene.triangleCount();
    auto fail = [&](std::string error) {
        result.ok = false;
        result.error = std::move(error);
        return result;
    };
    if (!plan.error.empty()) return fail(plan.error);
    if (plan.points.empty()) return fail("the sweep has no points");

    Renderer renderer;  // times the frames; the meter keeps its own renderer for the shadow factor S
    RenderTarget target;
    if (std::string error = target.resize(options.width, options.height); !error.empty()) return fail(error);
    const GlInfo& info = renderer.glInfo();
    result.glRenderer = info.renderer;
    // Before any work: every map size must fit this GPU (the renderer would otherwise keep its previous map).
    for (const SweepPoint& point : plan.points)
        for (std::size_t i = 0; i < point.settings.lights.size(); ++i)
            if (point.settings.lights[i].shadow.resolution > info.maxTextureSize)
                return fail("--axis lights." + std::to_string(i) + ".shadow.resolution: " +
                            std::to_string(point.settings.lights[i].shadow.resolution) +
                            " is above this GPU's GL_MAX_TEXTURE_SIZE " + std::to_string(info.maxTextureSize));
    AccuracyMeter meter;
    std::optional<Scene> playedScene;  // sweep --play: the copy the points are posed on (alive as long as the meter)
    std::unique_ptr<BareDepthDraw> bare;
    std::vector<std::optional<SweepPointResult>> measured(plan.points.size());  // by plan index

    const bool presetExtra = options.measurePreset && plan.basePoint >= plan.points.size();
    const std::size_t total = plan.points.size() + (presetExtra ? 1 : 0);
    result.presetPoint = plan.basePoint;
    const double aspect = double(options.width) / double(options.height);

    // The scene comes posed at the base settings' animation; a point with another animation.time or .play (an
    // axis) is drawn and measured on a copy posed at its own (posing sets every transform, so one copy serves all).
    std::optional<Scene> reposed;
    std::optional<AnimationSettings> reposedAt;  // what `reposed` is posed at
    auto sceneFor = [&](const Settings& settings, std::string& error) -> const Scene* {
        if (settings.animation == base.animation) return &scene;
        if (reposedAt == settings.animation) return &*reposed;
        if (!reposed) reposed = scene;
        reposedAt.reset();
        if (error = poseScene(*reposed, settings.animation); !error.empty()) return nullptr;
        reposedAt = settings.animation;
        return &*reposed;
    };

    // Times and measures one point into r: nullopt when cancelled, else "" or why it failed.
    auto measurePoint = [&](const SweepPoint& point, SweepPointResult& r, std::size_t done) -> std::optional<std::string> {
        std::string poseError;
        const Scene* posed = sceneFor(point.settings, poseError);
        if (!posed) return poseError;
        if (std::string error = sceneCameraError(point.settings.camera, *posed); !error.empty()) return error;
        if (castingLights(point.settings, *posed).empty())
            return std::string("no light casts a shadow with these values (every light is off or has "
                               "castsShadows=false): nothing to time or measure");
        if (progress) {
            progress->base = float(done) / float(total);
            progress->span = 1.0f / float(total);
            progress->fraction = progress->base;
            progress->setStage("timing " + r.label);
        }
        const Camera camera = options.camera && point.settings.camera == base.camera
                                  ? *options.camera
                                  : cameraFor(point.settings.camera, *posed, aspect);
        // Played (sweep --play): timed along the animation and measured at its last frame, by the point's policy.
        std::optional<PlayedPoint> played;
        if (options.playFrames > 0) {
            if (!playedScene) playedScene = scene;
            played = playPoint(meter, *playedScene, point.settings, camera, options.width, options.height,
                               options.playFrames, options.playStep, progress);
            if (!played->error.empty()) return played->error;
            r.playedTime = played->measuredTime;
            r.viewsRenderedPerFrame = played->viewsRenderedPerFrame;
        }
        const TimedFrames timed =
            played ? played->timed : timeFrames(renderer, *posed, point.settings, camera, target, options.frames);
        if (!timed.ok) return timed.error;
        result.timingSource = timed.timingSource;
        r.warnings = timed.last.warnings;
        r.shadowMs = timed.shadowMs;
        r.mainMs = timed.mainMs;
        r.momentsMs = timed.momentsMs;
        r.blurMs = timed.blurMs;
        r.mipsMs = timed.mipsMs;
        r.costMs = r.shadowMs + r.momentsMs + r.blurMs + r.mipsMs + r.mainMs;  // a moments technique's passes count
        r.shadowMinMs = timed.shadowMinMs;
        r.mainMinMs = timed.mainMinMs;
        r.wallMsPerFrame = timed.wallMsPerFrame;
        r.resolution = timed.last.shadowMapResolution;
        r.format = timed.last.shadowMapFormat;
        r.mapBytes = timed.last.shadowMapBytes;

        // The raster limit at this size and format, once per sweep.
        auto found = std::find_if(result.bareDraws.begin(), result.bareDraws.end(), [&](const BareDrawTiming& b) {
            return b.resolution == r.resolution && b.format == r.format &&
                   b.lightViewProjection == timed.last.light.viewProjection();
        });
        if (found == result.bareDraws.end()) {
            if (progress) progress->setStage("bare draw " + std::to_string(r.resolution) + "² " + depthFormatName(r.format));
            if (!bare)
                bare = std::make_unique<BareDepthDraw>(*posed, timed.last.renderOrigin,
                                                       info.softwareRasterizer ? TimingSource::CpuAroundFinish
                                                                               : TimingSource::GpuQueries);
            BareDrawTiming timing = bare->time(timed.last.light.viewProjection(), r.resolution, r.format,
                                               info.maxTextureSize, options.frames);
            if (!timing.ok) return "bare draw " + std::to_string(r.resolution) + ": " + timing.error;
            result.bareDraws.push_back(timing);
            found = result.bareDraws.end() - 1;
        }
        r.bareDrawMs = found->ms;
        r.shadowOverBare = found->ms > 0.0 ? r.shadowMs / found->ms : 0.0;
        if (progress && progress->cancel) return std::nullopt;

        if (progress) progress->setStage("measuring " + r.label);
        const auto measureStart = Clock::now();
        const AccuracyReport report =
            played ? played->report : meter.measure(*posed, point.settings, camera, options.width, options.height, progress);
        if (report.cancelled) return std::nullopt;
        if (!report.ok) return report.error;
        r.measureMs = wallMsSince(measureStart);
        if (!report.cost.referenceReused) {
            result.referenceMs += report.cost.gbufferMs + report.cost.traceMs + report.cost.bvhBuildMs;
            ++result.references;
        }
        r.referenceReused = report.cost.referenceReused;
        r.accuracy = report;
        r.soft = report.soft;
        r.kTexels = report.kTexels;
        r.coarseMap = !report.coarseMapWarning.empty();
        for (const std::string& w : report.warnings) r.warnings.push_back(w);
        return "";
    };

    // The sweep so far, for options.onResult: the finished points in plan order and their front.
    auto soFar = [&] {
        SweepResult partial = result;
        if (plan.basePoint < plan.points.size()) partial.presetPoint = plan.points.size();  // until its point is done
        for (const std::optional<SweepPointResult>& p : measured)
            if (p) {
                if (p->index == plan.basePoint) partial.presetPoint = partial.points.size();
                partial.points.push_back(*p);
            }
        markParetoFront(partial);
        partial.wallMs = wallMsSince(start);
        partial.ok = true;
        return partial;
    };
    // A finished point, measured or failed: kept, reported, and the sweep so far handed on.
    auto finish = [&](SweepPointResult& r, std::size_t done) {
        if (r.index < plan.points.size())
            measured[r.index] = r;
        else
            result.preset = r;
        if (options.onResult) options.onResult(soFar());  // first: a point reported done is in the files
        if (onPoint) onPoint(r, done + 1, total);
    };

    // nullopt: cancelled; else "" or why the point failed (it is kept with its error).
    auto runPoint = [&](const SweepPoint& point, std::size_t index, std::size_t done) -> std::optional<std::string> {
        SweepPointResult r;
        r.index = index;
        r.values = point.values;
        r.label = index < plan.points.size() ? point.label() : "preset (" + point.label() + ")";
        r.settings = point.settings;
        const std::optional<std::string> outcome = measurePoint(point, r, done);
        if (!outcome) return outcome;
        if (!outcome->empty()) {  // kept with its reason only: numbers from a half-done point would mislead
            SweepPointResult failed;
            failed.index = r.index;
            failed.values = r.values;
            failed.label = r.label;
            failed.settings = r.settings;
            failed.error = *outcome;
            r = std::move(failed);
        }
        finish(r, done);
        return outcome;
    };


    // Run order: grouped by the values of the axes the reference depends on (light, camera and the animation's
    // pose), plan order within.
    std::vector<std::size_t> order(plan.points.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    auto referenceValues = [&](std::size_t i) {
        std::vector<std::string> values;
        for (std::size_t a = 0; a < plan.axes.size(); ++a) {
            const std::vector<std::string>& keys = plan.axes[a].keys;
            // A light's own fields other than its map and projection move the light (the reference follows it),
            // whichever light and however typed (plan keys are canonical: "lights.N.type", never "light.type").
            if (std::any_of(keys.begin(), keys.end(), [](const std::string& key) {
                    const SettingsField* field = findSettingsField(key);
                    const bool movesLight = field && field->light >= 0 && field->group() != "shadow" &&
                                            field->group() != "projection";
                    // animation.*: the scene's pose, so its casters and receivers.
                    return movesLight || key.rfind("camera.", 0) == 0 || key.rfind("animation.", 0) == 0;
                }))
                values.push_back(plan.points[i].values[a]);
        }
        return values;
    };
    std::vector<std::vector<std::string>> firstSeen;  // reference values in order of first appearance
    std::vector<std::size_t> group(order.size());
    for (std::size_t i = 0; i < order.size(); ++i) {
        const std::vector<std::string> values = referenceValues(i);
        auto at = std::find(firstSeen.begin(), firstSeen.end(), values);
        if (at == firstSeen.end()) at = firstSeen.insert(firstSeen.end(), values);
        group[i] = std::size_t(at - firstSeen.begin());
    }
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return group[a] < group[b]; });
    for (std::size_t n = 0; n < order.size(); ++n) {
        const std::size_t i = order[n];
        const std::optional<std::string> outcome = runPoint(plan.points[i], i, n);
        if (!outcome || (progress && progress->cancel)) {
            result.cancelled = true;
            return fail("cancelled");
        }
    }
    if (presetExtra) {
        SweepPoint preset;
        preset.values = plan.baseValues;
        preset.settings = base;
        const std::optional<std::string> outcome = runPoint(preset, plan.points.size(), plan.points.size());
        if (!outcome) {
            result.cancelled = true;
            return fail("cancelled");
        }
    }

    for (std::optional<SweepPointResult>& p : measured) result.points.push_back(std::move(*p));
    if (std::all_of(result.points.begin(), result.points.end(), [](const SweepPointResult& p) { return p.failed(); }))
        return fail("every point failed; the first, " + result.points.front().label + ": " +
                    result.points.front().error);
    markParetoFront(result);
    result.wallMs = wallMsSince(start);
    if (progress) {
        progress->fraction = 1.0f;
        progress->setStage("done");
    }
    result.ok = true;
    return result;
}

}  // namespace shadowlab
