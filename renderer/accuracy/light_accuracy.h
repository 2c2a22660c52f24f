#pragma once
// Accuracy of a frame with many lights: every shadow-casting light measured alone (light_isolation.h), then the
// whole picture from their per-pixel verdicts. Knows no window, UI or CLI.
//
// Per light: DESIGN.md's numbers (version 2) over the pixels that light reaches. A pixel beyond a spot / point
// light's range is neither lit nor shadowed by it (counts.outOfRange) and no number of that light counts it; a light
// that is off or has castsShadows off casts no shadow and is not measured (notMeasured says so).
//
// The whole picture counts each pixel once, over the measured lights that reach it (score it):
//   measured      = pixels scored for at least one light
//   lit / shadowed = measured pixels truly lit by (V = 1) / truly shadowed from (V = 0) at least one light
//   acne / leak   = pixels with acne / leak (beyond k) for ANY light; acne % = acne / lit, leak % = leak / shadowed;
//                   acne severity = mean over acne pixels of the largest 1-S among the lights with acne there
//   wrong         = pixels wrong (|S-V| >= 0.5) for ANY light that reaches them; wrong % = wrong / measured.
//                   So max over lights of wrong <= whole wrong <= sum over lights of wrong.
//   mismatched    = visibly wrong for any light (mismatchedWithinK: every such light's mismatch is within k)
//   mean error    = mean over measured pixels of the largest |S-V| among the lights that reach the pixel
//   edge error    = the largest of the lights' edge errors (each unit on its own): a bound, not a percentile
//   causes        = each mismatched pixel counted once, under the cause of its worst light
// With a light of size > 0 among them, the whole picture's soft numbers (version 3), each pixel once over the lights
// that score it, V being a sized light's soft visibility and a hard light's exact one:
//   wrong          = pixels with |S-V| >= 0.5 for ANY light; mean error = mean of the largest |S-V| among the lights
//   bleeding       = pixels some light's umbra (V = 0) holds that that light lights (S > e), over pixels in some umbra
//   over-darkening = pixels some light fully lights (V = 1) that that light darkens (S < 1-e), over pixels fully lit
//                    by some light
//   penumbra width error = the lights' largest in magnitude (each is a median over its own profiles): a bound
// The worst light at a pixel: acne / leak beyond k (wrong first) > mismatched within k (wrong first), then the larger
// |S-V|; so the union overlay shows a counted acne / leak colour wherever any light has one.
// The overlays of the whole picture colour each pixel as its worst light's overlay does; pixels no light gets
// wrong show the true boundary of any light, else the mean of the lights' dimmed pictures.
#include "accuracy/accuracy_meter.h"

#include <optional>
#include <string>
#include <vector>

namespace shadowlab {

struct LightAccuracy {
    std::size_t index = 0;  // in the effective lights (light/scene_lights.h)
    LightType type = LightType::Directional;
    AccuracyReport report;
};

struct NotMeasuredLight {
    std::size_t index = 0;
    std::string reason;  // names the key, e.g. "lights.2.castsShadows is false: ..."
};

struct ManyLightsReport {
    bool ok = false;
    bool cancelled = false;
    std::string error;
    std::vector<LightAccuracy> lights;        // every measured light, in index order
    std::vector<NotMeasuredLight> notMeasured;
    AccuracyNumbers whole;                    // see above; counts.pixels/background/nonFinite/coverageMismatch are
                                              // the largest over the lights, other exclusion counts stay 0
    std::size_t unreached = 0;                // surface pixels no measured light scores
    SoftAccuracy wholeSoft;                   // see above; measured only when some measured light has a size
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> overlayRgba;       // the union, coloured by each pixel's worst light
    std::vector<std::uint8_t> causeOverlayRgba;
};

// Measures `only` (an index into the effective lights; it must cast: see unmeasurableReason) or every casting light.
// Fails (ok = false) when nothing can be measured, a light's measurement fails, or it is cancelled.
ManyLightsReport measureLights(AccuracyMeter& meter, const Scene& scene, const Settings& settings,
                               const Camera& camera, int width, int height, std::optional<std::size_t> only = {},
                               AccuracyProgress* progress = nullptr);

// The whole picture's numbers and overlays from per-light reports of one view (all the same size, ok). No GL.
void combineLights(ManyLightsReport& many);

}  // namespace shadowlab
