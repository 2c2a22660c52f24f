#include "cli/measure_motion.h"

#include "accuracy/flicker.h"
#include "accuracy/light_isolation.h"
#include "cli/accuracy_output.h"
#include "cli/command_input.h"
#include "cli/flicker_output.h"
#include "cli/progress.h"
#include "cli/settings_from_cli.h"
#include "context/headless_context.h"
#include "image/image_io.h"
#include "light/scene_lights.h"
#include "scene/scene_source.h"
#include "settings/atomic_file.h"
#include "settings/user_config.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace shadowlab::cli {

namespace {

// The folder for --frames-out, created when missing; "" or why not.
std::string prepareFolder(const std::string& path) {
    const std::string error = ensureFolder(path);
    return error.empty() ? "" : "--frames-out: " + error;
}

}  // namespace

std::optional<double> parseFiniteOption(const std::string& text, const std::string& option, std::string& error) {
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(value)) {
        error = option + " '" + text + "': not a finite number";
        return std::nullopt;
    }
    return value;
}

std::optional<glm::dvec3> parseVectorOption(const std::string& text, const std::string& option, std::string& error) {
    std::vector<std::string> parts;
    std::stringstream in(text);
    for (std::string part; std::getline(in, part, ',');) parts.push_back(part);
    if (parts.size() != 3) {
        error = option + " '" + text + "': expected three numbers x,y,z";
        return std::nullopt;
    }
    glm::dvec3 v;
    for (int i = 0; i < 3; ++i) {
        const auto value = parseFiniteOption(parts[std::size_t(i)], option, error);
        if (!value) return std::nullopt;
        v[i] = *value;
    }
    return v;
}

bool wantsMotion(const MeasureOptions& o) {
    return !o.motion.empty() || o.frames != -1 || !o.step.empty() || !o.direction.empty() || !o.framesOut.empty();
}

int runMeasureMotion(const MeasureOptions& options) {
    if (options.motion.empty())
        return fail("--frames, --step, --direction and --frames-out measure flicker: they need --motion " +
                    motionNames());
    const std::optional<MotionKind> kind = parseMotion(options.motion);
    if (!kind) return fail("--motion '" + options.motion + "': unknown motion (" + motionNames() + ")");
    if (options.step.empty())
        return fail(std::string("--motion ") + motionName(*kind) + " needs --step S (" + motionInfo(*kind).unit +
                    " per frame)");
    if (!options.causeOverlay.empty()) return fail("--cause-overlay: not with --motion (flicker has its own --overlay)");
    if (!options.softOverlay.empty()) return fail("--soft-overlay: not with --motion (flicker has its own --overlay)");
    if (options.remeasureBench > 0) return fail("--remeasure-bench: not with --motion");
    Motion motion;
    motion.kind = *kind;
    motion.frames = options.frames == -1 ? kDefaultMotionFrames : options.frames;
    std::string error;
    const std::optional<double> step = parseFiniteOption(options.step, "--step", error);
    if (!step) return fail(error);
    motion.step = *step;
    if (!options.direction.empty()) {
        motion.direction = parseVectorOption(options.direction, "--direction", error);
        if (!motion.direction) return fail(error);
    }

    std::optional<Settings> settings = settingsFromCli(options.preset, options.overrides, options.scene);
    if (!settings) return 2;
    if (error = checkViewSize(options.width, options.height); !error.empty()) return fail(error);
    // The pictures' limits first: they hold on any machine, the memory check depends on this one.
    for (const NamedPath& picture : {NamedPath{options.overlay, "--overlay"}, NamedPath{options.framesOut, "--frames-out"}})
        if (error = checkPictureOutput(picture, {options.width, options.height, 4, 4, true, {}}); !error.empty())
            return fail(error);
    if (error = checkMeasureMemory(options.width, options.height); !error.empty()) return fail(error);
    if (error = checkOutputs({{options.json, "--json"}, {options.overlay, "--overlay"}},
                             {{options.scene, "--scene"}, {options.preset, "--preset"}});
        !error.empty())
        return fail(error);
    if (!options.framesOut.empty())
        if (error = prepareFolder(options.framesOut); !error.empty()) return fail(error);
    SceneLoadResult loaded = loadSceneForCommand(options.scene, {&*settings});
    if (!loaded.scene) return fail(loaded.error);
    const Scene& scene = *loaded.scene;
    if (options.light >= 0) {
        if (std::string why = unmeasurableReason(*settings, scene, std::size_t(options.light)); !why.empty())
            return fail("--light " + std::to_string(options.light) + ": " + why);
        motion.light = std::size_t(options.light);
    } else {
        const std::vector<std::size_t> casting = castingLights(*settings, scene);
        if (casting.empty()) return fail("--motion: no light casts a shadow, so nothing can flicker");
        motion.light = casting.front();
    }
    if (error = motionError(motion, scene.bounds); !error.empty()) return fail(error);

    try {
        HeadlessContext context;
        AccuracyMeter meter;
        const Camera camera = cameraFor(settings->camera, scene, double(options.width) / options.height);
        AccuracyProgress accuracyProgress;
        ProgressLine progress(
            "measure --motion", 0, "", [&] { return double(accuracyProgress.fraction.load()); },
            [&] { return accuracyProgress.stage(); });
        const FlickerReport report =
            measureFlicker(meter, scene, *settings, camera, options.width, options.height, motion, &accuracyProgress);
        progress.finish();
        if (!report.ok) return fail(report.error);
        for (const std::string& w : report.warnings) std::cerr << "warning: " << w << "\n";
        std::cout << "scene " << scene.name << " (" << scene.triangleCount() << " triangles), "
                  << describeLightSource(*settings, scene) << "\n";
        printFlicker(std::cout, report);
        if (!options.json.empty()) {
            nlohmann::json json = flickerToJson(report);
            json["scene"] = options.scene;
            json["preset"] = options.preset;
            const std::string text = json.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
            if (error = writeFileAtomically(options.json, text); !error.empty()) return fail(error);
            std::cout << "wrote " << options.json << "\n";
        }
        if (!options.overlay.empty()) {
            if (error = writePng(options.overlay, report.width, report.height, 4, report.overlayRgba.data(), false);
                !error.empty())
                return fail(error);
            std::cout << "wrote " << options.overlay << " (" << legendText(flickerLegend())
                      << ", union over the pairs; the last frame dimmed)\n";
        }
        if (!options.framesOut.empty()) {
            for (int half = 0; half < 2; ++half) {
                const int frame = report.worstPair + half;
                const std::string path =
                    (std::filesystem::path(options.framesOut) / ("frame-" + std::to_string(frame) + ".png")).string();
                const std::vector<std::uint8_t>& rgba = half == 0 ? report.worstPreviousRgba : report.worstCurrentRgba;
                if (error = writePng(path, report.width, report.height, 4, rgba.data(), false); !error.empty())
                    return fail(error);
                std::cout << "wrote " << path << " (frame " << frame << " of the worst pair, S x Lambert dimmed)\n";
            }
        }
    } catch (const std::exception& e) {
        return fail(e.what());
    }
    return 0;
}

}  // namespace shadowlab::cli
