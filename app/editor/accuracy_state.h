#pragma once
// What the Accuracy panel and the viewport's "accuracy overlay" view show: the newest measurement and what it was
// measured for (so the panel can say when it is stale), the running job's progress, the bias search's path and
// result. The editor fills it from its AccuracyWorker each frame; the panel reads it and asks through EditorActions.
#include "accuracy/accuracy_meter.h"
#include "accuracy/accuracy_overlay.h"
#include "accuracy/bias_tuner.h"
#include "accuracy/flicker.h"
#include "frame/camera.h"
#include "gl/gl_objects.h"
#include "scene/scene.h"
#include "settings/settings.h"

#include <optional>
#include <string>
#include <vector>

namespace shadowlab::editor {

// Everything a measurement depends on. The view mode (lit / shadow / light-depth) is not part of it: the numbers
// do not depend on what the viewport shows.
struct AccuracyViewKey {
    Settings settings;
    Camera camera;
    const Scene* scene = nullptr;
    int width = 0, height = 0;
    std::size_t light = 0;  // the light measured (the selected one, in the effective lights): every number is its
    bool operator==(const AccuracyViewKey& other) const;
};

// The reference of `a` (scene, camera, view size) serves `b`: a live count can re-measure b without new rays, unless
// the light moved (the meter says so).
bool sameReferenceView(const AccuracyViewKey& a, const AccuracyViewKey& b);

// "" when `measured` still describes `now`; otherwise what changed, e.g. "shadow.depthBias, filter.kind changed".
std::string staleReason(const AccuracyViewKey& measured, const AccuracyViewKey& now);

struct AccuracyState {
    // Auto: after every edit a live count on the GPU (while a slider moves, every frame the previous count has
    // finished), and a full measure (causes, overlay) once the view has been still for kAutoDelaySeconds.
    bool autoMeasure = false;
    bool showOverlay = false;   // the viewport shows the overlay (an editor view mode, never saved in presets)
    OverlayKind overlayKind = OverlayKind::Error;  // coloured by error (acne / leak), by cause, or soft (bleeding...)
    static constexpr double kAutoDelaySeconds = 0.5;

    // The running job (if any).
    bool running = false;
    bool runningTune = false;
    float progress = 0.0f;
    std::string stage;

    // The newest measurement that finished (a Measure, or the bias search's best setting).
    std::optional<AccuracyReport> report;
    std::optional<AccuracyViewKey> reportKey;
    double reportSeconds = 0.0;  // wall time of the job that made it
    bool reportFromSearch = false;  // made by Suggest bias (its best setting) rather than by Measure
    std::string stale;           // "" while the report matches the current view and settings
    std::string error;           // why the newest job failed ("cancelled", invalid settings, ...)
    long measurements = 0;       // finished jobs that produced a report (measures and searches)
    std::optional<AccuracyViewKey> fullKey;  // what the newest full measure or search described

    // Live accuracy (report->live while its numbers are the newest): counted on the GPU against the cached reference.
    bool liveRunning = false;
    long liveMeasurements = 0;   // live counts adopted
    bool liveBlocked = false;    // no reference for this light: no live counts until the next full measure

    // Suggest bias.
    std::vector<TuneStep> steps;  // the search's path, live while it runs
    std::optional<TuneResult> tune;  // the newest finished search (its report is also `report`)
    double maxAcnePercent = 0.1;
    std::size_t stepsFollowed = 0;   // the path table scrolled to its newest row when it grew
    // What Suggest searches (tune's --search): auto = the technique's trade-off when it declares one, else the bias.
    TuneSearch search = TuneSearch::Auto;
    // The running or newest search: what it searched (Auto resolved), for which light, and the trade-off keys it
    // varies as keys of the whole preset ("filter.minVariance", "lights.2.size"), in the order of TuneStep::tradeOff.
    TuneSearch searched = TuneSearch::Bias;
    std::size_t searchedLight = 0;
    std::string searchedTechnique;
    std::vector<std::string> searchedKeys;

    // Flicker (the panel's Flicker tab): the motion to play, the newest result (its own, beside `report`) and its
    // overlay on the GPU.
    Motion flickerMotion = [] {
        Motion m;
        m.kind = MotionKind::Light;
        m.step = motionInfo(m.kind).typicalStep;
        m.frames = 8;
        return m;
    }();
    bool runningFlicker = false;
    std::optional<FlickerReport> flicker;
    double flickerSeconds = 0.0;
    gl::Texture flickerTexture;

    // The overlay picture on the GPU (uploaded once per report).
    gl::Texture overlayTexture;
    int overlayWidth = 0, overlayHeight = 0;
    OverlayKind uploadedKind = OverlayKind::Error;
    // The texture holds uploadedKind's picture of the newest full measurement (false after one without that picture:
    // the soft overlay of a light with no size).
    bool overlayUploaded = false;
    // The viewport shows the overlay picture chosen (it then hides the rendered view).
    bool overlayShown() const { return showOverlay && overlayTexture && overlayUploaded && uploadedKind == overlayKind; }
};

}  // namespace shadowlab::editor
