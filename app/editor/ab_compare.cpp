#include "editor/ab_compare.h"

#include "accuracy/compare_label.h"
#include "editor/editor_state.h"

#include <algorithm>
#include <utility>

namespace shadowlab::editor {

namespace {

constexpr std::size_t kMeasurementsKept = 4;

// The preset's name, with " *" when the settings differ from it.
std::string sideName(const EditorState& state, const Settings& settings) {
    return state.preset.name() + (state.preset.dirty(settings) ? " *" : "");
}

// A frame that skipped the shadow pass (its map was still valid) labelled with the time of the newest one that ran:
// the side's shadow cost, not "n/a".
FrameStats withShadowTime(FrameStats stats, const FrameStats& lastRan) {
    if (!stats.shadowPass.ran && lastRan.shadowPass.milliseconds)
        stats.shadowPass.milliseconds = lastRan.shadowPass.milliseconds;
    return stats;
}

}  // namespace

void startAb(EditorState& state) {
    state.ab.active = true;
    state.ab.a = state.settings;
    state.ab.aName = sideName(state, state.settings);
    state.ab.haveStatsA = false;
    state.ab.renders = 0;
    state.ab.measured.clear();
    state.ab.seen = -1;
    rememberMeasurement(state.ab, state.accuracy);
    state.say("A/B: A is a snapshot of " + state.ab.aName + "; edits change B (right of the divider)");
}

void swapAb(EditorState& state) {
    if (!state.ab.active) return;
    const ViewMode view = state.settings.view;  // the view mode is the viewport's, not a side's
    const std::string oldB = sideName(state, state.settings);
    std::swap(state.ab.a, state.settings);
    state.undo.reset();  // its note was about the settings that are now A
    state.settings.view = view;
    state.ab.aName = oldB;
    state.fieldErrors.clear();
    state.say("A/B: swapped; B (edited now) is the former A, A is " + oldB);
}

void applyA(EditorState& state) {
    if (!state.ab.active) return;
    const ViewMode view = state.settings.view;
    state.settings = state.ab.a;
    state.settings.view = view;
    state.undo.reset();
    state.fieldErrors.clear();
    state.say("A/B: applied A (" + state.ab.aName + ") to the edited settings");
}

void stopAb(EditorState& state) {
    state.ab.active = false;
    state.ab.measured.clear();
    state.say("A/B: comparison closed; the edited settings (B) stay");
}

Settings abSettingsA(const EditorState& state) {
    Settings a = state.ab.a;
    a.view = state.settings.view;
    return a;
}

void rememberMeasurement(AbState& ab, const AccuracyState& accuracy) {
    const long reports = accuracy.measurements + accuracy.liveMeasurements;
    if (reports == ab.seen || !accuracy.report || !accuracy.reportKey) return;
    ab.seen = reports;
    auto same = [&](const auto& entry) { return entry.first == *accuracy.reportKey; };
    auto it = std::find_if(ab.measured.begin(), ab.measured.end(), same);
    if (it != ab.measured.end()) {
        it->second = *accuracy.report;  // a newer count for the same view
        return;
    }
    ab.measured.emplace_back(*accuracy.reportKey, *accuracy.report);
    if (ab.measured.size() > kMeasurementsKept) ab.measured.erase(ab.measured.begin());
}

std::vector<std::string> abLabel(const EditorState& state, bool sideA, const std::optional<AccuracyViewKey>& now) {
    const AbState& ab = state.ab;
    std::vector<std::string> lines;
    if (sideA)
        lines = ab.haveStatsA ? compareLabel("A", ab.aName, ab.statsA) : std::vector<std::string>{"A: " + ab.aName};
    else
        lines = state.haveStats ? compareLabel("B", sideName(state, state.settings),
                                               withShadowTime(state.stats, state.lastShadowPass))
                                : std::vector<std::string>{"B: " + sideName(state, state.settings)};
    if (now) {
        AccuracyViewKey key = *now;
        if (sideA) key.settings = abSettingsA(state);
        for (const auto& [measuredKey, report] : ab.measured)
            if (measuredKey == key) {
                // The numbers are the selected light's, measured alone: with several lights the label says which.
                const bool several = key.settings.lights.size() > 1;
                lines.push_back((several ? "light " + std::to_string(key.light) + ": " : std::string()) +
                                accuracyLine(report));
                break;
            }
    }
    return lines;
}

AbRenderer::Key AbRenderer::keyFor(const EditorState& state, const Settings& settingsA, const Camera& camera, int width,
                                   int height, bool frustum) {
    return Key{settingsA, camera.position, camera.target, camera.fovYDeg, state.scene.get(), width, height, frustum,
               frustum ? state.selectedLight : 0, state.frozenCascadeCamera};
}

bool AbRenderer::due(const EditorState& state, const Settings& settingsA, const Camera& camera, int width, int height,
                     bool frustum) const {
    return state.scene && !(last_ && *last_ == keyFor(state, settingsA, camera, width, height, frustum));
}

void AbRenderer::sceneChanged() {
    if (renderer_) renderer_->sceneChanged();
    last_.reset();
}

bool AbRenderer::render(EditorState& state, const Settings& settingsA, const Camera& camera, int width, int height,
                        LightFrustumOverlay* frustum) {
    if (!state.scene) return false;
    if (!renderer_) renderer_ = std::make_unique<Renderer>();
    if (target_.width() != width || target_.height() != height) {
        if (std::string error = target_.resize(width, height); !error.empty()) {
            state.say("A/B: view A: " + error, true);
            return false;
        }
        last_.reset();
    }
    const Key key = keyFor(state, settingsA, camera, width, height, frustum != nullptr);
    if (last_ && *last_ == key) return false;
    last_ = key;
    FrameStats stats = renderer_->render(*state.scene, settingsA, camera, target_,
                                         key.fitCamera ? &*key.fitCamera : nullptr);
    // A runs only when it changed, so its timer queries would never be read by a later frame: wait for them now.
    if (stats.ok) renderer_->waitForTimings(stats);
    if (!stats.ok) {
        state.say("A/B: view A: " + stats.error, true);
        state.ab.haveStatsA = false;
        return true;
    }
    if (frustum) {
        const std::vector<OverlayLines> lines =
            lightOverlayLines(stats, state.selectedLight, FrustumOverlayStyle{}.color, key.fitCamera.has_value());
        if (std::string error = frustum->draw(stats, lines, target_); !error.empty())
            state.say("A/B: light frustum: " + error, true);
    }
    if (state.ab.haveStatsA) stats = withShadowTime(std::move(stats), state.ab.statsA);
    state.ab.statsA = std::move(stats);
    state.ab.haveStatsA = true;
    ++state.ab.renders;
    return true;
}

}  // namespace shadowlab::editor
