#include "cli/bench_lights.h"
#include "cli/bench_input.h"

#include "cli/command_input.h"
#include "context/headless_context.h"
#include "frame/timed_frames.h"
#include "light/scene_lights.h"
#include "scene/scene_source.h"
#include "settings/settings_fields.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <map>

namespace shadowlab::cli {

namespace {

int viewsThatRan(const FrameStats& stats) {
    return int(std::count_if(stats.views.begin(), stats.views.end(), [](const ShadowViewStats& v) { return v.ran; }));
}

}  // namespace

int runBenchLights(const BenchOptions& options) {
    const BenchInput input = readBenchInput(options);
    if (input.refused) return input.refused;
    const Scene& scene = *input.loaded.scene;
    const Settings base = withEffectiveLights(*input.settings, scene);
    if (base.lights.empty()) return fail("--lights: the settings have no light");
    try {
        HeadlessContext context;
        Renderer renderer;
        RenderTarget target;
        if (std::string e = target.resize(options.width, options.height); !e.empty()) return fail(e);
        const Camera camera = cameraFor(base.camera, scene, double(options.width) / options.height);
        std::cout << "bench --lights: " << scene.name << " (" << scene.triangleCount() << " triangles), view "
                  << options.width << "x" << options.height << ", " << base.lights.size() << " lights, "
                  << options.frames << " frames per row\ngl: " << renderer.glInfo().renderer << "\n";
        nlohmann::json doc = {{"scene", scene.name}, {"width", options.width}, {"height", options.height},
                              {"frames", options.frames}, {"glRenderer", renderer.glInfo().renderer},
                              {"lights", benchLightsJson(base)}};

        // 1. Every view forced each frame: the median time of each view.
        PerViewTimes times = timeEveryView(renderer, scene, base, camera, target, options.frames);
        if (!times.error.empty()) return fail(times.error);
        std::map<std::string, std::vector<double>>& perView = times.viewMs;
        std::vector<double>& mainAll = times.mainMs;
        const FrameStats& last = times.last;
        std::cout << "timing: " << last.timingSource << "\n\nevery view rendered (median ms):\n";
        nlohmann::json views = nlohmann::json::array();
        double allViews = 0.0;
        for (const ShadowViewStats& v : last.views) {
            const LightSettings& light = base.lights[v.light];
            if (!v.hasView) {
                std::cout << "  " << std::left << std::setw(14) << v.name << lightTypeName(light.type) << ": " << v.reason
                          << "\n";
                continue;
            }
            const double ms = medianOf(perView[v.name]);
            allViews += ms;
            std::cout << "  " << std::left << std::setw(14) << v.name << std::setw(12) << lightTypeName(light.type)
                      << std::setw(8) << v.resolution << std::fixed << std::setprecision(3) << ms << " ms  "
                      << v.castersDrawn << " casters\n";
            views.push_back({{"view", v.name}, {"light", v.light}, {"face", v.face}, {"kind", lightTypeName(light.type)},
                             {"resolution", v.resolution},
                             {"ms", ms}, {"castersDrawn", v.castersDrawn}});
        }
        std::cout << "  all views " << std::setprecision(3) << allViews << " ms; main pass " << medianOf(mainAll)
                  << " ms\n";
        doc["views"] = views;
        doc["allViewsMs"] = allViews;

        // 2. A static frame, then a frame that moves one light (a spot if there is one).
        renderer.render(scene, base, camera, target);
        FrameStats still = renderer.render(scene, base, camera, target);
        Settings moved = base;
        std::size_t mover = 0;
        for (std::size_t i = 0; i < moved.lights.size(); ++i)
            if (moved.lights[i].type == LightType::Spot && moved.lights[i].castsShadows) {
                mover = i;
                break;
            }
        moved.lights[mover].position.x += 0.01f * std::max(1.0f, scene.bounds.radius());
        moved.lights[mover].direction.x += 0.01f;
        FrameStats afterMove = renderer.render(scene, moved, camera, target);
        renderer.waitForTimings(afterMove);
        std::cout << "\nstatic frame: " << viewsThatRan(still) << " views rendered\n"
                  << "moving light " << mover << " (" << lightTypeName(base.lights[mover].type)
                  << "): " << viewsThatRan(afterMove) << " views rendered, "
                  << afterMove.shadowPass.milliseconds.value_or(0.0) << " ms; the others: unchanged\n";
        doc["staticFrameViews"] = viewsThatRan(still);
        doc["movedLight"] = mover;
        doc["movedLightViews"] = viewsThatRan(afterMove);
        doc["movedLightShadowMs"] = afterMove.shadowPass.milliseconds.value_or(0.0);

        // 3. The main pass with the first k lights, shadowed and not: the difference is what the taps cost.
        std::cout << "\nmain pass by shadowed lights (filter " << nlohmann::json(base.filter.kind == FilterKind::Pcf
                                                                                     ? "pcf" + std::to_string(base.filter.kernel)
                                                                                     : "see preset")
                                                                        .get<std::string>()
                  << "; median ms):\n  lights  shadowed  unshadowed  taps cost  per light\n";
        nlohmann::json scaling = nlohmann::json::array();
        for (std::size_t k = 1; k <= base.lights.size(); k *= 2) {
            Settings some = base;
            some.lights.resize(k);
            Settings bare = some;
            for (LightSettings& l : bare.lights) l.castsShadows = false;
            const TimedFrames shadowed = timeFrames(renderer, scene, some, camera, target, options.frames);
            const TimedFrames unshadowed = timeFrames(renderer, scene, bare, camera, target, options.frames);
            if (!shadowed.ok || !unshadowed.ok) return fail(shadowed.ok ? unshadowed.error : shadowed.error);
            const double taps = shadowed.mainMs - unshadowed.mainMs;
            std::cout << "  " << std::setw(8) << k << std::setw(10) << shadowed.mainMs << std::setw(12)
                      << unshadowed.mainMs << std::setw(11) << taps << taps / double(k) << "\n";
            scaling.push_back({{"lights", k}, {"shadowedMainMs", shadowed.mainMs},
                               {"unshadowedMainMs", unshadowed.mainMs}, {"shadowTapsMs", taps}});
        }
        doc["mainPassByShadowedLights"] = scaling;
        if (int failed = writeBenchJson(options.json, doc)) return failed;
    } catch (const std::exception& e) {
        return fail(e.what());
    }
    return 0;
}

}  // namespace shadowlab::cli
