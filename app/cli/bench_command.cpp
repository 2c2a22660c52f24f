#include "cli/bench_command.h"

#include "shading/filters/filter_technique.h"

#include "cli/command_input.h"
#include "cli/settings_from_cli.h"
#include "context/headless_context.h"
#include "frame/timed_frames.h"
#include "light/scene_lights.h"
#include "scene/scene_source.h"
#include "settings/atomic_file.h"
#include "settings/settings_fields.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <iomanip>
#include <iostream>

namespace shadowlab::cli {

namespace {

// "pcf5" -> kind pcf, kernel 5; "poisson", "point", "hardware2x2" as they are.
bool applyFilter(const std::string& name, Settings& settings) {
    if (name.rfind("pcf", 0) == 0 && name.size() > 3) {
        settings.filter.kind = FilterKind::Pcf;
        const char* end = name.data() + name.size();
        const auto [ptr, ec] = std::from_chars(name.data() + 3, end, settings.filter.kernel);
        return ec == std::errc{} && ptr == end;  // validate() then checks the kernel size
    }
    if (name == "point") settings.filter.kind = FilterKind::Point;
    else if (name == "hardware2x2") settings.filter.kind = FilterKind::Hardware2x2;
    else if (name == "poisson") settings.filter.kind = FilterKind::Poisson;
    else {
        // The moments techniques and PCSS by their filter.kind name (their keys as the preset and --set give them).
        for (const FilterTechnique* t : filterTechniques())
            if ((t->moments || t->ownLookup) && name == t->name) {
                settings.filter.kind = t->kind;
                return true;
            }
        return false;
    }
    return true;
}

}  // namespace

nlohmann::json benchLightsJson(const Settings& effective) {
    nlohmann::json lights = nlohmann::json::array();
    for (std::size_t i = 0; i < effective.lights.size(); ++i) {
        const LightSettings& l = effective.lights[i];
        const bool casts = l.enabled && l.castsShadows;
        lights.push_back({{"index", i}, {"type", lightTypeName(l.type)}, {"enabled", l.enabled},
                          {"castsShadows", casts}, {"views", casts ? (l.type == LightType::Point ? 6 : 1) : 0}});
    }
    return lights;
}

int runBench(const BenchOptions& options) {
    std::optional<Settings> base = settingsFromCli(options.preset, options.overrides, options.scene);
    if (!base) return 2;
    // Every row's settings and the output path are checked before the scene, the context and the timing runs.
    if (std::string error = checkOutputFolder(options.json, "--json"); !error.empty()) return fail(error);
    if (std::string error = checkViewSize(options.width, options.height); !error.empty()) return fail(error);
    for (int resolution : options.resolutions) {
        Settings settings = *base;
        if (std::string e = findSettingsField("shadow.resolution")->set(settings, resolution); !e.empty()) {
            std::cerr << "error: --resolutions: " << e << "\n";
            return 2;
        }
    }
    for (const std::string& filter : options.filters) {
        Settings settings = *base;
        if (!applyFilter(filter, settings)) {
            std::cerr << "error: --filters: unknown filter '" << describeKey(filter)
                      << "' (allowed point, hardware2x2, pcfN with N in 1, 3, 5, 7, 9, poisson, vsm, evsm2, evsm4, msm, pcss)\n";
            return 2;
        }
        if (std::vector<std::string> problems = settings.validate(); !problems.empty()) {
            std::cerr << "error: --filters " << describeKey(filter) << ": " << problems.front() << "\n";
            return 2;
        }
    }
    SceneLoadResult loaded = loadSceneForCommand(options.scene, {&*base});
    if (!loaded.scene) return fail(loaded.error);
    const Scene& scene = *loaded.scene;
    // The lights the frames use (a scene's own with useSceneLights): the rows set each one's map resolution.
    const Settings effective = withEffectiveLights(*base, scene);
    try {
        HeadlessContext context;
        Renderer renderer;
        RenderTarget target;
        if (std::string e = target.resize(options.width, options.height); !e.empty()) return fail(e);
        const GlInfo& info = renderer.glInfo();
        std::cout << "bench: " << scene.name << " (" << scene.triangleCount() << " triangles), view " << options.width
                  << "x" << options.height << ", " << options.frames << " frames per row, shadow pass every frame\n"
                  << "gl: " << info.renderer << "\n";
        const std::size_t lightCount = effective.lights.size();
        std::cout << (lightCount == 0 ? std::string("lights: none (no shadow pass: the rows time the main pass only)")
                      : lightCount == 1 ? std::string("lights: 1 (the resolution column is its map's)")
                                        : "lights: " + std::to_string(lightCount) +
                                              " (the resolution column applies to every light's map; bench --lights "
                                              "times each view)")
                  << "\n";
        const Camera camera = cameraFor(base->camera, scene, double(options.width) / options.height);
        nlohmann::json rows = nlohmann::json::array();
        std::cout << std::left << std::setw(12) << "resolution" << std::setw(13) << "filter" << std::setw(12)
                  << "map MiB" << std::setw(14) << "shadow ms" << std::setw(12) << "moments ms" << std::setw(10)
                  << "blur ms" << std::setw(10) << "mips ms" << std::setw(14) << "main ms" << "wall ms/frame\n";
        std::string timing;
        for (int resolution : options.resolutions) {
            if (resolution > info.maxTextureSize) {
                std::cout << resolution << ": above GL_MAX_TEXTURE_SIZE " << info.maxTextureSize << ", skipped\n";
                continue;
            }
            for (const std::string& filter : options.filters) {
                Settings settings = effective;
                for (LightSettings& light : settings.lights) light.shadow.resolution = resolution;  // every light's map
                applyFilter(filter, settings);  // checked above
                const TimedFrames timed = timeFrames(renderer, scene, settings, camera, target, options.frames);
                if (!timed.ok) {
                    std::cerr << "error: " << timed.error << "\n";
                    return 1;
                }
                timing = timed.timingSource;
                const double mib = double(timed.last.shadowMapBytes) / (1024.0 * 1024.0);  // every light's maps
                const double shadow = timed.shadowMs, main = timed.mainMs, wall = timed.wallMsPerFrame;
                std::cout << std::left << std::setw(12) << resolution << std::setw(13) << filter << std::setw(12)
                          << std::fixed << std::setprecision(1) << mib << std::setw(14) << std::setprecision(3)
                          << shadow << std::setw(12) << timed.momentsMs << std::setw(10) << timed.blurMs << std::setw(10) << timed.mipsMs << std::setw(14)
                          << main << std::setprecision(2) << wall << "\n";
                rows.push_back({{"resolution", resolution}, {"filter", filter}, {"shadowMapMiB", mib},
                                {"shadowPassMs", shadow}, {"momentsPassMs", timed.momentsMs},
                                {"blurPassMs", timed.blurMs}, {"mipsPassMs", timed.mipsMs}, {"mainPassMs", main}, {"wallMsPerFrame", wall}});
            }
        }
        std::cout << "times: median of " << options.frames << " frames; source: " << timing << "\n";
        if (!options.json.empty()) {
            nlohmann::json doc = {{"scene", scene.name},      {"triangles", scene.triangleCount()},
                                  {"glRenderer", info.renderer}, {"timingSource", timing},
                                  {"width", options.width},     {"height", options.height},
                                  {"frames", options.frames},   {"lights", benchLightsJson(effective)},
                                  {"rows", rows}};
            const std::string text = doc.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
            if (std::string error = writeFileAtomically(options.json, text); !error.empty())
                return fail("--json " + options.json + ": " + error);
            std::cout << "wrote " << options.json << "\n";
        }
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}

}  // namespace shadowlab::cli
