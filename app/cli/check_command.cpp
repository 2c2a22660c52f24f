#include "cli/check_command.h"

#include "frame/camera.h"

#include "accuracy/check_limits.h"
#include "accuracy/flicker.h"
#include "accuracy/light_isolation.h"
#include "accuracy/light_accuracy.h"
#include "cli/accuracy_output.h"
#include "cli/check_report.h"
#include "cli/command_input.h"
#include "cli/progress.h"
#include "cli/settings_from_cli.h"
#include "context/headless_context.h"
#include "image/image_io.h"
#include "scene/scene_animation.h"
#include "settings/atomic_file.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>

namespace shadowlab::cli {

namespace {

namespace fs = std::filesystem;

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

int badInput(const std::string& message) {
    fail(message);
    return kCheckBadInput;
}

// The one case of the flags, checked as the case file's are, naming the flags.
std::optional<CheckCase> caseFromFlags(const CheckOptions& options, std::string& error) {
    CheckCase c = options.flagCase;
    if (c.scene.empty()) {
        error = "check needs a case file (shadowlab check CASES.json) or a case from flags (--scene S and a limit)";
        return std::nullopt;
    }
    for (const CheckLimitInfo& info : checkLimitInfos())
        if (const std::optional<double>& v = c.limits.*info.member)
            if (std::string why = checkLimitValueError(info, *v); !why.empty()) {
                error = std::string(info.flag) + " " + std::to_string(*v) + ": " + why;
                return std::nullopt;
            }
    if (error = checkCaseHasLimits(c, "check"); !error.empty()) {
        std::string flags;
        for (const CheckLimitInfo& info : checkLimitInfos()) flags += (flags.empty() ? "" : ", ") + std::string(info.flag);
        error += " (give one of " + flags + ")";
        return std::nullopt;
    }
    const bool flicker = c.limits.maxFlickerPercent.has_value();
    for (const char* flag : {"--motion", "--step", "--frames"})
        if (!flicker && std::find(options.caseFlags.begin(), options.caseFlags.end(), flag) != options.caseFlags.end()) {
            error = std::string(flag) + " says how flicker is measured: it needs --max-flicker";
            return std::nullopt;
        }
    if (c.step && !std::isfinite(*c.step)) {
        error = "--step: not a finite number";
        return std::nullopt;
    }
    if (c.frames < 2 || c.frames > kMaxMotionFrames) {
        error = "--frames " + std::to_string(c.frames) + ": flicker compares consecutive frames, so it needs 2.." +
                std::to_string(kMaxMotionFrames) + " frames";
        return std::nullopt;
    }
    if (!options.motion.empty()) {
        const std::optional<MotionKind> kind = parseMotion(options.motion);
        if (!kind) {
            error = "--motion '" + options.motion + "': unknown motion (" + motionNames() + ")";
            return std::nullopt;
        }
        c.motion = *kind;
    }
    c.name = defaultCheckCaseName(c);
    return c;
}

// "FILE: case 2 (\"name\")" or "" for the flags' case: how messages name a case.
std::string caseWhere(const CheckOptions& options, std::size_t index, const CheckCase& c) {
    if (options.file.empty()) return {};
    return options.file + ": case " + std::to_string(index + 1) + " (\"" + c.name + "\")";
}

std::string prefixed(const std::string& where, const std::string& message) {
    return where.empty() ? message : where + ": " + message;
}

// An overlay's file name: the case's number and its name with anything but letters, digits, '.', '_' and '-' as '-'.
std::string overlayName(std::size_t index, const std::string& name) {
    std::string slug;
    for (char ch : name.substr(0, 60))
        slug += (std::isalnum(static_cast<unsigned char>(ch)) || ch == '.' || ch == '_' || ch == '-') ? ch : '-';
    char number[16];
    std::snprintf(number, sizeof number, "%02zu-", index + 1);
    return number + slug + ".png";
}

// Measures one case: every casting light and the whole picture, then each light's flicker when a flicker limit is
// set. `error` on the outcome when it cannot be measured.
void measureCase(CheckOutcome& o, const Settings& settings, const Scene& scene, AccuracyMeter& meter,
                 AccuracyProgress& progress, const std::string& outDir) {
    const CheckCase& c = *o.check;
    const Camera camera = cameraFor(settings.camera, scene, double(c.width) / c.height);
    const bool flicker = c.limits.maxFlickerPercent.has_value();
    // The progress bar's share of each job: the measurement, then one flicker motion per light.
    const std::size_t jobs = 1 + (flicker ? castingLights(settings, scene).size() : 0);
    progress.fraction = 0.0f;
    progress.setStage("");
    progress.base = 0.0f;
    progress.span = 1.0f / float(jobs);
    const ManyLightsReport many = measureLights(meter, scene, settings, camera, c.width, c.height, {}, &progress);
    if (!many.ok) {
        o.error = many.error;
        return;
    }
    for (const LightAccuracy& light : many.lights) {
        const std::string label = lightLabel(light.index, light.type);
        for (CheckFigure& f : accuracyFigures(c.limits, label, light.report)) o.figures.push_back(std::move(f));
        o.numbers.emplace_back(label, numbersToJson(light.report));
        for (const std::string& w : light.report.warnings) o.notes.push_back("warning: " + label + ": " + w);
    }
    if (many.lights.size() > 1) {
        for (CheckFigure& f : wholePictureFigures(c.limits, many.whole)) o.figures.push_back(std::move(f));
        o.numbers.emplace_back("whole picture", numbersToJson(many.whole));
    }
    for (const NotMeasuredLight& n : many.notMeasured) o.notes.push_back("not measured: " + n.reason);
    // The overlay of what was measured, before flicker: it is there even when a motion cannot be played.
    if (!outDir.empty()) {
        const std::string path = (fs::path(outDir) / overlayName(o.index, c.name)).string();
        if (std::string error = writePng(path, many.width, many.height, 4, many.overlayRgba.data(), false);
            !error.empty()) {
            o.error = "overlay: " + error;
            return;
        }
        o.overlay = path;
    }

    if (flicker) {
        Motion motion;
        motion.kind = c.motion;
        motion.step = c.step.value_or(motionInfo(c.motion).typicalStep);
        motion.frames = c.frames;
        std::size_t job = 1;
        for (const LightAccuracy& light : many.lights) {
            motion.light = light.index;
            if (std::string why = motionError(motion, scene.bounds); !why.empty()) {
                o.error = "flicker: " + why;
                return;
            }
            progress.base = float(job) / float(jobs);
            progress.span = 1.0f / float(jobs);
            ++job;
            const FlickerReport report =
                measureFlicker(meter, scene, settings, camera, c.width, c.height, motion, &progress);
            if (!report.ok) {
                o.error = "flicker of " + lightLabel(light.index, light.type) + ": " + report.error;
                return;
            }
            char subject[160];
            std::snprintf(subject, sizeof subject, "%s under %s motion (%g %s per frame, %d frames)",
                          lightLabel(light.index, light.type).c_str(), motionName(c.motion), motion.step,
                          motionInfo(c.motion).unit, motion.frames);
            for (CheckFigure& f : flickerFigures(c.limits, subject, report.maxFlickerPercent))
                o.figures.push_back(std::move(f));
        }
    }
}

}  // namespace

int runCheck(const CheckOptions& options) {
    // Every input is checked before any case runs: a typo in the last case must not cost the others' time.
    std::vector<CheckCase> cases;
    std::string error;
    if (!options.file.empty()) {
        if (!options.caseFlags.empty())
            return badInput(options.caseFlags.front() + ": a case file lists its own cases; the case flags (" +
                            options.caseFlags.front() + ", ...) describe one case without a file");
        std::optional<std::vector<CheckCase>> loaded = loadCheckCases(options.file, error);
        if (!loaded) return badInput(error);
        cases = std::move(*loaded);
    } else {
        std::optional<CheckCase> one = caseFromFlags(options, error);
        if (!one) return badInput(error);
        cases.push_back(std::move(*one));
    }
    std::vector<Settings> settings;
    bool settingsOk = true;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const CheckCase& c = cases[i];
        const std::string where = caseWhere(options, i, c);
        std::optional<Settings> s = settingsFromCli(c.preset, c.overrides, c.scene, where);
        settingsOk = settingsOk && s.has_value();
        settings.push_back(s.value_or(Settings{}));
        if (std::string e = checkViewSize(c.width, c.height); !e.empty()) return badInput(prefixed(where, e));
        if (std::string e = checkMeasureMemory(c.width, c.height); !e.empty()) return badInput(prefixed(where, e));
    }
    if (!settingsOk) return kCheckBadInput;

