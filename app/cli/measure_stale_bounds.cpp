#include "cli/measure_stale_bounds.h"
#include "cli/json_output.h"

#include "accuracy/stale_depth_bounds.h"
#include "cli/accuracy_output.h"
#include "cli/command_input.h"
#include "cli/measure_motion.h"
#include "cli/settings_from_cli.h"
#include "context/headless_context.h"
#include "light/scene_lights.h"
#include "scene/scene_source.h"

#include <nlohmann/json.hpp>

#include <iomanip>
#include <iostream>

namespace shadowlab::cli {

namespace {

nlohmann::json frameJson(const StaleBoundsFrame& f) {
    return {{"shadowedPixels", f.shadowed}, {"missingShadows", f.missing}, {"missingPercent", f.missingPercent}};
}

}  // namespace

int runMeasureStaleBounds(const MeasureOptions& options) {
    if (wantsMotion(options)) return fail("--stale-bounds: not with --motion (each measures its own frames)");
    if (!options.overlay.empty() || !options.causeOverlay.empty() || !options.softOverlay.empty() ||
        options.remeasureBench > 0 || options.light >= 0)
        return fail("--stale-bounds measures light 0 in two frames of its own: not with --overlay, --cause-overlay, "
                    "--soft-overlay, --remeasure-bench or --light");
    std::string error;
    const std::optional<double> degrees = parseFiniteOption(options.staleBounds, "--stale-bounds", error);
    if (!degrees) return fail(error);
    if (*degrees <= 0.0 || *degrees > 180.0)
        return fail("--stale-bounds " + options.staleBounds + ": the camera's turn must lie in (0, 180] degrees");
    std::optional<Settings> settings = settingsFromCli(options.preset, options.overrides, options.scene);
    if (!settings) return 2;
    if (error = checkViewSize(options.width, options.height); !error.empty()) return fail(error);
    if (error = checkMeasureMemory(options.width, options.height); !error.empty()) return fail(error);
    if (error = checkOutputs({{options.json, "--json"}}, {{options.scene, "--scene"}, {options.preset, "--preset"}});
        !error.empty())
        return fail(error);
    SceneLoadResult loaded = loadSceneForCommand(options.scene, {&*settings});
    if (!loaded.scene) return fail(loaded.error);
    const Scene& scene = *loaded.scene;
    try {
        HeadlessContext context;
        AccuracyMeter meter;
        const Camera camera = cameraFor(settings->camera, scene, double(options.width) / options.height);
        const StaleBoundsReport report =
            measureStaleBounds(meter, scene, *settings, camera, *degrees, options.width, options.height);
        if (!report.ok) return fail(report.error);
        std::cout << "scene " << scene.name << " (" << scene.triangleCount() << " triangles), "
                  << describeLightSource(*settings, scene) << "\n"
                  << "stale depth bounds, lights.0 (" << options.width << "x" << options.height
                  << "): the frame right after the camera turns " << report.turnDegrees << " degrees\n"
                  << std::fixed << std::setprecision(3);
        for (const StaleBoundsFrame* f : {&report.sameFrame, &report.previousFrame})
            std::cout << "  " << std::left << std::setw(52)
                      << (f == &report.sameFrame ? "bounds of this frame (sameFrame, 0 late):"
                                                 : "bounds of the frame before (previousFrame, 1 late):")
                      << std::right << " missing shadows " << f->missing << " of " << f->shadowed
                      << " truly shadowed pixels (" << f->missingPercent << " %)\n";
        std::cout << "  (missing: the reference shadows the pixel, the picture shows it lit; stale bounds leave "
                     "receivers beyond the last cascade for one frame)\n";
        if (!options.json.empty()) {
            nlohmann::json json = {{"scene", options.scene},
                                   {"preset", options.preset},
                                   {"light", 0},
                                   {"width", options.width},
                                   {"height", options.height},
                                   {"turnDegrees", report.turnDegrees},
                                   {"sameFrame", frameJson(report.sameFrame)},
                                   {"previousFrame", frameJson(report.previousFrame)}};
            if (error = writeJsonOutput(options.json, json); !error.empty()) return fail(error);
        }
    } catch (const std::exception& e) {
        return fail(e.what());
    }
    return 0;
}

}  // namespace shadowlab::cli
