#include "cli/profile_command.h"
#include "cli/json_output.h"

#include "accuracy/light_isolation.h"
#include "cli/command_input.h"
#include "cli/probe_command.h"
#include "cli/settings_from_cli.h"
#include "context/headless_context.h"
#include "image/image_io.h"
#include "probe/depth_profile_output.h"
#include "scene/scene_source.h"
#include "settings/settings_fields.h"

#include <iostream>

namespace shadowlab::cli {

int runProfile(const ProfileOptions& options) {
    glm::ivec2 from{0}, to{0};
    std::string error;
    if (!parsePixel(options.from, from.x, from.y, error, "--from") || !parsePixel(options.to, to.x, to.y, error, "--to"))
        return fail(error);
    std::optional<Settings> settings = settingsFromCli(options.preset, options.overrides, options.scene);
    if (!settings) return 2;
    if (error = checkViewSize(options.width, options.height); !error.empty()) return fail(error);
    for (const auto& [name, text, point] : {std::tuple{"--from", options.from, from}, std::tuple{"--to", options.to, to}})
        if (error = checkPixelInView(name, text, point.x, point.y, options.width, options.height); !error.empty())
            return fail(error);
    if (options.plotWidth < 200 || options.plotHeight < 120 || options.plotWidth > 8192 || options.plotHeight > 8192)
        return fail("--plot-width/--plot-height " + std::to_string(options.plotWidth) + "x" +
                    std::to_string(options.plotHeight) + ": expected 200..8192 x 120..8192");
    if (error = checkOutputFolder(options.out, "--out"); !error.empty()) return fail(error);
    if (error = checkOutputFolder(options.json, "--json"); !error.empty()) return fail(error);
    SceneLoadResult loaded = loadSceneForCommand(options.scene, {&*settings});
    if (!loaded.scene) return fail(loaded.error);
    const Scene& scene = *loaded.scene;
    const std::optional<std::size_t> light = chooseOneLight(*settings, scene, options.light, "profile", error);
    if (!light) return fail(error);
    const std::optional<Settings> one = isolateLight(*settings, scene, *light, error);
    if (!one) return fail(error);

    try {
        HeadlessContext context;
        Renderer renderer;
        PixelProbe probe;
        const Camera camera = cameraFor(settings->camera, scene, double(options.width) / options.height);
        if (error = probe.capture(renderer, scene, *one, camera, options.width, options.height, *light); !error.empty())
            return fail(error);
        for (const std::string& w : probe.stats().warnings) std::cerr << "warning: " << w << "\n";
        std::optional<std::size_t> view;
        if (!options.view.empty() && !(view = findView(probe.views(), options.view, error))) return fail(error);
        const DepthProfile profile = depthProfile(probe, from, to, view);
        if (!profile.ok) return fail(profile.error);
        std::cout << "scene " << scene.name << ", light " << *light << " (" << lightTypeName(one->lights.front().type)
                  << ")"
                  << (!options.view.empty() ? ", " + options.view + " (--view)"
                      : probe.views().size() > 1 ? ", each point in the view holding it (of " +
                                                       std::to_string(probe.views().size()) + "; --view chooses one)"
                                                 : std::string())
                  << "\n"
                  << "line " << options.from << " -> " << options.to << ": " << profile.samples.size()
                  << " samples, " << profile.surfaces << " on surfaces, " << profile.acne << " acne, "
                  << profile.peterPanning << " Peter Panning\n";
        const PlotImage image = drawLinePlot(depthProfilePlot(profile), options.plotWidth, options.plotHeight);
        if (error = writePng(options.out, image.width, image.height, 4, image.rgba.data(), false); !error.empty())
            return fail(error);
        std::cout << "wrote " << options.out << "\n";
        if (!options.json.empty()) {
            nlohmann::json json = depthProfileToJson(profile);
            json["scene"] = options.scene;
            json["preset"] = options.preset;
            json["view"] = {options.width, options.height};
            json["light"] = *light;
            if (!options.view.empty()) json["lightView"] = options.view;
            if (error = writeJsonOutput(options.json, json); !error.empty()) return fail(error);
        }
    } catch (const std::exception& e) {
        return fail(e.what());
    }
    return 0;
}

}  // namespace shadowlab::cli
