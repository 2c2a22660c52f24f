#pragma once
// The editor without a window system: Dear ImGui panels around a viewport that shows the two-pass renderer. A host
// (the GLFW window in app/editor_window, or a headless test) owns the GL and ImGui contexts and calls, per frame:
//   editor.renderFrame();   // passes for what changed last frame (idle frames run none), map picture, screenshots
//   ImGui::NewFrame(); editor.buildUi(); ImGui::Render();   // then draws ImGui's draw data
// Rendering before the UI keeps every texture the UI shows valid for the frame that draws it.
#include "editor/accuracy_worker.h"
#include "editor/autosave.h"
#include "editor/editor_state.h"
#include "editor/panels/panel_registry.h"
#include "frame/orbit_camera.h"
#include "frame/render_target.h"
#include "frame/renderer.h"
#include "overlay/light_frustum_overlay.h"
#include "overlay/shadow_map_view.h"
#include "scene/async_scene_loader.h"

#include <imgui.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace shadowlab::editor {

struct EditorOptions {
    std::string scene = kDefaultSceneSpec;  // "builtin:NAME" or a .gltf / .glb path
    std::string preset;                     // a preset path or a shipped preset's name; empty = "default"
    std::string shippedPresetsDir;          // empty = shippedPresetsDir() (see settings/shipped_data.h)
    std::string userPresetsDir;             // empty = userPresetsDir() (see settings/user_config.h)
    std::string recentFilesPath;            // empty = recentFilesPath(); "-" = do not remember
    std::string screenshotDir = "screenshots";
    std::string autosavePath;               // empty = autosavePath() (see settings/user_config.h); "-" = none
    // Seconds on a steady clock, read for every timing decision (Auto's delay, the light animation). Empty = the
    // real steady clock; a test sets its own and moves it.
    std::function<double()> clock;
    // Called from any thread when a worker has something to show (an accuracy job or a scene load finished, a sweep
    // point measured): the window host wakes its event loop with it (glfwPostEmptyEvent). Must be thread-safe.
    std::function<void()> wake;
};

class Editor final : public EditorActions {
public:
    // Needs a current GL 4.5 context and an ImGui context. Throws std::runtime_error if the renderer cannot start.
    // A preset that does not load is reported and built-in defaults are used.
    explicit Editor(EditorOptions options);
    ~Editor() override;

    void renderFrame();
    void buildUi();

    // True while frames must keep coming without input (the light animating, a change not yet rendered, a
    // screenshot or probe asked for); otherwise the host may sleep (see secondsUntilNextFrame).
    bool busy() const;
    // When a host with no input pending needs the next frame: 0 = now (busy), a time in seconds (a worker's progress
    // to show, Auto's delay falling due), or nullopt = only on input or options.wake (nothing is running or due).
    std::optional<double> secondsUntilNextFrame() const;
    // Ctrl+Q or the window's close button: asks about unsaved changes first. quitConfirmed() once it may close.
    void requestQuit();
    bool quitConfirmed() const { return quitConfirmed_; }
    // Files dropped onto the window: the first .gltf / .glb is loaded.
    void dropFiles(const std::vector<std::string>& paths);
    // Ctrl+F12: the host writes the whole window to this path after drawing it (then calls windowScreenshotDone).
    std::optional<std::string> takeWindowScreenshotRequest();
    void windowScreenshotDone(const std::string& pathOrError, bool ok);
    std::string windowTitle() const;

    EditorState& state() { return state_; }
    const Renderer& renderer() const { return *renderer_; }
    const RenderTarget& viewportTarget() const { return target_; }
    // The Shadow map viewer's newest picture (RGBA, row 0 = bottom), for tests.
    std::vector<std::uint8_t> mapViewPixels() const { return mapView_->readPixels(); }
    const OrbitCamera* orbitCamera() const { return orbit_ ? &*orbit_ : nullptr; }
    ImVec4 viewportRect() const { return viewportRect_; }  // x, y, w, h in window pixels
    AccuracyWorker& accuracyWorker() { return *accuracyWorker_; }  // for tests (its step hook)