    // The overlays go beside the JUnit file unless --out-dir says where.
    std::string outDir = options.outDir;
    if (outDir.empty() && !options.junit.empty()) {
        fs::path junit(options.junit);
        outDir = (junit.parent_path() / (junit.stem().string() + "-overlays")).string();
    }
    std::vector<NamedPath> inputs = {{options.file, "CASES.json"}};
    for (const CheckCase& c : cases) {
        inputs.push_back({resolvePresetPath(c.preset), "preset"});
        inputs.push_back({c.scene, "scene"});
    }
    if (!outDir.empty()) {
        for (std::size_t i = 0; i < cases.size(); ++i)
            if (std::string e = checkPictureOutput({(fs::path(outDir) / overlayName(i, cases[i].name)).string(),
                                                    "the overlay"},
                                                   {cases[i].width, cases[i].height, 4, 4, true, {}});
                !e.empty())
                return badInput(prefixed(caseWhere(options, i, cases[i]), e));
        std::error_code ec;
        fs::create_directories(outDir, ec);
        if (!fs::is_directory(outDir, ec))
            return badInput((options.outDir.empty() ? "the overlays' folder " : "--out-dir ") + outDir +
                            ": cannot create the folder" + (ec ? " (" + ec.message() + ")" : ""));
    }
    // After --out-dir, which may be the JUnit file's folder.
    if (std::string e = checkOutputs({{options.junit, "--junit"}}, inputs); !e.empty()) return badInput(e);

