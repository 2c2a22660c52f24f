#include "cli/bench_animation.h"
#include "cli/bench_input.h"

#include "accuracy/cache_error.h"
#include "accuracy/light_isolation.h"
#include "accuracy/motion.h"
#include "cli/command_input.h"
#include "cli/measure_motion.h"
#include "cli/mover_camera.h"
#include "cli/settings_from_cli.h"
#include "context/headless_context.h"
#include "frame/renderer.h"
#include "light/scene_lights.h"
#include "scene/scene_animation.h"
#include "timing/repeated_timing.h"
#include "scene/scene_casters.h"
#include "scene/scene_source.h"
#include "settings/settings_fields.h"

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <sstream>

namespace shadowlab::cli {

namespace {

constexpr double kDefaultStepSeconds = 1.0 / 30.0;  // one frame at 30 fps

double meanOf(const std::vector<double>& v) {
    double sum = 0.0;
    for (double x : v) sum += x;
    return v.empty() ? 0.0 : sum / double(v.size());
}

std::string fixed(double value, int digits) {
    std::ostringstream out;
    out << std::fixed << std::setprecision(digits) << value;
    return out.str();
}

// An update policy: its name and the settings every light of the frames gets.
struct Policy {
    std::string name;
    Settings settings;
    std::string flaggedStatic;  // the moving caster casters.static names ("" for the plain policies)
};

// `settings` with every light's shadow.update (and everyNthFrame's N) set through their keys.
Settings withUpdate(Settings settings, const std::string& update, int interval = 0) {
    for (std::size_t i = 0; i < settings.lights.size(); ++i) {
        const std::string light = "lights." + std::to_string(i) + ".shadow.";
        applySettingOverride(settings, light + "update=" + update);
        if (interval > 0) applySettingOverride(settings, light + "updateInterval=" + std::to_string(interval));
    }
    return settings;
}

// What one frame did with a policy's views.
struct ViewFrame {
    std::string name;
    std::string cache;  // reused, static + dynamic, full
    double ms = 0.0;    // 0 when reused
    int castersDrawn = 0;
    std::size_t texelsRedrawn = 0;
    std::string reason;
    // Texels its map got from a draw this frame (full: all of them; static + dynamic: the rectangle; scrolled: the
    // strips that came into view; reused: none) of `texels` (resolution²).
    std::size_t texelsRendered = 0, texels = 0;
};
struct PolicyFrame {
    double shadowMs = 0.0;  // the views that ran (0: none ran)
    int rendered = 0, full = 0, staticPlusDynamic = 0, scrolled = 0, reused = 0;
    std::size_t texelsRendered = 0, texels = 0;  // over its views
    std::vector<ViewFrame> views;
    std::vector<std::string> warnings;
};

PolicyFrame summarize(const FrameStats& stats) {
    PolicyFrame f;
    f.shadowMs = stats.shadowPass.ran ? stats.shadowPass.milliseconds.value_or(0.0) : 0.0;
    f.warnings = stats.warnings;
    for (const ShadowViewStats& v : stats.views) {
        if (!v.hasView) continue;
        const std::size_t texels = std::size_t(v.resolution) * std::size_t(v.resolution);
        const std::size_t rendered = !v.ran ? 0 : v.cache == "full" ? texels : v.texelsRedrawn;
        f.views.push_back({v.name, v.ran ? v.cache : "reused", v.ran ? v.milliseconds.value_or(0.0) : 0.0,
                           v.ran ? v.castersDrawn : 0, v.texelsRedrawn, v.reason, rendered, texels});
        f.texelsRendered += rendered;
        f.texels += texels;
        if (!v.ran) ++f.reused;
        else if (v.cache == "static + dynamic") ++f.staticPlusDynamic, ++f.rendered;
        else if (v.cache == "scrolled") ++f.scrolled, ++f.rendered;
        else ++f.full, ++f.rendered;
    }
    return f;
}

double percentOf(std::size_t part, std::size_t whole) { return whole > 0 ? 100.0 * double(part) / double(whole) : 0.0; }

nlohmann::json frameJson(const PolicyFrame& f) {
    nlohmann::json views = nlohmann::json::array();
    for (const ViewFrame& v : f.views)
        views.push_back({{"view", v.name}, {"cache", v.cache}, {"ms", v.ms}, {"castersDrawn", v.castersDrawn},
                         {"texelsRedrawn", v.texelsRedrawn}, {"texelsRendered", v.texelsRendered},
                         {"texels", v.texels}, {"texelsRenderedPercent", percentOf(v.texelsRendered, v.texels)},
                         {"reason", v.reason}});
    return {{"shadowPassMs", f.shadowMs}, {"viewsRendered", f.rendered}, {"viewsFull", f.full},
            {"viewsStaticPlusDynamic", f.staticPlusDynamic}, {"viewsScrolled", f.scrolled},
            {"viewsReused", f.reused}, {"texelsRendered", f.texelsRendered}, {"texels", f.texels},
            {"texelsRenderedPercent", percentOf(f.texelsRendered, f.texels)}, {"views", views}};
}

std::string viewsText(const PolicyFrame& f) {
    std::string text = std::to_string(f.rendered);
    if (f.staticPlusDynamic > 0) text += " (" + std::to_string(f.staticPlusDynamic) + " s+d)";
    if (f.scrolled > 0) text += " (" + std::to_string(f.scrolled) + " scr)";
    return text + " / " + std::to_string(f.reused);
}

// One view's cell of the per-frame table: its cache state, the share of its texels drawn, its ms.
std::string viewCell(const ViewFrame& v) {
    if (v.cache == "reused") return "reused";
    const std::string state = v.cache == "static + dynamic" ? "s+d" : v.cache;
    return state + " " + fixed(percentOf(v.texelsRendered, v.texels), 2) + "% " + fixed(v.ms, 3);
}

// The casters a chosen animation moves, in scene order (the first is what the flagged-static policy names; all are
// what --cache-error's camera sees).
std::vector<std::size_t> movingInstances(const Scene& scene, const std::vector<int>& chosen,
                                         const CasterSettings& casters) {
    const std::vector<char> statics = staticInstances(scene, chosen, casters);
    const std::vector<char> casting = castingInstances(scene, casters);
    std::vector<std::size_t> moving;
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        const int node = scene.instances[i].node;
        if (!statics[i] && casting[i] && node >= 0 && std::size_t(node) < scene.nodes.size()) moving.push_back(i);
    }
    return moving;
}

void addWarnings(std::vector<std::string>& into, const std::vector<std::string>& warnings) {
    for (const std::string& w : warnings)
        if (std::find(into.begin(), into.end(), w) == into.end()) into.push_back(w);
}

}  // namespace

