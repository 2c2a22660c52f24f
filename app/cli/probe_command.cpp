#include "cli/probe_command.h"
#include "cli/json_output.h"

#include "cli/command_input.h"
#include "cli/settings_from_cli.h"
#include "accuracy/light_isolation.h"
#include "context/headless_context.h"
#include "light/scene_lights.h"
#include "probe/probe_description.h"
#include "scene/scene_source.h"
#include "settings/settings_fields.h"

#include <charconv>
#include <iostream>

namespace shadowlab::cli {

bool parsePixel(const std::string& text, int& x, int& y, std::string& error, const std::string& option) {
    const std::size_t comma = text.find(',');
    auto number = [](std::string_view s, int& out) {
        const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
        return ec == std::errc() && end == s.data() + s.size() && !s.empty();
    };
    if (comma == std::string::npos || !number(std::string_view(text).substr(0, comma), x) ||
        !number(std::string_view(text).substr(comma + 1), y)) {
        error = option + " '" + text + "': expected X,Y (two integers, y down from the top), e.g. " + option +
                " 640,360";
        return false;
    }
    return true;
}

int runProbe(const ProbeOptions& options) {
    int x = 0, y = 0;
    std::string pixelError;
    if (!parsePixel(options.pixel, x, y, pixelError)) return fail(pixelError);
    std::optional<Settings> settings = settingsFromCli(options.preset, options.overrides, options.scene);
    if (!settings) return 2;
    if (std::string error = checkViewSize(options.width, options.height); !error.empty()) return fail(error);
    if (std::string error = checkPixelInView("--pixel", options.pixel, x, y, options.width, options.height);
        !error.empty())
        return fail(error);
    if (std::string error = checkOutputFolder(options.json, "--json"); !error.empty()) return fail(error);
    SceneLoadResult loaded = loadSceneForCommand(options.scene, {&*settings});
    if (!loaded.scene) return fail(loaded.error);
    const Scene& scene = *loaded.scene;

    // Which lights: --light N, else every shadow-casting light, each probed alone (its own S on GPU and CPU).
    std::string chooseError;
    const std::optional<std::vector<std::size_t>> chosen = chooseLights(*settings, scene, options.light, "probe", chooseError);
    if (!chosen) return fail(chooseError);
    const std::vector<std::size_t>& lights = *chosen;

    try {
        HeadlessContext context;
        Renderer renderer;
        PixelProbe probe;
        const Camera camera = cameraFor(settings->camera, scene, double(options.width) / options.height);
        std::cout << "scene " << scene.name << "\n";
        nlohmann::json perLight = nlohmann::json::array();
        bool disagrees = false;
        for (std::size_t index : lights) {
            std::string error;
            const std::optional<Settings> one = isolateLight(*settings, scene, index, error);
            if (!one) return fail(error);
            if (error = probe.capture(renderer, scene, *one, camera, options.width, options.height, index);
                !error.empty())
                return fail("light " + std::to_string(index) + ": " + error);
            for (const std::string& w : probe.stats().warnings) std::cerr << "warning: " << w << "\n";
            std::optional<AccuracyReport> measured;
            if (options.measure) {
                AccuracyMeter meter;
                measured = meter.measure(scene, *one, camera, options.width, options.height);
                if (!measured->ok) return fail("--measure: light " + std::to_string(index) + ": " + measured->error);
            }
            std::optional<std::size_t> view;
            if (!options.view.empty() && !(view = findView(probe.views(), options.view, error)))
                return fail(error);
            const PixelProbeReport report = probe.at(x, y, measured ? &*measured : nullptr, view);
            if (!report.ok) return fail("light " + std::to_string(index) + ": " + report.error);
            for (const std::string& line : describeProbe(report)) std::cout << line << "\n";
            perLight.push_back(probeToJson(report));
            disagrees = disagrees || !report.agrees;
            if (!report.agrees)  // (true when not compared: a --view the GPU does not read there)
                std::cerr << "error: light " << index
                          << ": the CPU's shadow factor and the GPU's disagree at this pixel (a bug)\n";
        }
        if (!options.json.empty()) {
            // One light: the probe itself (as the editor's Save JSON writes it); several: each under "lights".
            nlohmann::json json = perLight.size() == 1 ? perLight[0] : nlohmann::json{{"lights", perLight}};
            json["scene"] = options.scene;
            json["preset"] = options.preset;
            if (std::string error = writeJsonOutput(options.json, json); !error.empty()) return fail(error);
        }
        if (disagrees) return 1;
    } catch (const std::exception& e) {
        return fail(e.what());
    }
    return 0;
}

}  // namespace shadowlab::cli
