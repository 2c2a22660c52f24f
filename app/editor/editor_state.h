#pragma once
// What the editor's panels read and change: the edited Settings, the scene, the preset session, the last frame's
// stats, messages and the named controls' rectangles. Panels change Settings only through edit().
#include "editor/ab_compare.h"
#include "editor/accuracy_state.h"
#include "editor/control_rects.h"
#include "editor/preset_session.h"
#include "editor/probe_state.h"
#include "editor/settings_edit.h"
#include "editor/sweep_state.h"
#include "frame/frame_stats.h"
#include "frame/renderer.h"
#include "overlay/shadow_map_view.h"
#include "scene/async_scene_loader.h"
#include "scene/scene.h"
#include "settings/preset_catalog.h"
#include "settings/recent_files.h"
#include "settings/settings.h"

#include <nlohmann/json.hpp>

#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace shadowlab::editor {

struct Message {
    std::string text;
    bool error = false;
    double time = 0.0;  // seconds since the editor started
    std::string clock;  // local wall-clock time, "HH:MM:SS" (the message log shows it)
    bool automatic = false;  // said by the editor on its own (Auto's measurement), not as a user action's result
    long serial = 0;         // order of saying (the status line names the message it shows by it)
};

// An automatic change the editor made on top of the user's edit (e.g. DepthBias re-expressed for a new depth
// format), which the status line offers to undo.
struct UndoStep {
    Settings before;   // the settings before the user's edit
    std::string note;  // what was changed and why, the status message it goes with
    std::size_t light = 0;  // the light whose format and DepthBias the step changed
};

struct FrameHistory {
    static constexpr std::size_t kLength = 120;
    std::deque<float> frameMs;       // wall time of frames that rendered
    std::deque<float> shadowPassMs;  // 0 where the shadow pass did not run
    void push(float frame, float shadow);
};

// The Shadow map viewer panel's view of the map: options and size it asks for, the picture the editor made.
struct MapViewerState {
    ShadowMapViewOptions options;
    MapZoomPan zoomPan;
    int width = 0, height = 0;              // picture size the panel asks for (0 = panel hidden)
    std::optional<glm::ivec2> hoverTexel;   // set by the panel; the editor reads the stored depth there
    std::optional<float> hoverDepth;
    std::optional<glm::vec4> hoverMoments;  // a moments technique: the stored moments there
    unsigned texture = 0;                   // GL texture of the newest picture (0 = none)
    int textureWidth = 0, textureHeight = 0;
    ShownDepthRange shown;
    bool gridShown = false;
    // The view the viewer shows (a light and, for a point light, a cube face); when the frame has no such view the
    // viewer shows the selected light's first view, else the frame's first one (see EditorState::shownView).
    std::size_t light = 0;
    ShadowViewKind kind = ShadowViewKind::Single;  // with `index`: a cube face or a cascade
    int index = 0;
    std::string error;                      // why the newest picture could not be made
    std::string shownLabel;                 // a moments technique: which light, view and channel, and the range
};

// The Timeline panel's player. The time and the animation played are settings (animation.time, animation.play);
// playing, looping and speed are how the editor moves the time (never saved).
struct TimelineState {
    bool playing = false;
    bool loop = true;
    float speed = 1.0f;                       // seconds of animation per second of the clock
    std::shared_ptr<const Scene> rest;        // the scene as loaded; EditorState::scene is it posed
    std::optional<AnimationSettings> posedAs;  // what EditorState::scene was posed at (none: not yet)
    std::string error;                        // why the scene could not be posed (an unknown animation.play)
};

struct EditorState {
    Settings settings;                              // what the next frame renders
    // The light the Light, Shadow map and Projection panels edit (an index into settings.lights; kept in range by
    // clampSelectedLight, which every removal and preset load calls). With no lights there is nothing to edit.
    std::size_t selectedLight = 0;
    std::map<std::string, std::string> fieldErrors;  // key -> why its last edit was refused (cleared on success)
    EditLimits limits;

    std::string sceneSpec;                // "builtin:textbook" or a path
    std::shared_ptr<const Scene> scene;   // never null once the editor runs
    PresetSession preset;
    TimelineState timeline;

    // View options that are not settings (they never mark the preset as changed).
    bool showLightFrustum = true;
    // "freeze cascades": the camera the cascades stay fitted to while the view moves on (set when frozen, from the
    // view's camera at that moment); none: they follow the view. The frustum overlay then also draws each cascade's
    // slice of that camera's frustum, so the user can fly out and look at the fit.
    std::optional<FitCamera> frozenCascadeCamera;
    bool animateLight = false;
    float animateDegreesPerSecond = 30.0f;
    double animatedAzimuthDeg = 0.0;  // added to the light's azimuth while animating (a preview)
    // Fly mode's speed, times the scene-sized base (OrbitCamera::flySpeed): the wheel changes it while flying.
    double flySpeedFactor = 1.0;