bool BenchAnimationOptions::requested(const CLI::App& bench) const {
    return bench.get_option("--animation")->count() > 0 || bench.get_option("--walk")->count() > 0;
}

void addBenchAnimationOptions(CLI::App& bench, BenchAnimationOptions& o) {
    CLI::Option* animation = bench.add_option("--animation", o.animation,
                     "play the scene's animation (animation.play: a name or index; alone: the settings' choice) and "
                     "time each frame's shadow pass with the lights' shadow.update against every view re-rendered")
        ->expected(0, 1)
        ->type_name("[NAME|INDEX]");
    o.animationOption = animation;
    bench.add_option("--walk", o.walk,
                     "move the camera and its target by this vector every frame (world units; with or without "
                     "--animation) and time each frame's shadow pass with the lights' shadow.update against every view "
                     "re-rendered, with the share of texels each view re-rendered (stable cascades scroll)")
        ->type_name("DX,DY,DZ");
    bench.add_option("--step", o.step, "with --animation: seconds per frame (default 1/30)")
        ->type_name("SECONDS")
        ->needs(animation);
    bench.add_option("--time", o.time, "with --animation: the first frame's animation.time (default: the settings')")
        ->type_name("SECONDS")
        ->needs(animation);
    CLI::Option* cacheError =
        bench.add_flag("--cache-error", o.cacheError,
                       "with --animation: each shadow.update policy's frames against the exact reference and against "
                       "a full re-render (the cache error), beside the ms it saves")
            ->needs(animation);
    bench.add_option("--intervals", o.intervals, "with --cache-error: everyNthFrame's N values")
        ->capture_default_str()
        ->check(CLI::Range(1, 1000))
        ->needs(cacheError);
    bench.add_option("--light", o.light, "with --cache-error: the light measured (default: the only casting one)")
        ->check(CLI::NonNegativeNumber)
        ->needs(cacheError);
}

