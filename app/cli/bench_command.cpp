#include "cli/bench_command.h"

#include "cli/command_input.h"
#include "cli/settings_from_cli.h"
#include "context/headless_context.h"
#include "frame/renderer.h"
#include "scene/scene_source.h"
#include "settings/atomic_file.h"
#include "settings/settings_fields.h"
#include "shadow/shadow_map.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <iomanip>
#include <iostream>

namespace shadowlab::cli {

namespace {

double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

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
    else return false;
    return true;
}

}  // namespace

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
                      << "' (allowed point, hardware2x2, pcfN with N in 1, 3, 5, 7, 9, poisson)\n";
            return 2;
        }
        if (std::vector<std::string> problems = settings.validate(); !problems.empty()) {
            std::cerr << "error: --filters " << describeKey(filter) << ": " << problems.front() << "\n";
            return 2;
        }
    }
    SceneLoadResult loaded = loadSceneForCommand(options.scene);
    if (!loaded.scene) return fail(loaded.error);
    const Scene& scene = *loaded.scene;
    try {
        HeadlessContext context;
        Renderer renderer;
        RenderTarget target;
        if (std::string e = target.resize(options.width, options.height); !e.empty()) return fail(e);
        const GlInfo& info = renderer.glInfo();
        std::cout << "bench: " << scene.name << " (" << scene.triangleCount() << " triangles), view " << options.width
                  << "x" << options.height << ", " << options.frames << " frames per row, shadow pass every frame\n"
                  << "gl: " << info.renderer << "\n";
        const Camera camera = cameraFor(base->camera, scene, double(options.width) / options.height);
        nlohmann::json rows = nlohmann::json::array();
        std::cout << std::left << std::setw(12) << "resolution" << std::setw(13) << "filter" << std::setw(12)
                  << "map MiB" << std::setw(14) << "shadow ms" << std::setw(14) << "main ms" << "wall ms/frame\n";
        std::string timing;
        for (int resolution : options.resolutions) {
            if (resolution > info.maxTextureSize) {
                std::cout << resolution << ": above GL_MAX_TEXTURE_SIZE " << info.maxTextureSize << ", skipped\n";
                continue;
            }
            for (const std::string& filter : options.filters) {
                Settings settings = *base;
                settings.lights[0].shadow.resolution = resolution;
                applyFilter(filter, settings);  // checked above
                std::vector<double> shadowMs, mainMs;
                double wallTotal = 0.0;
                for (int frame = -3; frame < options.frames; ++frame) {  // 3 warm-up frames
                    renderer.invalidateShadowMap();
                    const auto start = std::chrono::steady_clock::now();
                    FrameStats stats = renderer.render(scene, settings, camera, target);
                    renderer.waitForTimings(stats);
                    const double wall =
                        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
                    if (!stats.ok) {
                        std::cerr << "error: " << stats.error << "\n";
                        return 1;
                    }
                    timing = stats.timingSource;
                    if (frame < 0) continue;
                    wallTotal += wall;
                    if (stats.shadowPass.milliseconds) shadowMs.push_back(*stats.shadowPass.milliseconds);
                    if (stats.mainPass.milliseconds) mainMs.push_back(*stats.mainPass.milliseconds);
                }
                const double mib = double(renderer.shadowMap().memoryBytes()) / (1024.0 * 1024.0);
                const double shadow = median(shadowMs), main = median(mainMs);
                const double wall = wallTotal / std::max(options.frames, 1);
                std::cout << std::left << std::setw(12) << resolution << std::setw(13) << filter << std::setw(12)
                          << std::fixed << std::setprecision(1) << mib << std::setw(14) << std::setprecision(3)
                          << shadow << std::setw(14) << main << std::setprecision(2) << wall << "\n";
                rows.push_back({{"resolution", resolution}, {"filter", filter}, {"shadowMapMiB", mib},
                                {"shadowPassMs", shadow}, {"mainPassMs", main}, {"wallMsPerFrame", wall}});
            }
        }
        std::cout << "times: median of " << options.frames << " frames; source: " << timing << "\n";
        if (!options.json.empty()) {
            nlohmann::json doc = {{"scene", scene.name},      {"triangles", scene.triangleCount()},
                                  {"glRenderer", info.renderer}, {"timingSource", timing},
                                  {"width", options.width},     {"height", options.height},
                                  {"frames", options.frames},   {"rows", rows}};
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