    FrameStats stats;           // the newest frame the renderer drew
    bool haveStats = false;
    FrameStats lastShadowPass;  // the newest frame whose shadow pass ran (its triangles, casters, time)
    FrameHistory history;
    std::map<ShadowViewId, double> viewMilliseconds;  // each view's newest measured pass time (shown while it is kept)
    long renderedFrames = 0;
    long idleFrames = 0;        // frames where nothing changed and no pass ran
    double lastFrameMs = 0.0;   // wall time of the newest rendered frame (renderer + readiness)

    MapViewerState viewer;
    AccuracyState accuracy;  // the Accuracy panel and the viewport's accuracy overlay
    ProbeState probe;        // the Probe panel: why the clicked pixel is lit or shadowed
    SweepPanelState sweep;   // the Cost vs accuracy panel
    AbState ab;              // A/B: the snapshot A beside the edited settings B
    // A panel to bring forward: its sidebar tab is selected on the next frame (e.g. Probe after a click on the view).
    std::string showPanel;

    // Scene panel
    std::optional<SceneLoadProgress> loading;  // while a scene loads
    RecentFiles recentFiles;
    std::string scenePathInput;

    // Presets panel
    std::vector<PresetEntry> presetList;  // shipped first, then the user's
    std::string userPresetsDir;

    // Screenshots
    std::string screenshotDir = "screenshots";
    bool screenshotWithShadowMap = false;
    std::string lastScreenshot;  // path of the newest screenshot, or why it failed

    static constexpr std::size_t kMessagesKept = 50;
    std::vector<Message> messages;  // newest last, the last kMessagesKept
    std::optional<UndoStep> undo;   // offered by the status line while its note is the message it shows
    ControlRects controls;
    double time = 0.0;

    // "lights.<selectedLight>.<key>" for a key within a light ("shadow.depthBias", "type"): the panels' one way
    // to name the selected light's fields.
    std::string lightKey(std::string_view key) const;
    // The selected light, or nullptr when there are no lights.
    const LightSettings* selected() const;
    void clampSelectedLight();
    // The frame's view the viewer shows (see MapViewerState::light/face), nullptr when no light casts.
    const ShadowViewStats* shownView() const;
    // The selected light's views that have a light space (a point light's six faces), for its volume overlay.
    std::vector<const ShadowViewStats*> selectedLightViews() const;

    // Applies an edit through the key table; on refusal records it under the key and as an error message.
    // A new shadow.depthFormat re-expresses DepthBias so it keeps its world size (see depth_format_change.h) and
    // says so, with an undo.
    bool edit(std::string_view key, const nlohmann::json& value);
    // Puts back the format and DepthBias from before the step (the status line's Undo); later edits stay.
    void undoLastStep();
    // Messages go to the log (and the terminal); the status line shows one of them. A user action's result (say)
    // shows until the next user action or a more important message (an error); what the editor says on its own
    // (sayAutomatic: Auto's measurement) shows only when no action result or error stands, so it never hides the
    // answer to what the user just did.
    void say(std::string text, bool error = false);
    void sayAutomatic(std::string text, bool error = false);
    // A user's edit: the standing result gives way to whatever is said next.
    void userActed() { statusStands_ = false; }
    const std::string* fieldError(const std::string& key) const;
    const Message* lastMessage() const { return messages.empty() ? nullptr : &messages.back(); }  // newest logged
    const Message* statusMessage() const;  // what the status line shows (nullptr: nothing said yet)

private:
    void log(Message message);
    long nextSerial_ = 1;
    long statusSerial_ = 0;       // the message the status line shows
    bool statusStands_ = false;   // it is an action's result or an error: automatic news does not replace it
};

// Requests panels make of the editor (scene and preset switches may first ask about unsaved changes).
class EditorActions {
public:
    virtual ~EditorActions() = default;
    virtual void requestScene(const std::string& spec) = 0;
    virtual void requestPreset(const std::string& path, bool shipped) = 0;
    virtual void savePreset() = 0;                      // in place, or opens Save As for shipped/unnamed presets
    virtual void openSaveAs() = 0;
    virtual void revertPreset() = 0;
    // The current user preset: a new file name in the same folder, or moved into the folder's deleted/ subfolder.
    virtual void renamePreset(const std::string& name) = 0;
    virtual void deletePreset() = 0;
    virtual void requestScreenshot(bool withShadowMap) = 0;
    virtual void frameScene() = 0;
    // The view moves to one of the scene's cameras (its index; -1 = the free camera, which keeps the view): the
    // choice is the camera.sceneCamera setting, saved with the preset.
    virtual void chooseSceneCamera(int index) = 0;
    // The Probe panel's report as JSON (probe --json's format, with the scene and preset) in the screenshots folder.
    virtual void saveProbeJson() = 0;
    // Accuracy: measure the current view, search for a bias (applied to the settings when done), cancel either.
    virtual void measureAccuracy() = 0;
    virtual void suggestBias() = 0;
    virtual void measureFlicker() = 0;  // plays accuracy.flickerMotion on the current view
    virtual void cancelAccuracy() = 0;
    // What a measurement now would be made for (settings, camera, scene, viewport size); none before a viewport.
    virtual std::optional<AccuracyViewKey> currentView() const = 0;
    // Before work whose crash would lose the unsaved settings (a sweep): they are written to the autosave file.
    virtual void keepSession() = 0;
};

}  // namespace shadowlab::editor