int runBenchAnimation(const BenchOptions& bench, const BenchAnimationOptions& o) {
    std::vector<std::string> overrides = bench.overrides;
    if (!o.animation.empty()) overrides.push_back("animation.play=" + nlohmann::json(o.animation).dump());
    std::string error;
    if (!o.time.empty()) {
        const std::optional<double> time = parseFiniteOption(o.time, "--time", error);
        if (!time) return fail(error);
        overrides.push_back("animation.time=" + nlohmann::json(*time).dump());
    }
    std::optional<Settings> requested = settingsFromCli(bench.preset, overrides, bench.scene);
    if (!requested) return 2;
    if (error = checkOutputFolder(bench.json, "--json"); !error.empty()) return fail(error);
    if (error = checkViewSize(bench.width, bench.height); !error.empty()) return fail(error);
    Motion motion;
    motion.kind = MotionKind::Animation;
    motion.frames = bench.frames;
    motion.step = kDefaultStepSeconds;
    if (!o.step.empty()) {
        const std::optional<double> step = parseFiniteOption(o.step, "--step", error);
        if (!step) return fail(error);
        motion.step = *step;
    }
    SceneLoadResult loaded = loadSceneForCommand(bench.scene, {&*requested});
    if (!loaded.scene) return fail(loaded.error);
    const Scene& scene = *loaded.scene;
    if (error = motionError(motion, scene.bounds); !error.empty()) return fail(error);
    // --animation plays the scene's animation; a walk alone keeps the pose of animation.time.
    const bool play = o.animationOption && o.animationOption->count() > 0;
    std::optional<std::vector<int>> chosen = std::vector<int>{};
    if (play) {
        chosen = chosenAnimations(scene, requested->animation.play, error);
        if (!chosen) return fail(error);
        if (chosen->empty())
            return fail("bench --animation: the scene " + scene.name + " has no animation to play (animation.play " +
                        requested->animation.play + ")");
    }
    // --walk: a camera motion (accuracy/motion.h) whose step is the vector's length, along it.
    Motion walk;
    walk.kind = MotionKind::Camera;
    walk.frames = motion.frames;
    if (!o.walk.empty()) {
        const std::optional<glm::dvec3> by = parseVectorOption(o.walk, "--walk", error);
        if (!by) return fail(error);
        const double diameter = scene.bounds.empty ? 2.0 : 2.0 * double(scene.bounds.radius());
        const double length = glm::length(*by);
        if (!(length > 0.0) || !std::isfinite(length) || length > kMaxCameraStepDiameters * diameter)
            return fail("--walk " + o.walk + ": the camera's move per frame must be non-zero and at most the scene " +
                        scene.name + "'s diameter (" + fixed(diameter, 1) + " world units)");
        walk.step = length;
        walk.direction = *by;
    }

    // --cache-error measures one light (the meter's rule): the frames are that light's alone, timed and measured.
    Settings base = withEffectiveLights(*requested, scene);
    std::size_t measuredLight = 0;
    if (o.cacheError) {
        const std::optional<std::size_t> light = chooseOneLight(*requested, scene, o.light, "--light", error);
        if (!light) return fail(error);
        measuredLight = *light;
        const std::optional<Settings> isolated = isolateLight(*requested, scene, *light, error);
        if (!isolated) return fail(error);
        base = *isolated;
    }
    const double start = base.animation.time;
    const std::vector<std::size_t> moving = movingInstances(scene, *chosen, base.casters);
    std::vector<Policy> policies;
    std::string cachedName;
    if (o.cacheError) {
        policies.push_back({"everyFrame", withUpdate(base, "everyFrame"), ""});
        policies.push_back({"onChange", withUpdate(base, "onChange"), ""});
        policies.push_back({"cachedStatic", withUpdate(base, "cachedStatic"), ""});
        for (int n : o.intervals)
            policies.push_back({"everyNthFrame " + std::to_string(n), withUpdate(base, "everyNthFrame", n), ""});
        const std::string mover = moving.empty() ? "" : scene.nodes[std::size_t(scene.instances[moving[0]].node)].path;
        if (!mover.empty()) {
            Policy flagged{"cachedStatic, " + mover + " static", withUpdate(base, "cachedStatic"), mover};
            flagged.settings.casters.forcedStatic.push_back(mover);
            policies.push_back(flagged);
        }
    } else {
        // The lights' own policy against every view re-rendered.
        std::set<std::string> names;
        for (std::size_t i = 0; i < base.lights.size(); ++i)
            names.insert(findSettingsField("lights." + std::to_string(i) + ".shadow.update")->get(base).get<std::string>());
        for (const std::string& n : names) cachedName += (cachedName.empty() ? "" : ", ") + n;
        policies.push_back({"cached (" + cachedName + ")", base, ""});
        policies.push_back({"full (everyFrame)", withUpdate(base, "everyFrame"), ""});
    }
    for (const Policy& p : policies)
        if (std::vector<std::string> problems = p.settings.validate(); !problems.empty())
            return fail(p.name + ": " + problems.front());

    try {
        HeadlessContext context;
        std::vector<std::unique_ptr<Renderer>> renderers;
        for (std::size_t i = 0; i < policies.size(); ++i) renderers.push_back(std::make_unique<Renderer>());
        RenderTarget target;
        if (error = target.resize(bench.width, bench.height); !error.empty()) return fail(error);
        std::unique_ptr<AccuracyMeter> meter;
        std::unique_ptr<Renderer> scratch;  // --cache-error: every frame with every view forced (the exact baseline)
        if (o.cacheError) {
            meter = std::make_unique<AccuracyMeter>();
            scratch = std::make_unique<Renderer>();
        }
        const double aspect = double(bench.width) / bench.height;
        std::vector<double> times;  // each frame's animation time (a walk alone: animation.time throughout)
        for (int f = 0; f < motion.frames; ++f) times.push_back(play ? animationTimeAtFrame(start, motion, f) : start);
        // --cache-error sees the first caster that moves where the settings leave the camera to auto-framing.
        const bool onMover = o.cacheError && !moving.empty() && base.camera.autoFrame && base.camera.sceneCamera < 0;
        const Camera camera = onMover ? cameraOnMovers(scene, *chosen, {moving.front()}, times, base.camera, aspect)
                                      : cameraFor(base.camera, scene, aspect);
        std::cout << "bench --animation: " << scene.name << " (" << scene.triangleCount() << " triangles), view "
                  << bench.width << "x" << bench.height << ", "
                  << (play ? animationNote(scene, base.animation) : "no animation played (a walk alone)") << "\n"
                  << motion.frames << " frames"
                  << (play ? " of " + fixed(motion.step, 4) + " s from " + fixed(start, 4) + " s" : "")
                  << (o.cacheError ? ", light " + std::to_string(measuredLight) + " alone" : "") << "\n";
        if (onMover)
            std::cout << "camera: on " << scene.nodes[std::size_t(scene.instances[moving[0]].node)].path
                      << " (the first caster that moves; fix camera.position / target with camera.autoFrame=false, "
                         "or camera.sceneCamera, to measure from another view)\n";
        if (walk.direction)
            std::cout << "walk: the camera moves " << o.walk << " a frame (" << fixed(walk.step, 3)
                      << " world units), from " << fixed(camera.position.x, 2) << "," << fixed(camera.position.y, 2)
                      << "," << fixed(camera.position.z, 2) << "\n";
        std::cout << "gl: " << renderers.front()->glInfo().renderer << "\n";

        Scene animated = scene;
        // [frame][policy]; the last frame is the still one (--cache-error plays no still frame).
        std::vector<std::vector<PolicyFrame>> frames;
        std::vector<std::vector<AccuracyNumbers>> accuracy;  // --cache-error: [frame][policy]
        std::vector<std::vector<CacheError>> cacheErrors;
        std::vector<std::vector<std::string>> warnings(policies.size());
        std::string timingSource;
        const int played = motion.frames + (o.cacheError ? 0 : 1);
        for (int f = 0; f < played; ++f) {
            const bool still = f == motion.frames;
            const int at = still ? f - 1 : f;  // the still frame: the last pose and camera again
            const double t = times[std::size_t(at)];
            AnimationSettings pose = base.animation;
            pose.time = float(t);
            if (!still && play) poseScene(animated, *chosen, t);
            const Camera frameCamera = walk.direction ? cameraAtFrame(camera, walk, at) : camera;
            frames.emplace_back();
            if (!o.cacheError) {
                for (std::size_t p = 0; p < policies.size(); ++p) {
                    Settings s = policies[p].settings;
                    s.animation = pose;
                    FrameStats stats = renderers[p]->render(animated, s, frameCamera, target);
                    if (!stats.ok) return fail(policies[p].name + ", frame " + std::to_string(f) + ": " + stats.error);
                    renderers[p]->waitForTimings(stats);
                    timingSource = stats.timingSource;
                    addWarnings(warnings[p], stats.warnings);
                    frames.back().push_back(summarize(stats));
                }
                continue;
            }
            // The exact baseline first: the same frame with every view forced.
            Settings full = policies.front().settings;
            full.animation = pose;
            scratch->invalidateShadowMap();
            meter->setToolRenderer(scratch.get());
            const AccuracyReport baseline = meter->measure(animated, full, frameCamera, bench.width, bench.height);
            if (!baseline.ok) return fail("frame " + std::to_string(f) + " re-rendered: " + baseline.error);
            accuracy.emplace_back();
            cacheErrors.emplace_back();
            for (std::size_t p = 0; p < policies.size(); ++p) {
                Settings s = policies[p].settings;
                s.animation = pose;
                meter->setToolRenderer(renderers[p].get());
                const AccuracyReport r = meter->measure(animated, s, frameCamera, bench.width, bench.height);
                if (!r.ok) return fail(policies[p].name + ", frame " + std::to_string(f) + ": " + r.error);
                FrameStats stats = meter->lastToolFrame();
                renderers[p]->waitForTimings(stats);
                timingSource = stats.timingSource;
                addWarnings(warnings[p], r.warnings);
                frames.back().push_back(summarize(stats));
                accuracy.back().push_back(r);
                cacheErrors.back().push_back(cacheErrorAgainst(r, baseline));
            }
            meter->setToolRenderer(nullptr);
        }
        const bool cpu = timingSource.rfind("CPU", 0) == 0;
        // Who drew the frames, as the tables label them: "CPU: llvmpipe ..." or "GPU: NVIDIA H200 ...".
        const std::string device = std::string(cpu ? "CPU: " : "GPU: ") + renderers.front()->glInfo().renderer;
        std::cout << "times: " << timingSource << (cpu ? " — CPU times, not a GPU's" : "") << "\n";
        for (std::size_t p = 0; p < policies.size(); ++p)
            for (const std::string& w : warnings[p]) std::cerr << "warning: " << policies[p].name << ": " << w << "\n";

        nlohmann::json doc = {{"scene", scene.name},
                              {"triangles", scene.triangleCount()},
                              {"width", bench.width},
                              {"height", bench.height},
                              {"glRenderer", renderers.front()->glInfo().renderer},
                              {"timingSource", timingSource},
                              {"cpuTimes", cpu},
                              {"device", device},
                              {"animation", base.animation.play},
                              {"startTime", start},
                              {"step", motion.step},
                              {"frames", motion.frames},
                              {"played", play},
                              {"lights", benchLightsJson(base)}};
        if (walk.direction) doc["walk"] = {walk.direction->x, walk.direction->y, walk.direction->z};
        doc["camera"] = {{"position", {camera.position.x, camera.position.y, camera.position.z}},
                         {"target", {camera.target.x, camera.target.y, camera.target.z}},
                         {"onMover", onMover}};
        nlohmann::json policyNames = nlohmann::json::array();
        for (const Policy& p : policies) policyNames.push_back(p.name);
        doc["policies"] = policyNames;

        if (!o.cacheError) {
            // Per frame: the cached policy (0) against the full re-render (1); "drawn %": the share of the views'
            // texels a draw wrote this frame (full re-render: every texel of every view that ran).
            std::cout << "\nper frame (views rendered / reused; s+d = static + dynamic, scr = scrolled), shadow pass "
                         "ms, texels drawn %:\n"
                      << std::left << std::setw(7) << "frame" << std::setw(9) << "time s" << std::setw(20)
                      << "cached views" << std::setw(12) << "cached ms" << std::setw(10) << "drawn %" << std::setw(14)
                      << "full views" << std::setw(12) << "full ms" << std::setw(10) << "drawn %" << "cached/full ms\n";
            nlohmann::json perFrame = nlohmann::json::array();
            std::vector<double> cachedMs, fullMs;
            std::size_t cachedTexels = 0, fullTexels = 0, allTexels = 0;  // over the moving frames
            for (std::size_t f = 0; f < frames.size(); ++f) {
                const PolicyFrame& c = frames[f][0];
                const PolicyFrame& u = frames[f][1];
                const bool still = int(f) == motion.frames;
                const double time = times[std::min(f, times.size() - 1)];
                const double share = u.shadowMs > 0.0 ? 100.0 * c.shadowMs / u.shadowMs : 0.0;
                std::cout << std::left << std::setw(7) << (still ? "still" : std::to_string(f)) << std::setw(9)
                          << (play ? fixed(time, 3) : "-") << std::setw(20) << viewsText(c) << std::setw(12) << fixed(c.shadowMs, 3)
                          << std::setw(10) << fixed(percentOf(c.texelsRendered, c.texels), 2) << std::setw(14)
                          << viewsText(u) << std::setw(12) << fixed(u.shadowMs, 3) << std::setw(10)
                          << fixed(percentOf(u.texelsRendered, u.texels), 2) << fixed(share, 1) << " %"
                          << (f == 0 ? "  (first frame: every view)" : "")
                          << (still ? "  (the last pose again: nothing moved)" : "") << "\n";
                perFrame.push_back({{"frame", f}, {"time", time}, {"still", still},
                                    {"cached", frameJson(c)}, {"full", frameJson(u)}});
                if (f > 0 && !still) {
                    cachedMs.push_back(c.shadowMs);
                    fullMs.push_back(u.shadowMs);
                    cachedTexels += c.texelsRendered;
                    fullTexels += u.texelsRendered;
                    allTexels += c.texels;
                }
            }
            doc["perFrame"] = perFrame;
            // Per frame and view, the cached policy: what each view got, the share of its texels drawn, its ms.
            const std::vector<ViewFrame>& names = frames.front()[0].views;
            std::cout << "\nper frame and view, cached (state, texels drawn %, ms):\n" << std::left << std::setw(7)
                      << "frame";
            for (const ViewFrame& v : names) std::cout << std::setw(28) << v.name;
            std::cout << "\n";
            for (std::size_t f = 0; f < frames.size(); ++f) {
                std::cout << std::left << std::setw(7) << (int(f) == motion.frames ? "still" : std::to_string(f));
                for (const ViewFrame& v : frames[f][0].views) std::cout << std::setw(28) << viewCell(v);
                std::cout << "\n";
            }
            // Per view, over the moving frames (1 .. N-1).
            std::cout << "\nper view, frames 1.." << motion.frames - 1 << " (median ms over the frames it rendered):\n"
                      << std::left << std::setw(22) << "view" << std::setw(7) << "full" << std::setw(7) << "s+d"
                      << std::setw(10) << "scrolled" << std::setw(9) << "reused" << std::setw(12) << "cached ms"
                      << std::setw(10) << "full ms" << "texels drawn % (cached)\n";
            nlohmann::json perView = nlohmann::json::array();
            for (std::size_t v = 0; v < names.size(); ++v) {
                int fullCount = 0, sd = 0, scrolled = 0, reused = 0;
                std::size_t drawn = 0, texels = 0;
                std::vector<double> c, u;
                for (std::size_t f = 1; f < std::size_t(motion.frames); ++f) {
                    if (v >= frames[f][0].views.size() || v >= frames[f][1].views.size()) continue;
                    const ViewFrame& cv = frames[f][0].views[v];
                    drawn += cv.texelsRendered;
                    texels += cv.texels;
                    if (cv.cache == "reused") ++reused;
                    else {
                        (cv.cache == "full" ? fullCount : cv.cache == "scrolled" ? scrolled : sd) += 1;
                        c.push_back(cv.ms);
                    }
                    if (frames[f][1].views[v].cache != "reused") u.push_back(frames[f][1].views[v].ms);
                }
                std::cout << std::left << std::setw(22) << names[v].name << std::setw(7) << fullCount << std::setw(7)
                          << sd << std::setw(10) << scrolled << std::setw(9) << reused << std::setw(12)
                          << fixed(medianOf(c), 3) << std::setw(10) << fixed(medianOf(u), 3)
                          << fixed(percentOf(drawn, texels), 2) << "\n";
                perView.push_back({{"view", names[v].name}, {"framesFull", fullCount}, {"framesStaticPlusDynamic", sd},
                                   {"framesScrolled", scrolled}, {"framesReused", reused},
                                   {"cachedMedianMs", medianOf(c)}, {"fullMedianMs", medianOf(u)},
                                   {"cachedTexelsRenderedPercent", percentOf(drawn, texels)}});
            }
            doc["perView"] = perView;
            const double c = medianOf(cachedMs), u = medianOf(fullMs);
            const double sumC = meanOf(cachedMs) * double(cachedMs.size()), sumU = meanOf(fullMs) * double(fullMs.size());
            std::cout << "\nframes 1.." << motion.frames - 1 << ": shadow pass median " << fixed(c, 3) << " ms cached, "
                      << fixed(u, 3) << " ms full (" << fixed(u > 0 ? 100.0 * c / u : 0.0, 1) << " %); total "
                      << fixed(sumC, 1) << " ms against " << fixed(sumU, 1) << " ms ("
                      << fixed(sumU > 0 ? 100.0 * sumC / sumU : 0.0, 1) << " %); texels drawn "
                      << fixed(percentOf(cachedTexels, allTexels), 2) << " % cached, "
                      << fixed(percentOf(fullTexels, allTexels), 2) << " % full [" << device << "]"
                      << "\nstill frame: " << frames.back()[0].rendered << " views rendered cached, "
                      << frames.back()[1].rendered << " full\n";
            doc["summary"] = {{"movingFrames", cachedMs.size()}, {"cachedMedianMs", c}, {"fullMedianMs", u},
                              {"cachedTotalMs", sumC}, {"fullTotalMs", sumU},
                              {"cachedOverFullPercent", u > 0 ? 100.0 * c / u : 0.0},
                              {"cachedTexelsRenderedPercent", percentOf(cachedTexels, allTexels)},
                              {"fullTexelsRenderedPercent", percentOf(fullTexels, allTexels)},
                              {"stillFrameViewsRendered", frames.back()[0].rendered},
                              {"stillFrameFullViewsRendered", frames.back()[1].rendered}};
        } else {
            // Per policy over the frames after the first (which draws every view under every policy).
            std::cout << "\ncache error along the animation, frames 1.." << motion.frames - 1
                      << " (mean; max in brackets): against the exact reference at the frame's time, and against the "
                         "same frame re-rendered (the cache error)\n"
                      << std::left << std::setw(30) << "policy" << std::setw(11) << "shadow ms" << std::setw(10)
                      << "saved %" << std::setw(8) << "views" << std::setw(22) << "wrong % (ref)" << std::setw(20)
                      << "mean err (ref)" << std::setw(22) << "cache wrong %" << "cache mean err\n";
            nlohmann::json rows = nlohmann::json::array();
            double everyFrameMs = 0.0;
            for (std::size_t p = 0; p < policies.size(); ++p) {
                std::vector<double> ms, views, wrong, mean, cacheWrong, cacheMean;
                nlohmann::json perFrame = nlohmann::json::array();
                for (std::size_t f = 0; f < frames.size(); ++f) {
                    const PolicyFrame& pf = frames[f][p];
                    const AccuracyNumbers& a = accuracy[f][p];
                    const CacheError& e = cacheErrors[f][p];
                    nlohmann::json row = frameJson(pf);
                    row.erase("views");
                    row["frame"] = f;
                    row["time"] = times[f];
                    row["wrongPercent"] = a.wrongPercent;
                    row["wrongPixels"] = a.counts.wrong;
                    row["meanError"] = a.meanError;
                    row["cacheWrongPercent"] = e.wrongPercent;
                    row["cacheWrongPixels"] = e.wrong;
                    row["cacheMeanError"] = e.meanError;
                    perFrame.push_back(row);
                    if (f == 0) continue;
                    ms.push_back(pf.shadowMs);
                    views.push_back(pf.rendered);
                    wrong.push_back(a.wrongPercent);
                    mean.push_back(a.meanError);
                    cacheWrong.push_back(e.wrongPercent);
                    cacheMean.push_back(e.meanError);
                }
                const double policyMs = meanOf(ms);
                if (p == 0) everyFrameMs = policyMs;
                const double saved = everyFrameMs > 0.0 ? 100.0 * (everyFrameMs - policyMs) / everyFrameMs : 0.0;
                auto maxOf = [](const std::vector<double>& v) { return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end()); };
                std::cout << std::left << std::setw(30) << policies[p].name << std::setw(11) << fixed(policyMs, 3)
                          << std::setw(10) << fixed(saved, 1) << std::setw(8) << fixed(meanOf(views), 2)
                          << std::setw(22) << (fixed(meanOf(wrong), 3) + " [" + fixed(maxOf(wrong), 3) + "]")
                          << std::setw(20) << (fixed(meanOf(mean), 4) + " [" + fixed(maxOf(mean), 4) + "]")
                          << std::setw(22) << (fixed(meanOf(cacheWrong), 3) + " [" + fixed(maxOf(cacheWrong), 3) + "]")
                          << fixed(meanOf(cacheMean), 4) << " [" << fixed(maxOf(cacheMean), 4) << "]\n";
                nlohmann::json row = {{"policy", policies[p].name},
                                      {"shadowPassMeanMs", policyMs},
                                      {"savedMs", everyFrameMs - policyMs},
                                      {"savedPercent", saved},
                                      {"viewsRenderedPerFrame", meanOf(views)},
                                      {"wrongPercentMean", meanOf(wrong)},
                                      {"wrongPercentMax", maxOf(wrong)},
                                      {"meanErrorMean", meanOf(mean)},
                                      {"meanErrorMax", maxOf(mean)},
                                      {"cacheWrongPercentMean", meanOf(cacheWrong)},
                                      {"cacheWrongPercentMax", maxOf(cacheWrong)},
                                      {"cacheMeanErrorMean", meanOf(cacheMean)},
                                      {"cacheMeanErrorMax", maxOf(cacheMean)},
                                      {"warnings", warnings[p]},
                                      {"perFrame", perFrame}};
                if (!policies[p].flaggedStatic.empty()) row["flaggedStatic"] = policies[p].flaggedStatic;
                rows.push_back(row);
            }
            std::cout << "saved %: against everyFrame's shadow ms" << " [" << device << "]"
                      << "; views: rendered per frame\n";
            doc["light"] = measuredLight;
            doc["cacheError"] = rows;
        }
        if (int failed = writeBenchJson(bench.json, doc)) return failed;
    } catch (const std::exception& e) {
        return fail(e.what());
    }
    return 0;
}

}  // namespace shadowlab::cli
