#include "cli/render_command.h"

#include "accuracy/accuracy_meter.h"
#include "accuracy/compare_label.h"
#include "cli/frame_report.h"
#include "cli/command_input.h"
#include "cli/settings_from_cli.h"
#include "context/headless_context.h"
#include "frame/renderer.h"
#include "gl/gl_errors.h"
#include "image/image_io.h"
#include "image/split_view.h"
#include "light/scene_lights.h"
#include "scene/scene_animation.h"
#include "scene/scene_source.h"
#include "settings/preset_io.h"
#include "settings/settings_fields.h"
#include "shadow/shadow_map_files.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <iostream>
#include <optional>
#include <tuple>

namespace shadowlab::cli {

int runRender(const RenderOptions& options) {
    std::vector<std::string> overrides = options.overrides;
    if (!options.view.empty()) overrides.push_back("view=" + options.view);
    std::optional<Settings> settings = settingsFromCli(options.preset, overrides, options.scene);
    if (!settings) return 2;
    // Checked against the settings' lights before any work; with useSceneLights the scene decides (after loading).
    // Only a --light the user gave is checked: without it nothing names a light (the map outputs choose below).
    if (options.light < -1 ||
        (options.light >= 0 && !settings->useSceneLights && std::size_t(options.light) >= settings->lights.size()))
        return fail("--light " + std::to_string(options.light) + ": there is no light " +
                    std::to_string(options.light) + " (the settings have " + std::to_string(settings->lights.size()) +
                    " light" + (settings->lights.size() == 1 ? "" : "s") + ")");
    if (std::string error = checkViewSize(options.width, options.height); !error.empty()) return fail(error);
    if (std::string error = checkOutputs({{options.out, "--out"}, {options.shadowMapExr, "--shadow-map"},
                                          {options.shadowMapPng, "--shadow-map-png"}},
                                         {{options.scene, "--scene"}, {options.preset, "--preset"},
                                          {options.compare, "--compare"}});
        !error.empty())
        return fail(error);
    if (std::string error = checkPictureOutput({options.out, "--out"}, {options.width, options.height, 4, 4, true, {}});
        !error.empty())
        return fail(error);

    std::optional<Settings> settingsB;
    if (!options.compare.empty()) {
        settingsB = settingsFromCli(options.compare, {}, options.scene);
        if (!settingsB) return 2;
        if (!(options.split >= 0.0 && options.split <= 1.0))
            return fail("--split " + std::to_string(options.split) + ": expected a fraction of the width in [0, 1]");
    } else if (options.measure) {
        return fail("--measure goes with --compare (for one preset's numbers use `shadowlab measure`)");
    }

    SceneLoadResult loaded = loadSceneForCommand(options.scene, {&*settings, settingsB ? &*settingsB : nullptr});
    if (!loaded.scene) return fail(loaded.error);
    const Scene& scene = *loaded.scene;
    // B at its own preset's animation time and choice: the scene was posed at A's (posing sets every transform).
    std::optional<Scene> posedB;
    if (settingsB && settingsB->animation != settings->animation) {
        posedB = scene;
        if (std::string error = poseScene(*posedB, settingsB->animation); !error.empty())
            return fail("--compare " + options.compare + ": " + error);
        if (!posedB->animations.empty()) std::cerr << "note: B: " << animationNote(*posedB, settingsB->animation) << "\n";
    }
    const Scene& sceneB = posedB ? *posedB : scene;

    // The map files' light and size are known before the render: a point light's faces unfold into a 4 x 3 cross.
    std::optional<std::size_t> mapLight;
    if (!options.shadowMapExr.empty() || !options.shadowMapPng.empty()) {
        // Without --light: the only light that casts, never light 0 of several silently.
        std::string chooseError;
        mapLight = chooseOneLight(*settings, scene, options.light,
                                  options.shadowMapExr.empty() ? "--shadow-map-png" : "--shadow-map", chooseError);
        if (!mapLight) return fail(chooseError);
        const LightSettings light = effectiveLights(*settings, scene)[*mapLight];  // a copy: the list is a temporary
        const int face = light.shadow.resolution;
        const bool cube = light.type == LightType::Point;
        const int width = cube ? 4 * face : face, height = cube ? 3 * face : face;
        const std::string what = "light " + std::to_string(*mapLight) + "'s " +
                                 (cube ? "six " + std::to_string(face) + "² faces as one cross"
                                       : std::to_string(face) + "² map") + ", float depth";
        for (const auto& [output, png] : {std::pair{NamedPath{options.shadowMapPng, "--shadow-map-png"}, true},
                                          std::pair{NamedPath{options.shadowMapExr, "--shadow-map"}, false}})
            if (std::string error = checkPictureOutput(output, {width, height, 1, 4, png, what}); !error.empty())
                return fail(error);
    }

    try {
#ifndef NDEBUG
        // Debug builds report every GL error through KHR_debug.
        HeadlessContext context(/*debug=*/true);
        gl::enableDebugOutput();
#else
        HeadlessContext context;
#endif
        Renderer renderer;
        RenderTarget target;
        if (std::string error = target.resize(options.width, options.height); !error.empty()) return fail(error);
        const Camera camera = cameraFor(settings->camera, scene, double(options.width) / options.height);
        FrameStats stats = renderer.render(scene, *settings, camera, target);
        if (!stats.ok) return fail(stats.error);
        renderer.waitForTimings(stats);
        for (const std::string& w : stats.warnings) std::cerr << "warning: " << w << "\n";
        for (const std::string& e : gl::takeDebugErrors()) std::cerr << "GL error: " << e << "\n";

        std::vector<std::uint8_t> pixels = target.readColor();
        bool flip = true;  // GL rows (bottom first) unless composed top-first below
        // The picture carries the preset that made it, with the scene and the camera used (render --preset shot.png).
        Settings used = *settings;
        used.camera = recordedCamera(camera, settings->camera.autoFrame);
        used.camera.sceneCamera = settings->camera.sceneCamera;  // the file's camera, when one was used
        if (settingsB) {
            // B from the same camera, with its own renderer (its maps are B's own); then one split picture.
            Renderer rendererB;
            RenderTarget targetB;
            if (std::string error = targetB.resize(options.width, options.height); !error.empty()) return fail(error);
            FrameStats statsB = rendererB.render(sceneB, *settingsB, camera, targetB);
            if (!statsB.ok) return fail(options.compare + ": " + statsB.error);
            rendererB.waitForTimings(statsB);
            std::vector<std::string> labelA = compareLabel("A", options.preset.empty() ? "default" : options.preset, stats);
            std::vector<std::string> labelB = compareLabel("B", options.compare, statsB);
            if (options.measure) {
                AccuracyMeter meter;  // one reference for both sides when the light and view are the same
                for (auto [side, sideScene, label] : {std::tuple{&*settings, &scene, &labelA},
                                                      std::tuple{&*settingsB, &sceneB, &labelB}}) {
                    const AccuracyReport report =
                        meter.measure(*sideScene, *side, camera, options.width, options.height);
                    if (!report.ok) return fail("--measure: " + report.error);
                    label->push_back(accuracyLine(report));
                    // The numbers in text too, with the truly shadowed pixels (they follow each side's pose).
                    std::cout << label->front() << ": " << label->back() << ", truly shadowed "
                              << report.counts.shadowed << " of " << report.counts.measured << " measured pixels\n";
                }
            }
            pixels = composeSplitView(topRowFirst(pixels, options.width, options.height),
                                      topRowFirst(targetB.readColor(), options.width, options.height), options.width,
                                      options.height, options.split, labelA, labelB);
            flip = false;
        }
        if (std::string error = writePng(options.out, target.width(), target.height(), 4, pixels.data(), flip,
                                         presetPngText(used, options.scene));
            !error.empty())
            return fail(error);
        printFrameReport(std::cout, scene, renderer.glInfo(), stats);
        std::cout << "wrote " << options.out << " (" << target.width() << "x" << target.height() << ")\n";

        if (!options.shadowMapExr.empty() || !options.shadowMapPng.empty()) {
            // The chosen light's map; a point light's six faces as an unfolded cross.
            const std::size_t light = *mapLight;
            const ShadowMap* map = renderer.viewMap(light, -1);
            // A cascaded light: one cascade's map (--map-view), the nearest by default.
            const std::vector<ShadowView> views = frameViewsOf(stats, light);
            std::string cascade;
            if (!views.empty() && views.front().kind == ShadowViewKind::Cascade) {
                std::string viewError;
                const std::optional<std::size_t> v =
                    options.mapView.empty() ? std::optional<std::size_t>(0) : findView(views, options.mapView, viewError);
                if (!v) return fail(viewError.replace(0, 6, "--map-view"));
                map = renderer.viewMap(views[*v].id());
                cascade = " " + viewSuffix(views[*v].kind, views[*v].index);
            } else if (!options.mapView.empty()) {
                return fail("--map-view " + options.mapView + ": light " + std::to_string(light) +
                            " has no cascades (--map-view chooses among a cascaded light's maps)");
            }
            std::array<const ShadowMap*, 6> faces{};
            for (int f = 0; f < 6; ++f) faces[std::size_t(f)] = renderer.viewMap(light, f);
            const bool cube = faces[0] != nullptr;
            if (!map && !cube)
                return fail("--light " + std::to_string(light) + ": light " + std::to_string(light) +
                            " has no shadow map (it is off or casts no shadow)");
            const ShadowMapFilesResult files =
                cube ? writeCubeShadowMapFiles(faces, options.shadowMapExr, options.shadowMapPng)
                     : writeShadowMapFiles(*map, options.shadowMapExr, options.shadowMapPng);
            if (!files.ok()) return fail(files.error);
            const int size = cube ? faces[0]->resolution() : map->resolution();
            const std::string shape = cube ? "a cross of six " + std::to_string(size) + "² faces (+Y above; -X +Z +X -Z; "
                                             "-Y below)"
                                           : std::to_string(size) + "²";
            if (!options.shadowMapExr.empty())
                std::cout << "wrote " << options.shadowMapExr << " (light " << light << cascade << ", " << shape
                          << ", float depth)\n";
            if (!options.shadowMapPng.empty())
                std::cout << "wrote " << options.shadowMapPng << " (depth " << files.pngRange.min << " .. "
                          << files.pngRange.max << " stretched to black .. light grey; white = no caster)\n";
        }
    } catch (const std::exception& e) {
        return fail(e.what());
    }
    return 0;
}

}  // namespace shadowlab::cli