    // EditorActions
    void requestScene(const std::string& spec) override;
    void requestPreset(const std::string& path, bool shipped) override;
    void savePreset() override;
    void openSaveAs() override;
    void revertPreset() override;
    void renamePreset(const std::string& name) override;
    void deletePreset() override;
    void requestScreenshot(bool withShadowMap) override;
    void frameScene() override;
    void chooseSceneCamera(int index) override;
    void saveProbeJson() override;
    void measureAccuracy() override;
    void suggestBias() override;
    void measureFlicker() override;
    void cancelAccuracy() override;
    std::optional<AccuracyViewKey> currentView() const override { return accuracyKey(); }
    void keepSession() override;
    // The autosave found at start, while the user has not answered whether to restore it.
    const std::optional<Autosave>& restoreOffer() const { return restoreOffer_; }

private:
    struct PendingSwitch {
        enum Kind { Scene, Preset, Quit } kind = Scene;
        std::string target;
        bool shipped = false;
    };
    // What the last rendered frame was made from; an identical next frame runs no pass.
    struct RenderKey {
        Settings settings;
        glm::dvec3 eye{0.0}, target{0.0};
        const Scene* scene = nullptr;
        int width = 0, height = 0;
        bool frustum = false;
        std::size_t frustumLight = 0;  // whose volume the overlay draws (the selected light)
        std::optional<FitCamera> fitCamera;  // the frozen camera the cascades fit to
        bool operator==(const RenderKey&) const = default;
    };
    RenderKey renderKey() const;  // what a frame now would be made from

    double now() const { return options_.clock(); }  // the editor's clock (seconds)
    void pollSceneLoad();
    void adoptScene(std::shared_ptr<const Scene> scene, const std::string& spec);
    void renderViewport();
    void renderMapPicture(bool mapRedrawn);
    void takeScreenshot();
    void refreshPresetList();
    Settings effectiveSettings() const { return previewed(state_.settings); }  // the edited settings, previewed
    Settings previewed(Settings s) const;  // `s` plus the light animation's preview
    std::optional<AccuracyViewKey> accuracyKey() const;  // what a measurement now would be made for
    void startAccuracyJob(AccuracyJobKind kind, bool automatic = false);  // automatic: Auto's, not a button's
    void pollAccuracy();
    void adoptAccuracyResult(AccuracyJobResult result);
    void adoptFlickerResult(FlickerReport flicker, double seconds);
    void startLiveJob(const AccuracyViewKey& key);      // Auto's live count on the worker
    void adoptLiveResult(AccuracyJobResult result);
    void uploadAccuracyOverlay();
    void probeViewportInput(ImVec2 imagePos);  // a click (no drag) or P held over the view asks for a probe
    void drawProbeMarker(ImVec2 imagePos);     // a ring around the probed pixel
    void runProbe();
    std::string captureProbe(const AccuracyViewKey& key);  // the probe's frame for key.light alone                           // the pending probe, or the same pixel again once the view changed
    void drawProfileLine(ImVec2 imagePos);     // the depth profile's line (Ctrl+drag draws it)
    void runProfile();                         // the drawn line's depth profile, again once the view changed
    // A/B (editor_ab.cpp): A's passes when it changed, the toolbar's buttons, the divider (an item submitted before
    // the view's so it wins the hover), both images with their labels.
    void renderAbView();
    bool abViewDue() const;
    void abToolbar();
    void abDividerInput(ImVec2 imagePos, ImVec2 imageSize);
    bool drawAbSplit(ImVec2 imagePos, ImVec2 imageSize);  // false when A has no picture yet (B is drawn whole)

    void handleShortcuts();
    ImVec4 viewportWindowRect() const;
    void drawViewport();
    void viewModeCombo();
    // "freeze cascades": keeps the cascades fitted to the view's camera as it is now (or lets them follow it again).
    void freezeCascadesToggle();
    void drawOverlayNotes(ImVec2 imagePos, ImVec2 imageSize);
    // Bottom right, while the view or the frustum shows cascades: each cascade's colour and index, and whether they
    // are frozen.
    void drawCascadeLegend(ImVec2 imagePos, ImVec2 imageSize);
    void viewportCameraInput(ImVec2 pos, ImVec2 size);
    // Fly mode while the right button is held on the view: mouse look, WASD / Q E travel per second of the clock.
    void flyInput();
    // Alt+click: orbits turn around the surface under the cursor.
    void pickPivot(ImVec2 imagePos);
    void closePopupOnEscape();
    void drawPanels();
    void drawSidebar(Sidebar side, PanelContext& ctx, const Panel* wanted);
    void drawUnsavedChangesDialog();
    void drawRestoreDialog();  // the autosave found at start: Restore / Discard
    void restoreAutosave();
    // A change of the settings that compiles shaders or allocates maps (a new variant: resolution, format, light set,
    // filter) keeps the session first; checked after the UI and before the viewport renders, so before it acts.
    void keepSessionBeforeRiskyChange();
    void dropAutosave();  // a clean exit or a save: nothing unsaved to restore
    void drawSaveAsDialog();
    void drawStatusBar();
    void performSwitch(const PendingSwitch& pending);
    void startSwitch(PendingSwitch pending);

