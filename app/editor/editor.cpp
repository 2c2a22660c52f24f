#include "editor/editor.h"

#include "editor/editor_keys.h"
#include "editor/panels/panel_registry.h"
#include "editor/timeline.h"
#include "frame/screenshot.h"
#include "image/image_io.h"
#include "image/split_view.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_casters.h"
#include "settings/preset_io.h"
#include "settings/preset_scene.h"
#include "settings/settings_fields.h"
#include "settings/shipped_data.h"
#include "settings/user_config.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <sstream>

namespace shadowlab::editor {

namespace fs = std::filesystem;

namespace {

// The real clock: the editor's default clock, and the wall time a frame's rendering took (a measurement shown in
// Stats, not a decision).
double secondsNow() {
    using namespace std::chrono;
    static const steady_clock::time_point start = steady_clock::now();
    return duration<double>(steady_clock::now() - start).count();
}

bool isGltfPath(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".gltf" || ext == ".glb";
}

}  // namespace

Editor::Editor(EditorOptions options) : options_(std::move(options)) {
    if (!options_.clock) options_.clock = secondsNow;
    renderer_ = std::make_unique<Renderer>();
    frustum_ = std::make_unique<LightFrustumOverlay>();
    mapView_ = std::make_unique<ShadowMapView>();
    // Workers wake the host when they have something to show, so an idle host needs no timer to notice them.
    accuracyWorker_ = std::make_unique<AccuracyWorker>(options_.wake);
    state_.sweep.worker = std::make_unique<SweepWorker>(options_.wake);
    loader_.setFinishedCallback(options_.wake);
    state_.limits.maxTextureSize = renderer_->glInfo().maxTextureSize;
    state_.time = now();

    if (options_.shippedPresetsDir.empty()) {
        options_.shippedPresetsDir = shippedPresetsDir().string();
        if (options_.shippedPresetsDir.empty()) state_.say(shippedData().problem, true);
    }
    if (options_.userPresetsDir.empty()) options_.userPresetsDir = userPresetsDir().string();
    if (options_.recentFilesPath.empty()) options_.recentFilesPath = recentFilesPath().string();
    state_.userPresetsDir = options_.userPresetsDir;
    state_.screenshotDir = options_.screenshotDir;
    if (options_.recentFilesPath != "-") {
        RecentFilesLoad recent = loadRecentFiles(options_.recentFilesPath);
        state_.recentFiles = recent.files;
        if (!recent.error.empty()) state_.say(recent.error, true);
    }
    refreshPresetList();

    // The start preset: a path, else a shipped preset's name, else a user preset's name (as every command resolves it).
    const std::string preset = options_.preset.empty() ? "default" : options_.preset;
    const std::optional<PresetEntry> start = findPreset(preset, options_.shippedPresetsDir, options_.userPresetsDir);
    const std::string path = start ? start->path.string() : preset;
    const bool shipped = start && start->readOnly;
    if (std::string error = state_.preset.load(path, shipped, state_.settings); !error.empty())
        state_.say("preset " + preset + " not loaded: " + error + "; using built-in defaults", true);

    state_.sceneSpec = options_.scene;
    state_.scenePathInput = options_.scene;
    loader_.request(options_.scene);
    state_.loading = loader_.progress();
    lastCheckedSettings_ = state_.settings;

    // An autosave exists only after an exit that was not clean (a clean exit and a save remove it): offer it.
    autosavePath_ = options_.autosavePath.empty() ? shadowlab::autosavePath().string()
                    : options_.autosavePath == "-" ? std::string()
                                                    : options_.autosavePath;
    if (!autosavePath_.empty()) {
        AutosaveRead found = readAutosave(autosavePath_);
        if (!found.error.empty()) state_.say(found.error + " (left as it is)", true);
        if (found.autosave) {
            restoreOffer_ = std::move(found.autosave);
            openRestoreDialog_ = true;
        }
    }
}

Editor::~Editor() {
    accuracyWorker_.reset();  // cancels a running job and joins the worker
}

// ---------------------------------------------------------------------------------------------------------------
// Autosave

void Editor::keepSession() {
    // Not before the user has answered the offer: the file still holds the work of the session that crashed.
    if (autosavePath_.empty() || restoreOffer_) return;
    if (!state_.preset.dirty(state_.settings)) {
        dropAutosave();  // nothing unsaved: an older autosave would only offer stale edits
        return;
    }
    if (autosaved_ && *autosaved_ == state_.settings) return;
    std::string error = writeAutosave(autosavePath_, Autosave{state_.settings, state_.sceneSpec, state_.preset.path(),
                                                              state_.preset.shipped(), {}});
    if (error.empty()) {
        autosaved_ = state_.settings;
    } else if (error != autosaveError_) {
        state_.say(error + " (unsaved work is not kept)", true);
    }
    autosaveError_ = std::move(error);
}

void Editor::keepSessionBeforeRiskyChange() {
    if (state_.settings == lastCheckedSettings_) return;
    const SettingsDiff diff = diffSettings(lastCheckedSettings_, state_.settings);
    lastCheckedSettings_ = state_.settings;
    if (diff.invalidates & kInvalidatesVariant) keepSession();
}

void Editor::dropAutosave() {
    if (autosavePath_.empty() || restoreOffer_) return;
    if (std::string error = removeAutosave(autosavePath_); !error.empty()) state_.say(error, true);
    autosaved_.reset();
}

void Editor::restoreAutosave() {
    Autosave a = std::move(*restoreOffer_);
    restoreOffer_.reset();
    // The preset they were edited from, as its baseline (so the unsaved marker shows), then the kept settings.
    std::string note;
    if (!a.presetPath.empty()) {
        if (std::string error = state_.preset.load(a.presetPath, a.presetShipped, state_.settings); !error.empty())
            note = "; its preset did not load (" + error + ")";
    }
    state_.settings = a.settings;
    state_.fieldErrors.clear();
    state_.clampSelectedLight();
    lastCheckedSettings_ = state_.settings;
    autosaved_ = state_.settings;  // the file holds them until a save or a clean exit
    if (!a.scene.empty() && a.scene != state_.sceneSpec) {
        loader_.request(a.scene);  // no question: these are the settings the user wants on it
        state_.loading = loader_.progress();
    } else if (state_.scene) {
        resetCameraFromSettings();
    }
    state_.say("restored the unsaved settings of " + a.savedAt + " (preset " +
               (a.presetPath.empty() ? std::string("built-in defaults") : presetNameFromPath(a.presetPath)) +
               ", scene " + a.scene + ")" + note + "; save them to keep them");
}

// ---------------------------------------------------------------------------------------------------------------
// Frame work (before the UI)

void Editor::renderFrame() {
    const double t = now();
    const double dt = std::clamp(t - state_.time, 0.0, 0.25);
    state_.time = t;
    pollSceneLoad();
    advanceTimeline(state_, dt);
    poseShownScene(state_);
    if (state_.animateLight) {
        state_.animatedAzimuthDeg = std::fmod(state_.animatedAzimuthDeg + state_.animateDegreesPerSecond * dt, 360.0);
    }
    renderViewport();
    renderAbView();
    pollAccuracy();
    runProbe();
    runProfile();
    if (screenshotRequested_) takeScreenshot();
}

void Editor::pollSceneLoad() {
    if (std::optional<FinishedSceneLoad> done = loader_.poll()) {
        if (done->result.ok()) {
            auto scene = std::make_shared<const Scene>(std::move(*done->result.scene));
            std::ostringstream text;
            text << "loaded " << done->spec << " (" << scene->triangleCount() << " triangles) in " << std::fixed
                 << std::setprecision(2) << done->seconds << " s";
            // Edits declined with "Don't save" go now that the new scene is here (not before: the load could fail).
            if (state_.preset.sceneLoadFinished(true, state_.settings)) {
                state_.fieldErrors.clear();
                state_.clampSelectedLight();
            }
            adoptScene(std::move(scene), done->spec);
            state_.say(text.str());
        } else {
            const bool kept = state_.preset.dirty(state_.settings);
            state_.preset.sceneLoadFinished(false, state_.settings);
            state_.say(done->result.error + (kept && state_.scene ? " (your unsaved edits are kept)" : ""), true);
            if (!state_.scene) {
                // The start scene failed: show the default one so the editor is usable.
                SceneLoadResult fallback = loadScene(kDefaultSceneSpec);
                if (fallback.ok()) {
                    adoptScene(std::make_shared<const Scene>(std::move(*fallback.scene)), kDefaultSceneSpec);
                    state_.say(std::string("showing ") + kDefaultSceneSpec + " instead");
                }
            }
        }
    }
    state_.loading = loader_.progress();
}

void Editor::adoptScene(std::shared_ptr<const Scene> scene, const std::string& spec) {
    state_.scene = std::move(scene);
    state_.timeline.rest = state_.scene;  // shown posed at the settings' animation time
    state_.timeline.posedAs.reset();
    state_.timeline.playing = false;
    poseShownScene(state_);
    state_.sceneSpec = spec;
    state_.scenePathInput = spec;
    renderer_->sceneChanged();
    abRenderer_.sceneChanged();
    state_.frozenCascadeCamera.reset();  // it was the old scene's
    state_.viewMilliseconds.clear();
    for (std::size_t i = 0; i < state_.scene->warnings.size() && i < 3; ++i)
        state_.say(state_.scene->name + ": " + state_.scene->warnings[i]);
    // A new scene gets the preset's camera (auto-framed by default, and on a scene it was not tuned on).
    resetCameraFromSettings(/*announce=*/true);
    lastRendered_.reset();
    if (spec.rfind(kBuiltinPrefix, 0) != 0 && options_.recentFilesPath != "-") {
        state_.recentFiles.add(spec);
        if (std::string error = saveRecentFiles(options_.recentFilesPath, state_.recentFiles); !error.empty())
            state_.say(error, true);
    }
}

Settings Editor::previewed(Settings s) const {
    if (state_.animateLight && state_.animatedAzimuthDeg != 0.0 && state_.selectedLight < s.lights.size()) {
        LightSettings& light = s.lights[state_.selectedLight];
        // The preview turns the light around the vertical axis through the scene's centre.
        const glm::dmat4 turn =
            glm::rotate(glm::dmat4(1.0), glm::radians(state_.animatedAzimuthDeg), glm::dvec3(0.0, 1.0, 0.0));
        light.direction = glm::vec3(turn * glm::dvec4(glm::dvec3(light.direction), 0.0));
        const glm::dvec3 center = state_.scene && !state_.scene->bounds.empty
                                      ? glm::dvec3(state_.scene->bounds.center())
                                      : glm::dvec3(0.0);
        light.position = glm::vec3(center + glm::dvec3(turn * glm::dvec4(glm::dvec3(light.position) - center, 0.0)));
    }
    return s;
}

Editor::RenderKey Editor::renderKey() const {
    return RenderKey{effectiveSettings(),
                     orbit_->eye(),
                     orbit_->target(),
                     state_.scene.get(),
                     int(viewportRect_.z),
                     int(viewportRect_.w),
                     state_.showLightFrustum,
                     state_.showLightFrustum ? state_.selectedLight : 0,
                     state_.frozenCascadeCamera};
}

void Editor::renderViewport() {
    if (!state_.scene || !orbit_) return;
    const int w = int(viewportRect_.z);
    const int h = int(viewportRect_.w);
    if (w < 16 || h < 16) return;  // no UI built yet, or the panels cover the window
    if (cameraNeedsViewport_) resetCameraFromSettings();
    if (target_.width() != w || target_.height() != h) {
        if (std::string error = target_.resize(w, h); !error.empty()) {
            state_.say("viewport: " + error, true);
            return;
        }
        lastRendered_.reset();
    }
    keepSessionBeforeRiskyChange();  // also for changes made outside the UI (a search's result)
    RenderKey key = renderKey();
    // The accuracy overlay hides the main view: a camera move or resize alone then needs no pass (the overlay says
    // it is stale); a settings or scene change still renders, so the shadow map, its viewer and Stats follow the edit.
    const bool overlayHidesView = state_.accuracy.overlayShown();
    const bool unchanged = lastRendered_ && (overlayHidesView ? lastRendered_->settings == key.settings &&
                                                                      lastRendered_->scene == key.scene
                                                                : *lastRendered_ == key);
    if (unchanged) {
        ++state_.idleFrames;  // nothing changed: no pass runs, the viewport keeps its picture
        renderMapPicture(false);
        return;
    }

    const double start = secondsNow();
    FrameStats stats = renderer_->render(*state_.scene, key.settings, orbit_->toCamera(), target_,
                                         key.fitCamera ? &*key.fitCamera : nullptr);
    // A frame's error or warning is said when it appears, not again with every frame while it lasts (repeated,
    // it would replace the result of whatever the user did meanwhile on the status line).
    std::vector<std::string> problems = stats.ok ? stats.warnings : std::vector<std::string>{stats.error};
    for (std::string& warning : unknownCasterPathWarnings(*state_.scene, key.settings.casters))
        problems.push_back(std::move(warning));
    for (const std::string& problem : problems)
        if (std::find(frameProblems_.begin(), frameProblems_.end(), problem) == frameProblems_.end())
            state_.say(problem, true);
    frameProblems_ = std::move(problems);
    if (!stats.ok) {
        lastRendered_ = key;
        return;
    }
    // A map the GPU refused (too big, out of memory): the settings go back to the map still in use.
    // The frame reports its first view's map: the GPU may have refused that light's size or format.
    const auto first = std::find_if(stats.views.begin(), stats.views.end(), [](const auto& v) { return v.hasView; });
    if (first != stats.views.end() && !state_.settings.useSceneLights && first->light < state_.settings.lights.size() &&
        (stats.shadowMapResolution != state_.settings.lights[first->light].shadow.resolution ||
         stats.shadowMapFormat != state_.settings.lights[first->light].shadow.format)) {
        const std::size_t light = first->light;
        state_.fieldErrors["lights." + std::to_string(light) + ".shadow.resolution"] =
            stats.warnings.empty() ? "the GPU refused this shadow map; the previous one is kept" : stats.warnings.front();
        for (Settings* s : {&state_.settings, &key.settings}) {
            s->lights[light].shadow.resolution = stats.shadowMapResolution;
            s->lights[light].shadow.format = stats.shadowMapFormat;
        }
    }
    state_.clampSelectedLight();
    if (state_.showLightFrustum) {
        // The selected light's volume: its one view, a point light's six cube faces or its cascades (each in its
        // tint, with the frozen camera's slice it answers for).
        const std::vector<OverlayLines> lines = lightOverlayLines(
            stats, state_.selectedLight, FrustumOverlayStyle{}.color, key.fitCamera.has_value());
        if (std::string error = frustum_->draw(stats, lines, target_); !error.empty())
            state_.say("light frustum: " + error, true);
    }
    for (const ShadowViewStats& view : stats.views)
        if (view.ran && view.milliseconds) state_.viewMilliseconds[{view.light, view.kind, view.index}] = *view.milliseconds;
    state_.lastFrameMs = (secondsNow() - start) * 1000.0;
    const float shadowMs = stats.shadowPass.ran && stats.shadowPass.milliseconds ? float(*stats.shadowPass.milliseconds)
                                                                                 : 0.0f;
    state_.history.push(float(state_.lastFrameMs), shadowMs);
    mapPictureStale_ = mapPictureStale_ || stats.shadowPass.ran || stats.shadowMapReallocated ||
                       stats.momentsPass.ran || stats.blurPass.ran;
    if (stats.shadowPass.ran) state_.lastShadowPass = stats;
    state_.stats = std::move(stats);
    state_.haveStats = true;
    ++state_.renderedFrames;
    lastRendered_ = key;
    renderMapPicture(false);
}

void Editor::renderMapPicture(bool mapRedrawn) {
    MapViewerState& v = state_.viewer;
    mapPictureStale_ = mapPictureStale_ || mapRedrawn;
    const ShadowViewStats* view = state_.shownView();
    const ShadowMap* map = view ? renderer_->viewMap({view->light, view->kind, view->index}) : nullptr;
    if (v.width < 8 || v.height < 8 || !map || !map->valid()) return;
    const ShadowViewId id{view->light, view->kind, view->index};
    const MomentsLayer moments = renderer_->viewMomentsLayer(id);
    if (!moments.texture) v.options.channel = 0;  // a depth technique now: its depth is all there is
    const std::pair<std::size_t, int> shown{view->light, view->face};
    const bool changed = mapPictureStale_ || v.width != lastMapWidth_ || v.height != lastMapHeight_ ||
                         !(v.options == lastMapOptions_) || v.texture == 0 || shown != lastMapView_;
    if (changed) {
        v.error = mapView_->render(*map, view->space, mapPictureStale_ || shown != lastMapView_, v.options, v.width,
                                   v.height, &moments);
        if (v.error.empty()) {
            v.texture = mapView_->texture();
            v.textureWidth = mapView_->width();
            v.textureHeight = mapView_->height();
            v.shown = mapView_->shownRange();
            v.gridShown = mapView_->gridShown();
        }
        lastMapOptions_ = v.options;
        lastMapWidth_ = v.width;
        lastMapHeight_ = v.height;
        lastMapView_ = shown;
        mapPictureStale_ = false;
    }
    v.hoverDepth.reset();
    v.hoverMoments.reset();
    if (v.hoverTexel) v.hoverDepth = mapView_->depthAt(*map, v.hoverTexel->x, v.hoverTexel->y);
    if (v.hoverTexel && moments.texture)
        if (const std::vector<glm::vec4> m = renderer_->viewMoments(id, v.hoverTexel->x, v.hoverTexel->y, 1, 1);
            m.size() == 1)
            v.hoverMoments = m[0];
}

void Editor::takeScreenshot() {
    screenshotRequested_ = false;
    if (target_.width() == 0 || !state_.haveStats) {
        state_.lastScreenshot = "screenshot failed: nothing has been rendered yet";
        state_.say(state_.lastScreenshot, true);
        return;
    }
    const ShadowMap* map = screenshotWithMap_ ? &renderer_->shadowMap() : nullptr;
    const auto now = std::chrono::system_clock::now();
    PngText text = presetPngText(settingsToSave(), state_.sceneSpec);
    // While comparing, the picture is what the view shows: A left of the divider, B right of it, both labelled. It
    // carries B's preset (the one being edited; --preset shot.png loads it) and A's under its own keyword.
    const RenderTarget& a = abRenderer_.target();
    const bool split = state_.ab.active && state_.ab.haveStatsA && a.width() == target_.width() &&
                       a.height() == target_.height() && !state_.accuracy.overlayShown();
    ScreenshotResult result;
    if (split) {
        Settings settingsA = abSettingsA(state_);
        settingsA.camera = settingsToSave().camera;
        text.emplace_back(kPresetAPngKeyword, presetPngText(settingsA, state_.sceneSpec).front().second);
        const int w = target_.width(), h = target_.height();
        const std::optional<AccuracyViewKey> view = accuracyKey();
        const std::vector<std::uint8_t> picture =
            composeSplitView(topRowFirst(a.readColor(), w, h), topRowFirst(target_.readColor(), w, h), w, h,
                             double(state_.ab.divider), abLabel(state_, true, view), abLabel(state_, false, view));
        result = writeScreenshot(picture, w, h, state_.screenshotDir, map, now, text);
    } else {
        result = writeScreenshot(target_, state_.screenshotDir, map, now, text);
    }
    if (!result.ok()) {
        state_.lastScreenshot = "screenshot failed: " + result.error;
        state_.say(state_.lastScreenshot, true);
        return;
    }
    state_.lastScreenshot = result.viewPng;
    std::string said = "screenshot: " + result.viewPng;
    if (split) said += " (A/B as shown; it carries B's preset, A's as " + std::string(kPresetAPngKeyword) + ")";
    if (!result.shadowMapExr.empty()) said += " + " + result.shadowMapExr;
    if (!result.shadowMapPng.empty()) said += " + " + result.shadowMapPng;
    state_.say(said);
}

void Editor::refreshPresetList() {
    state_.presetList = listPresets(options_.shippedPresetsDir, options_.userPresetsDir);
}

// ---------------------------------------------------------------------------------------------------------------
// Actions

void Editor::requestScene(const std::string& spec) {
    if (spec.empty()) {
        state_.say("scene: enter a .gltf / .glb path or pick a built-in scene", true);
        return;
    }
    startSwitch({PendingSwitch::Scene, spec, false});
}

void Editor::requestPreset(const std::string& path, bool shipped) { startSwitch({PendingSwitch::Preset, path, shipped}); }

void Editor::requestQuit() { startSwitch({PendingSwitch::Quit, {}, false}); }

void Editor::startSwitch(PendingSwitch pending) {
    if (state_.preset.dirty(state_.settings)) {
        pendingSwitch_ = std::move(pending);
        openUnsavedDialog_ = true;
        return;
    }
    performSwitch(pending);
}

void Editor::performSwitch(const PendingSwitch& pending) {
    switch (pending.kind) {
        case PendingSwitch::Scene:
            // Unsaved edits were declined (or there were none): the scene opens with the preset as saved, once it
            // has loaded; until then (and if the load fails) the edits stay.
            if (state_.preset.dirty(state_.settings)) state_.preset.discardEditsOnSceneLoad();
            keepSession();  // a scene load compiles and allocates anew: keep the unsaved work first
            loader_.request(pending.target);
            state_.loading = loader_.progress();
            break;
        case PendingSwitch::Preset: {
            if (std::string error = state_.preset.load(pending.target, pending.shipped, state_.settings);
                !error.empty()) {
                state_.say(error, true);
                break;
            }
            state_.fieldErrors.clear();
            state_.selectedLight = 0;  // another preset's lights: start at its first
            state_.say("preset " + state_.preset.name() + " loaded from " + pending.target);
            if (state_.scene) resetCameraFromSettings(/*announce=*/true);
            break;
        }
        case PendingSwitch::Quit:
            quitConfirmed_ = true;
            dropAutosave();  // a clean exit: the user saved or declined what was unsaved
            break;
    }
}

void Editor::savePreset() {
    if (!state_.preset.canSaveInPlace()) {
        openSaveAs();
        return;
    }
    const Settings saved = settingsToSave();
    if (std::string error = state_.preset.save(saved, state_.sceneSpec); !error.empty()) {
        state_.say(error, true);
        return;
    }
    state_.settings = saved;
    dropAutosave();
    state_.say("saved preset " + state_.preset.path());
}

void Editor::openSaveAs() {
    openSaveAsDialog_ = true;
    const std::string& name = state_.preset.name();
    saveAsName_ = state_.preset.canSaveInPlace() ? name
                  : state_.preset.path().empty() ? std::string("my-preset")
                                                 : name + "-tuned";
    saveAsError_.clear();
}

void Editor::revertPreset() {
    state_.preset.revert(state_.settings);
    state_.fieldErrors.clear();
    state_.clampSelectedLight();  // the saved preset may have fewer lights
    state_.say("reverted to preset " + state_.preset.name());
}

void Editor::renamePreset(const std::string& name) {
    const std::string old = state_.preset.path();
    std::string error = presetNameProblem(name);
    const std::string path = (std::filesystem::path(old).parent_path() / (name + ".json")).string();
    if (error.empty()) error = state_.preset.rename(path);
    if (!error.empty()) {
        state_.say("rename: " + error, true);
        return;
    }
    refreshPresetList();
    state_.say("renamed " + old + " to " + path);
}

void Editor::deletePreset() {
    const std::string old = state_.preset.path();
    const std::string deleted = (std::filesystem::path(old).parent_path() / "deleted").string();
    if (std::string error = state_.preset.remove(deleted); !error.empty()) {
        state_.say("delete: " + error, true);
        return;
    }
    refreshPresetList();
    state_.say("moved " + old + " to " + deleted + "/ (recoverable); Save asks for a new name");
}

void Editor::requestScreenshot(bool withShadowMap) {
    screenshotRequested_ = true;
    screenshotWithMap_ = withShadowMap;
}

Camera Editor::presetCamera(std::string* note) const {
    const bool laidOut = viewportRect_.z >= 16.0f && viewportRect_.w >= 16.0f;
    const double aspect = laidOut ? double(viewportRect_.z) / double(viewportRect_.w) : 16.0 / 9.0;
    Settings adapted = state_.settings;
    std::string said = adaptPresetToScene(adapted, state_.preset.scene(), state_.sceneSpec);
    if (note) *note = std::move(said);
    return cameraFor(adapted.camera, *state_.scene, aspect);
}

void Editor::resetCameraFromSettings(bool announce) {
    std::string note;
    orbit_.emplace(presetCamera(&note), state_.scene->bounds);
    cameraNeedsViewport_ = !(viewportRect_.z >= 16.0f && viewportRect_.w >= 16.0f);
    if (announce && !note.empty()) state_.say(note);
    // A camera index this scene lacks (a preset of another version of the file): the free camera is shown.
    if (std::string error = sceneCameraError(state_.settings.camera, *state_.scene); !error.empty())
        state_.say(error + "; the free camera is shown", true);
}

void Editor::chooseSceneCamera(int index) {
    if (!state_.scene || !state_.edit("camera.sceneCamera", index)) return;
    if (index < 0) {
        state_.say("free camera: the view stays where it is");
        return;
    }
    if (std::string error = sceneCameraError(state_.settings.camera, *state_.scene); !error.empty()) {
        state_.say(error, true);
        return;
    }
    resetCameraFromSettings();
    state_.say("view: camera " + std::to_string(index) + " '" + state_.scene->cameras[std::size_t(index)].name +
               "' of " + state_.scene->name);
}

Settings Editor::settingsToSave() const {
    Settings out = state_.settings;
    if (!orbit_ || !state_.scene) return out;
    const Camera shown = orbit_->toCamera();
    const Camera preset = presetCamera();
    const double size = std::max(1e-12, glm::length(preset.position - preset.target));
    const bool moved = glm::length(shown.position - preset.position) > 1e-9 * size ||
                       glm::length(shown.target - preset.target) > 1e-9 * size;
    const bool sameScene = samePresetScene(state_.preset.scene(), state_.sceneSpec);
    const bool autoFrame = state_.settings.camera.autoFrame && sameScene;
    out.camera = recordedCamera(shown, autoFrame && !moved);
    // The file's camera stays chosen while the view is still its view; once moved, the position is what is saved.
    out.camera.sceneCamera = sameScene && !moved ? state_.settings.camera.sceneCamera : -1;
    return out;
}

void Editor::frameScene() {
    if (!orbit_ || !state_.scene) return;
    const double aspect = viewportRect_.w > 0 ? double(viewportRect_.z) / double(viewportRect_.w) : 1.0;
    orbit_->frame(*state_.scene, aspect);
}

void Editor::dropFiles(const std::vector<std::string>& paths) {
    for (const std::string& path : paths) {
        if (isGltfPath(path)) {
            requestScene(path);
            return;
        }
    }
    state_.say("dropped " + (paths.empty() ? std::string("nothing") : paths.front()) +
                   ": not a .gltf / .glb file; the current scene stays",
               true);
}

bool Editor::busy() const {
    if (state_.animateLight || state_.timeline.playing || screenshotRequested_ || windowScreenshotPath_ ||
        state_.probe.request || flyMoving_)
        return true;
    // Nothing to draw into (no scene yet, or a minimized window): wait for events rather than spin.
    if (!state_.scene || !orbit_ || viewportRect_.z < 16.0f || viewportRect_.w < 16.0f) return false;
    if (!lastRendered_) return true;
    const RenderKey key = renderKey();
    // A stale map picture matters only while the viewer shows it (its tab may be closed: it redraws when opened).
    const bool mapPictureDue = mapPictureStale_ && state_.viewer.width >= 8;
    return !(key == *lastRendered_) || mapPictureDue || abViewDue();
}

std::optional<std::string> Editor::takeWindowScreenshotRequest() {
    std::optional<std::string> path = std::move(windowScreenshotPath_);
    windowScreenshotPath_.reset();
    return path;
}

void Editor::windowScreenshotDone(const std::string& pathOrError, bool ok) {
    state_.lastScreenshot = ok ? pathOrError : "window screenshot failed: " + pathOrError;
    state_.say(ok ? "window screenshot: " + pathOrError : state_.lastScreenshot, !ok);
}

std::string Editor::windowTitle() const {
    std::string title = "ShadowLab - " + (state_.scene ? state_.scene->name : state_.sceneSpec) + " - " +
                        state_.preset.name();
    if (state_.preset.dirty(state_.settings)) title += " *";
    return title;
}

// ---------------------------------------------------------------------------------------------------------------
// Helpers for hosts

std::string writeFramebufferPng(const std::string& path, int width, int height) {
    std::vector<std::uint8_t> pixels(std::size_t(width) * height * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    for (std::size_t i = 3; i < pixels.size(); i += 4) pixels[i] = 255;  // the window is opaque
    return writePng(path, width, height, 4, pixels.data(), true);
}

std::string windowScreenshotPath(const std::string& folder) { return stampedPath(folder, "window", ".png"); }

std::string stampedPath(const std::string& folder, const std::string& kind, const std::string& extension) {
    std::error_code ec;
    fs::create_directories(folder, ec);
    const std::time_t t = std::time(nullptr);
    std::tm local{};
    localtime_r(&t, &local);
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &local);
    const std::string base = "shadowlab-" + kind + "-" + stamp;
    fs::path path = fs::path(folder) / (base + extension);
    for (int n = 2; fs::exists(path, ec); ++n) path = fs::path(folder) / (base + "-" + std::to_string(n) + extension);
    return path.string();
}

}  // namespace shadowlab::editor