    const auto start = std::chrono::steady_clock::now();
    std::vector<CheckOutcome> outcomes(cases.size());
    try {
        HeadlessContext context;
        AccuracyMeter meter;
        AccuracyProgress accuracyProgress;
        ProgressLine progress(
            "check", cases.size(), "cases", [&] { return double(accuracyProgress.fraction.load()); },
            [&] { return accuracyProgress.stage(); });
        // Consecutive cases on one scene load it once (and keep the meter's BVH).
        std::string loadedSpec;
        SceneLoadResult loaded;
        for (std::size_t i = 0; i < cases.size(); ++i) {
            CheckOutcome& o = outcomes[i];
            o.check = &cases[i];
            o.index = i;
            const auto caseStart = std::chrono::steady_clock::now();
            if (loadedSpec != cases[i].scene || !loaded.scene) {
                meter.sceneChanged();
                progress.above([&] { loaded = loadSceneForCommand(cases[i].scene, {}); });
                loadedSpec = cases[i].scene;
            }
            // Each case's camera.sceneCamera against the scene (consecutive cases share one load), and the scene at
            // the case's animation time (posing sets every transform: one case's pose does not carry into the next).
            std::string caseError = loaded.scene ? sceneCameraError(settings[i].camera, *loaded.scene) : "";
            if (loaded.scene && caseError.empty()) caseError = poseScene(*loaded.scene, settings[i].animation);
            if (!loaded.scene)
                o.error = loaded.error;
            else if (!caseError.empty())
                o.error = caseError;
            else
                measureCase(o, settings[i], *loaded.scene, meter, accuracyProgress, outDir);
            o.seconds = secondsSince(caseStart);
            progress.setDone(i + 1);
            progress.above([&] {
                std::cout << checkLine(o, cases.size()) << "\n";
                for (const std::string& note : o.notes) std::cerr << note << "\n";
            });
        }
    } catch (const std::exception& e) {
        return badInput(e.what());
    }

    std::size_t failed = 0, errors = 0;
    for (const CheckOutcome& o : outcomes) {
        failed += o.failed() ? 1 : 0;
        errors += o.error.empty() ? 0 : 1;
    }
    std::cout << "check: " << cases.size() << " case" << (cases.size() == 1 ? "" : "s") << ", "
              << cases.size() - failed - errors << " passed, " << failed << " failed, " << errors
              << " not measured\n";
    if (!options.junit.empty()) {
        const std::string suite = options.file.empty() ? "shadowlab check" : options.file;
        if (std::string e = writeFileAtomically(options.junit, checkJunitXml(suite, outcomes, secondsSince(start)));
            !e.empty())
            return badInput("--junit " + options.junit + ": " + e);
        std::cout << "wrote " << options.junit << "\n";
    }
    if (!outDir.empty()) std::cout << "overlays in " << outDir << "\n";
    if (errors > 0) return kCheckBadInput;
    return failed > 0 ? kCheckLimitBroken : 0;
}

}  // namespace shadowlab::cli
