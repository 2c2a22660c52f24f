#pragma once
// A/B comparison in the editor. A is a snapshot of the settings taken when the comparison starts; B is what the user
// keeps editing (EditorState::settings). The viewport shows A left of a draggable divider and B right of it, each
// side labelled with its pass times and, once measured, its accuracy. A has its own renderer and target
// (AbRenderer) and runs a pass only when A's settings, the camera, the scene or the view size change: editing B
// never re-renders A.
#include "accuracy/accuracy_meter.h"
#include "editor/accuracy_state.h"
#include "frame/frame_stats.h"
#include "frame/render_target.h"
#include "frame/renderer.h"
#include "overlay/light_frustum_overlay.h"
#include "settings/settings.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace shadowlab::editor {

struct EditorState;

struct AbState {
    bool active = false;
    Settings a;             // the snapshot; it renders with B's view mode so both sides show the same thing
    std::string aName;      // what A was taken from ("default", "default *" when it had unsaved edits)
    float divider = 0.5f;   // fraction of the viewport's width left of the divider
    FrameStats statsA;      // A's newest frame
    bool haveStatsA = false;
    long renders = 0;       // passes A ran since the comparison started
    // Measurements' numbers seen while comparing (newest last, a few): a side shows the one made for its settings
    // and view. `seen` counts the accuracy state's reports already looked at.
    std::vector<std::pair<AccuracyViewKey, AccuracyNumbers>> measured;
    long seen = -1;
};

// The toolbar's actions. start: A = the current settings. swap: A and B trade settings. applyA: B = A (the comparison
// goes on, both sides equal until the next edit). stop: back to one view.
void startAb(EditorState& state);
void swapAb(EditorState& state);
void applyA(EditorState& state);
void stopAb(EditorState& state);

// What A renders: the snapshot with B's view mode (lit / shadow / light depth).
Settings abSettingsA(const EditorState& state);

// Keeps the newest measurement (if any) for the labels; call once a frame while comparing.
void rememberMeasurement(AbState& ab, const AccuracyState& accuracy);

// A side's label lines: name, pass times, and accuracy where a measurement was made for exactly this side's settings
// and the view `now` (camera, scene, size); `now` is the view with B's settings.
std::vector<std::string> abLabel(const EditorState& state, bool sideA, const std::optional<AccuracyViewKey>& now);

// A's renderer and target, made on the first comparison.
class AbRenderer {
public:
    // Runs A's passes if anything A depends on changed since its last frame; true when it did. `frustum` (may be null)
    // draws the selected light's volume over A as over B. A's cascades fit to the frozen camera as B's do.
    bool render(EditorState& state, const Settings& settingsA, const Camera& camera, int width, int height,
                LightFrustumOverlay* frustum);
    // Whether render() with these inputs would run a pass.
    bool due(const EditorState& state, const Settings& settingsA, const Camera& camera, int width, int height,
             bool frustum) const;
    const RenderTarget& target() const { return target_; }
    void sceneChanged();  // the scene was replaced or edited: the next render uploads it again

private:
    struct Key {
        Settings settings;
        glm::dvec3 eye{0.0}, target{0.0};
        double fovYDeg = 0.0;
        const Scene* scene = nullptr;
        int width = 0, height = 0;
        bool frustum = false;
        std::size_t frustumLight = 0;  // the selected light, while its volume is drawn
        std::optional<FitCamera> fitCamera;  // EditorState::frozenCascadeCamera
        bool operator==(const Key&) const = default;
    };
    static Key keyFor(const EditorState& state, const Settings& settingsA, const Camera& camera, int width, int height,
                      bool frustum);
    std::unique_ptr<Renderer> renderer_;
    RenderTarget target_;
    std::optional<Key> last_;
};

}  // namespace shadowlab::editor
