#pragma once
// Measures how wrong the tool's shadows are against an exact reference (DESIGN.md, "Accuracy"): per main-view pixel,
// the rasterized surface point and geometric normal (from a G-buffer pass with the same camera), exact visibility V by
// a shadow ray (Embree), and the tool's shadow factor S. The reference depends only on scene, light, camera and size,
// so it is cached: re-measuring after a bias / filter / resolution change costs one frame of the tool.
// Knows no window, UI or CLI. Needs a current GL 4.5 context on the calling thread (one meter per context).
#include "accuracy/cascade_accuracy.h"
#include "accuracy/mismatch_cause.h"
#include "accuracy/soft_metrics.h"
#include "frame/camera.h"
#include "frame/frame_stats.h"
#include "scene/scene.h"
#include "settings/settings.h"

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace shadowlab {

class Renderer;

// Shared between the measuring thread and a UI: how far it got, what it is doing, and a cancel request.
struct AccuracyProgress {
    std::atomic<float> fraction{0.0f};  // 0..1 of the current job (measure or tune)
    std::atomic<bool> cancel{false};    // set by the UI; the job stops soon after and reports "cancelled"
    // A measurement inside a longer job (the tuner) reports fraction = base + span x its own progress.
    float base = 0.0f;
    float span = 1.0f;

    void setStage(std::string text) {
        std::lock_guard<std::mutex> lock(mutex_);
        stage_ = std::move(text);
    }
    std::string stage() const {
        std::lock_guard<std::mutex> lock(mutex_);
        return stage_;
    }

private:
    mutable std::mutex mutex_;
    std::string stage_;
};

// Which of DESIGN.md's definitions the numbers follow (reports and JSON carry it).
inline constexpr int kMetricsVersion = 2;

// The counts behind the percentages (DESIGN.md's sets, version 2; e = 1/255), all in main-view pixels.
struct AccuracyCounts {
    std::size_t pixels = 0;            // width * height
    std::size_t background = 0;        // no surface under the pixel
    std::size_t facingAway = 0;        // geometric normal faces away from the light: unlit by the main pass, not scored
    std::size_t outsideCone = 0;       // spot light: outside the cone (V = 0, S = 0 expected; scored as shadowed)
    std::size_t outOfRange = 0;        // spot / point light: beyond its range: not reached, neither lit nor shadowed,
                                       // not scored
    std::size_t nonFinite = 0;         // a non-finite point, normal or S (must stay 0)
    std::size_t measured = 0;          // pixels scored
    std::size_t lit = 0;               // measured with V = 1
    std::size_t shadowed = 0;          // measured with V = 0
    std::size_t acne = 0;              // V = 1, S < 1-e, dist > k
    std::size_t leak = 0;              // V = 0, S > e, dist > k
    std::size_t wrong = 0;             // |S - V| >= 0.5, at any distance
    std::size_t wrongBeyondK = 0;      // wrong and farther than k from a true boundary
    std::size_t mismatched = 0;        // visibly different: (V = 1, S < 1-e) or (V = 0, S > e), at any distance
    std::size_t mismatchedWithinK = 0; // mismatched, but within k texels of a true boundary (filter blur: not acne/leak)
    std::size_t shadowedNearEdge = 0;  // shadowed pixels within k of a visible true boundary (coarse-map check)
    std::size_t boundaryPixels = 0;    // pixels on the true shadow boundary (drawn as the thin line)
    std::size_t coverageMismatch = 0;  // G-buffer and tool frame disagree about whether a surface is there
    std::array<std::size_t, kCauseCount> causePixels{};  // mismatched pixels per MismatchCause
    std::array<std::size_t, kCauseCount> causeWrong{};   // wrong pixels per MismatchCause
    std::array<std::size_t, kCauseCount> causeAcne{};    // acne pixels per MismatchCause
    std::array<std::size_t, kCauseCount> causeLeak{};    // leak pixels per MismatchCause
};

// A measured pixel's verdict: acne / leak (visibly wrong beyond k), or the same within k of a true edge.
enum class PixelMark : std::uint8_t { None, Acne, AcneNearEdge, Leak, LeakNearEdge };

// What the reference and the measurement cost (milliseconds unless named otherwise).
struct AccuracyCost {
    bool bvhReused = false;        // the scene's BVH came from the cache
    bool bvhUpdated = false;       // only instance transforms changed: the cached BVH's top level followed them
    bool referenceReused = false;  // G-buffer, visibility and boundary distances came from the cache
    double bvhBuildMs = 0.0;
    double bvhUpdateMs = 0.0;      // bvhUpdated: moving the instances and re-committing the top level
    std::size_t instancesMoved = 0;  // bvhUpdated: instances whose transform changed
    std::size_t triangles = 0;     // in the BVH
    double gbufferMs = 0.0;        // G-buffer pass + read-back + double-precision surface rebuild
    double gbufferDrawMs = 0.0, gbufferReadBackMs = 0.0, gbufferRebuildMs = 0.0;  // gbufferMs's parts
    double traceMs = 0.0;          // shadow rays
    std::size_t rays = 0;
    double raysPerSecond = 0.0;
    int threads = 0;
    double boundaryMs = 0.0;       // true boundary + distance of every pixel to it
    double probeMs = 0.0;          // extra rays probing boundaries the camera cannot see
    std::size_t probedPixels = 0;
    double toolFrameMs = 0.0;      // the tool's own frame (shadow pass + shadow-factor pass + read-back)
    double toolRenderMs = 0.0;     // toolFrameMs's render (scene upload, programs, passes) ...
    double toolReadBackMs = 0.0;   // ... and its read-back of S (waiting for the GPU, copying, unpacking)
    int programsBuilt = 0;         // GL programs built during this measurement (first use of a pass or variant)
    double programBuildMs = 0.0;   // their preprocess + compile + link wall time (inside the stages above)
    double causesMs = 0.0;         // metricsMs's part: a cause for each mismatched pixel (rays)
    double overlaysMs = 0.0;       // the overlays and per-pixel copies (beside the numbers)
    double metricsMs = 0.0;        // metrics + overlay (live: the GPU count)
    double uploadMs = 0.0;         // live: the reference uploaded to the GPU counter (once per reference and light space)
    double totalMs = 0.0;
};

// The numbers of DESIGN.md's version 2 (accuracy_metrics.h computes them; the report carries them as they are).
struct AccuracyNumbers {
    double acnePercent = 0.0;         // acne / lit * 100
    double acneSeverity = 0.0;        // mean 1-S over acne pixels (0..1)
    double leakPercent = 0.0;         // leak / shadowed * 100
    double wrongPercent = 0.0;        // wrong / measured * 100
    double meanError = 0.0;           // mean |S-V| over measured pixels (0..1)
    double edgeErrorP95Texels = 0.0;  // 95th percentile of dist over mismatched pixels (0 when none)
    double edgeErrorP95World = 0.0;   // the same in world units (each pixel's texel size)
    double edgeErrorP95ScreenPixels = 0.0;  // the same in main-view pixels (at each pixel's depth)
    AccuracyCounts counts;
};

// Shadow-map texels per screen pixel over the measured pixels: a pixel's world size at its depth over the world size
// of the texel that shades it (the cascade's for a cascaded light). Where a fit spends its texels, before any error:
// below 1 the map is blockier than the screen, far above 1 its texels are wasted. `render --view texel-density`
// shows the same ratio per pixel.
struct TexelDensity {
    std::size_t pixels = 0;
    double p5 = 0.0, median = 0.0, p95 = 0.0;
};

struct AccuracyReport : AccuracyNumbers {
    bool ok = false;
    bool cancelled = false;
    // Counted on the GPU from the cached reference (AccuracyMeter::remeasure): numbers and counts only; no causes,
    // overlays or per-pixel data (those come with measure()).
    bool live = false;
    bool needsReference = false;  // remeasure refused: no reference cached for this view (call measure first)
    std::string error;  // when !ok: why (invalid settings name the key; "cancelled")
    std::vector<std::string> warnings;  // the tool's frame was drawn, but something was refused (e.g. map size)

    int metricsVersion = kMetricsVersion;
    double kTexels = 1.0;             // filter radius + 1 texel
    double texelWorldSize = 0.0;      // world size of one shadow-map texel (directional; spot: at the cone's centre)
    // "" unless k covers most of the shadowed area (a coarse map): then acne and leak cannot judge (see the text).
    std::string coarseMapWarning;
    AccuracyCost cost;

    // The error overlay (accuracy_overlay.h) and the same view coloured by cause. RGBA8, width * height * 4 bytes,
    // row 0 = TOP of the view (PNG order).
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> overlayRgba;
    std::vector<std::uint8_t> causeOverlayRgba;

    // Per pixel, row 0 = TOP, for the pixel probe: the reference's verdict, the tool's S and the mismatch's cause.
    std::vector<PixelClass> pixelClass;
    std::vector<float> pixelShadow;
    std::vector<MismatchCause> pixelCause;
    std::vector<PixelMark> pixelMark;          // for combining lights (light_accuracy.h)
    std::vector<std::uint8_t> pixelMeasured;   // 1 where the pixel is scored for this light
    std::vector<std::uint8_t> pixelOnBoundary; // 1 on the true boundary's thin line
    std::vector<float> pixelLambert;           // max(n . l, 0): the overlays' dimmed picture (flicker.h draws one)

    TexelDensity texelDensity;
    // A cascaded light: its numbers per cascade and at the seams (cascade_accuracy.h); empty cascades otherwise.
    CascadeAccuracy cascades;

    // A light of size > 0: its soft numbers (version 3, against the soft reference; soft_metrics.h) beside the hard
    // ones above (version 2, against the ray through the light's centre). soft.measured is false for a hard light
    // and for a live remeasure (the GPU counter counts the hard numbers only).
    SoftAccuracy soft;
    std::vector<float> pixelSoftVisibility;  // the soft V per pixel, row 0 = TOP (empty for a hard light)
    std::vector<std::uint8_t> softOverlayRgba;  // the soft overlay (accuracy_overlay.h), RGBA8; empty for a hard light

    // Shadow views the tool frame's planner rendered (0: every map was reused; flicker.h checks it under camera motion).
    std::size_t shadowViewsRendered = 0;

    // The share of each set a cause explains: acne pixels are mostly not wrong (a darkening of 1-S < 0.5), so an
    // acne cause is judged against acne, a leak cause against leak, and wrong pixels against wrong.
    double causePercentOfWrong(MismatchCause cause) const;  // share of wrong pixels this cause explains
    double causePercentOfAcne(MismatchCause cause) const;
    double causePercentOfLeak(MismatchCause cause) const;
    // The cause of the most mismatched pixels beyond k (else "within k of a true edge"; None when nothing mismatches).
    MismatchCause mainCause() const;
};

// The share of shadowed pixels within k of a true edge above which acne and leak cannot judge (coarse map).
inline constexpr double kCoarseMapShare = 0.5;

class AccuracyMeter {
public:
    // Needs a current GL 4.5 context; throws std::runtime_error if its shaders do not build.
    AccuracyMeter();
    ~AccuracyMeter();
    AccuracyMeter(const AccuracyMeter&) = delete;
    AccuracyMeter& operator=(const AccuracyMeter&) = delete;

    // Measures one view for light 0 of the effective lights, alone (light_isolation.h: its shadow factor is the one
    // it has in the full frame); light_accuracy.h measures every light. Invalid settings, a size the GPU refuses or a cancel give ok = false with a reason; nothing
    // throws for user input. The scene must stay alive and unchanged while cached (call sceneChanged() after edits).
    // `shadowCamera` (null: `camera`): the camera a cascaded light's views follow (Renderer::render's), so the
    // flicker measure can shade this camera's pixels with the previous frame's cascades.
    AccuracyReport measure(const Scene& scene, const Settings& settings, const Camera& camera, int width, int height,
                           AccuracyProgress* progress = nullptr, const Camera* shadowCamera = nullptr);

    // Live accuracy: the same numbers for a view whose reference measure() cached (same scene, light, camera and
    // size; bias, filter, map size and format may differ), counted on the GPU (gpu_accuracy_counter.h) after one
    // tool frame that is never read back. ok = false with needsReference when nothing is cached for this view.
    AccuracyReport remeasure(const Scene& scene, const Settings& settings, const Camera& camera, int width,
                             int height);

    // Drops every cache (BVH, reference) — call after editing the scene in place.
    void sceneChanged();

    // Playing an animation under several shadow.update policies (bench --animation --cache-error, sweep --play):
    // the tool frame is drawn by `renderer` (null: the meter's own), so each policy keeps its own maps and cached
    // depths from frame to frame while all share one reference per pose. The caller keeps it alive while it is set.
    void setToolRenderer(Renderer* renderer);
    // Draws the tool frame measure() would draw (its settings, size, renderer) without measuring it: a played frame
    // between two measured ones. Its stats; the caller's renderer waits for their timings.
    FrameStats drawToolFrame(const Scene& scene, const Settings& settings, const Camera& camera, int width, int height);
    // The stats of the last tool frame (measure(), remeasure() or drawToolFrame()).
    const FrameStats& lastToolFrame() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace shadowlab
