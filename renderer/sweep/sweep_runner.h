#pragma once
// The cost-vs-accuracy sweep: for every point of a plan, the time of the shadow pass, a moments technique's moments
// and blur passes and the main pass (median of N frames, shadow pass forced, so the moments and blur re-run with it:
// the timing loop of `bench`), the map's memory, the error numbers of metrics version 2 against one exact reference
// (AccuracyMeter caches it: it depends only on scene, light, camera and view size) and, for a light with a size, the
// soft numbers against the soft reference, and the shadow pass as a multiple of a bare depth-only draw of the same
// triangles into a map of the same size and format. Then the Pareto front of cost (shadow + moments + blur + mips + main ms)
// against the error (sweepError: wrong pixels, or a soft light's mean |S-V|). Knows no window, UI or CLI; needs a
// current GL 4.5 context on the calling thread.
#include "accuracy/accuracy_meter.h"
#include "sweep/bare_depth_draw.h"
#include "sweep/sweep_plan.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace shadowlab {

struct SweepPointResult {
    std::size_t index = 0;            // in the plan's points; the preset's own extra point has plan.points.size()
    std::vector<std::string> values;  // one per axis
    std::string label;
    Settings settings;
    std::vector<std::string> warnings;

    double shadowMs = 0.0;            // median shadow pass
    double mainMs = 0.0;              // median main pass
    double momentsMs = 0.0;           // median moments pass (a moments technique; 0 for a depth technique)
    double blurMs = 0.0;              // median blur pass (likewise)
    double mipsMs = 0.0;              // median mips pass (filter.momentMips; 0 while it is off)
    double costMs = 0.0;              // shadow + moments + blur + mips + main: the cost the front uses
    double shadowMinMs = 0.0;         // the fastest timed frame of each pass (robust to a loaded CPU)
    double mainMinMs = 0.0;
    double wallMsPerFrame = 0.0;
    int resolution = 0;
    DepthFormat format = DepthFormat::D32F;
    std::size_t mapBytes = 0;
    double bareDrawMs = 0.0;          // the bare draw at this map size and format
    double shadowOverBare = 0.0;      // shadowMs / bareDrawMs

    AccuracyNumbers accuracy;         // metrics version 2 (wrongPercent: the error the front uses for a hard light)
    SoftAccuracy soft;                // a light with a size: version 3 against the soft reference (else unmeasured)
    double kTexels = 0.0;
    bool coarseMap = false;           // acne and leak cannot judge this map (read wrong pixels and mean error)
    bool referenceReused = false;     // the reference came from the sweep's cache
    double measureMs = 0.0;
    bool onFront = false;
    // sweep --play (played_point.h): the animation.time frame K-1 was measured at, the views drawn per frame.
    double playedTime = 0.0;
    double viewsRenderedPerFrame = 0.0;

    std::string error;  // not empty: the point failed, and why; its numbers are unset, it is on no front or chart
    bool failed() const { return !error.empty(); }
};

struct SweepResult {
    bool ok = false;
    bool cancelled = false;
    std::string error;
    std::vector<SweepAxis> axes;
    std::vector<SweepPointResult> points;         // in plan order (run grouped by light and camera; see runSweep)
    std::optional<SweepPointResult> preset;       // the base settings when they are not one of the points
    std::size_t presetPoint = 0;                  // index into points of the preset, or points.size() (see .preset)
    std::vector<BareDrawTiming> bareDraws;        // one per map size, format (and light), in the order met
    std::vector<std::size_t> front;               // indices into points, in order of cost
    std::string timingSource;
    std::string glRenderer;
    std::size_t triangles = 0;
    int width = 0, height = 0, frames = 0;
    int playFrames = 0;     // sweep --play K (0: not played)
    double playStep = 0.0;  // its seconds per frame
    double referenceMs = 0.0;  // the reference's work (G-buffer, BVH, shadow rays), summed over its computations
    int references = 0;        // how often it was computed: once, unless an axis moves the light or the camera
    double wallMs = 0.0;       // the whole sweep
    bool softwareRasterizer() const { return timingSource.rfind("CPU", 0) == 0; }
};

struct SweepRunOptions {
    int width = 1280;
    int height = 720;
    int frames = 10;
    bool measurePreset = true;  // also time and measure the base settings when they are not a point (the marker)
    // The view to time and measure (the editor's orbit camera); unset: each point's camera settings (auto-framed
    // unless they say otherwise). A point whose camera.* keys differ from the base's always uses its own.
    std::optional<Camera> camera;
    // > 0: each point plays this many frames of its animation, `playStep` seconds apart, from its animation.time,
    // and is timed along them and measured at the last (played_point.h), so shadow.update axes matter.
    int playFrames = 0;
    double playStep = 1.0 / 30.0;
    // Called after each point (a failed one too) with the sweep so far: the finished points in plan order, the
    // front among them. The CLI rewrites its JSON and CSV from it, so a point that fails later loses nothing.
    std::function<void(const SweepResult& soFar)> onResult;
};

// Called after each point (and the preset) with the point and how many of the total are done.
using SweepPointCallback = std::function<void(const SweepPointResult& point, std::size_t done, std::size_t total)>;

// Runs the plan (which must have no error). A point that fails (no light casts with its values, a GL error, a
// measurement that cannot be made) is kept with its error and the sweep goes on; the result fails only when every
// point did, or on cancel. Points that share the reference (the same light.* and camera.* values)
// run one after another, so an axis over the light recomputes the reference once per light, not once per point. Every point's map size is checked against GL_MAX_TEXTURE_SIZE before any
// work. `progress` (optional) gets the fraction and stage and carries a cancel request.
SweepResult runSweep(const Scene& scene, const Settings& base, const SweepPlan& plan, const SweepRunOptions& options,
                     const SweepPointCallback& onPoint = {}, AccuracyProgress* progress = nullptr);

// The error the front and the chart use: when every measured point's light has a size (soft.measured), the soft
// mean |S-V| against the soft reference; else version 2's wrong pixels %.
bool sweepSoftError(const SweepResult& result);
double sweepError(const SweepPointResult& point, bool soft);
std::string sweepErrorName(bool soft);  // "wrong pixels %" or "mean |S-V| against the soft reference"

// Sets result.front and each point's onFront from the points so far (failed points excluded) (a partial sweep's chart draws it live).
void markParetoFront(SweepResult& result);

// What the cost of going from one front point to the next buys: "+0.8 ms: wrong pixels 2.1 % -> 0.9 %".
std::string frontStepText(const SweepPointResult& from, const SweepPointResult& to);

}  // namespace shadowlab