    EditorOptions options_;
    EditorState state_;
    std::unique_ptr<Renderer> renderer_;
    std::unique_ptr<LightFrustumOverlay> frustum_;
    std::unique_ptr<ShadowMapView> mapView_;
    RenderTarget target_;
    AbRenderer abRenderer_;  // A's view while comparing
    AsyncSceneLoader loader_;
    std::optional<OrbitCamera> orbit_;
    std::optional<RenderKey> lastRendered_;
    std::vector<std::string> frameProblems_;  // the newest rendered frame's error or warnings (said once each)
    bool cameraFromPreset_ = true;  // the next adopted scene / loaded preset sets the camera from the settings
    ImVec4 viewportRect_{0, 0, 0, 0};  // the image area, where the renderer draws
    // The camera was set before the viewport had a size: set it again (auto-framing depends on the aspect) once
    // the viewport is laid out.
    bool cameraNeedsViewport_ = false;
    // A press on the view becomes a camera drag only if its first move stays inside the view (see
    // viewportCameraInput); otherwise it is refused until the button is let go.
    bool cameraDragLive_ = false, cameraDragRefused_ = false;
    std::optional<double> flyClock_;  // the clock at the previous fly-mode frame (none: not flying)
    bool flyMoving_ = false;          // a travel key is held while flying: frames must keep coming
    void resetCameraFromSettings(bool announce = false);
    // The camera the preset gives on this scene and viewport (auto-framed on a scene it was not tuned on).
    Camera presetCamera(std::string* note = nullptr) const;
    // The settings a save writes: the view camera actually shown (autoFrame kept only while the user has not moved
    // the camera away from the preset's).
    Settings settingsToSave() const;

    std::optional<PendingSwitch> pendingSwitch_;  // waiting for the unsaved-changes answer
    bool openUnsavedDialog_ = false;
    bool openSaveAsDialog_ = false;
    std::optional<PendingSwitch> afterSaveAs_;    // a switch to finish once Save As succeeded
    std::string saveAsName_;
    std::string saveAsError_;
    bool quitConfirmed_ = false;

    // Autosave (autosave.h): the file, what it holds now (not rewritten unchanged), the settings last checked for a
    // risky change, the offer found at start and the last write error (said once).
    std::string autosavePath_;
    std::optional<Settings> autosaved_;
    Settings lastCheckedSettings_;
    std::optional<Autosave> restoreOffer_;
    bool openRestoreDialog_ = false;
    std::string autosaveError_;

    bool screenshotRequested_ = false;
    bool screenshotWithMap_ = false;
    std::optional<std::string> windowScreenshotPath_;
    bool mapPictureStale_ = true;
    ShadowMapViewOptions lastMapOptions_;
    std::pair<std::size_t, int> lastMapView_{0, -2};  // (light, face) of the viewer's newest picture
    int lastMapWidth_ = 0, lastMapHeight_ = 0;
    double lastRenderTime_ = 0.0;

    // Accuracy: the worker (its thread and GL context start with the first job), what the running job measures,
    // and the automatic measurement's bookkeeping.
    std::unique_ptr<AccuracyWorker> accuracyWorker_;
    std::unique_ptr<PixelProbe> probe_;  // made on the first probe (its G-buffer shaders)
    std::optional<AccuracyViewKey> accuracyJobKey_;
    bool accuracyJobAutomatic_ = false;                   // the running job was started by Auto
    std::optional<AccuracyViewKey> lastSeenAccuracyKey_;  // the view as of the newest change
    double lastAccuracyChange_ = 0.0;                     // when the view or settings last changed
    std::optional<AccuracyViewKey> autoMeasured_;         // the view Auto last measured (never twice)
    bool autoDue_ = false;                                // Auto will measure this view once it is still
    std::optional<AccuracyViewKey> liveJobKey_;           // what the running live count measures
    std::optional<AccuracyJobKind> queuedJob_;            // asked for while a live count held the worker
};

// Reads the bound framebuffer (width x height, GL rows) and writes it as PNG; "" or why it failed.
std::string writeFramebufferPng(const std::string& path, int width, int height);

// "shadowlab-window-YYYYMMDD-HHMMSS.png" in `folder` (created if missing); never an existing file.
std::string windowScreenshotPath(const std::string& folder);
// The same rule for any kind of file: "shadowlab-KIND-YYYYMMDD-HHMMSS.EXT".
std::string stampedPath(const std::string& folder, const std::string& kind, const std::string& extension);

}  // namespace shadowlab::editor
