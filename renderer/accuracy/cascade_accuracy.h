#pragma once
// A cascaded light's accuracy per cascade and at its seams, from the per-pixel buffers of a measurement (no GL).
// Each measured pixel belongs to the cascade that holds it (views/view_select.h; -1 beyond the shadow distance).
//   per cascade: acne %, leak %, wrong %, mean error over the pixels it holds (the definitions of
//                accuracy_metrics.h, restricted to those pixels)
//   the seam:    pixels within `bandPixels` screen pixels of a pixel held by another cascade (the band around each
//                split as the camera sees it) against the cascades' interiors (the other held pixels): wrong % and
//                mean error in each. A hard seam (blendBand 0) shows as a jump of error across the split; a blend
//                band spreads it.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace shadowlab {

struct AccuracyReport;  // accuracy_meter.h, which holds a CascadeAccuracy

struct CascadeNumbers {
    int cascade = 0;
    std::size_t measured = 0, lit = 0, shadowed = 0, acne = 0, leak = 0, wrong = 0;
    double acnePercent = 0.0, leakPercent = 0.0, wrongPercent = 0.0, meanError = 0.0;
    double texelWorldSize = 0.0;  // the cascade's texel, world units
};

struct SeamNumbers {
    int bandPixels = 0;  // the band's half-width, screen pixels
    std::size_t band = 0, interior = 0;  // measured pixels in each
    double bandWrongPercent = 0.0, bandMeanError = 0.0;
    double interiorWrongPercent = 0.0, interiorMeanError = 0.0;
};

struct CascadeAccuracy {
    std::vector<CascadeNumbers> cascades;  // nearest first
    std::size_t beyondShadowDistance = 0;  // measured pixels no cascade holds (lit by the tool)
    SeamNumbers seam;
};

// The band's default half-width in screen pixels: a PCF kernel's footprint seen at a split is a few pixels wide.
inline constexpr int kSeamBandPixels = 3;

// `cascadeOf`: per pixel (row 0 = top, as the report's buffers), the cascade holding it or -1. `texelWorld`: each
// cascade's texel world size. The report's pixelClass, pixelShadow, pixelMeasured and pixelMark are read.
CascadeAccuracy cascadeAccuracy(const AccuracyReport& report, const std::vector<std::int8_t>& cascadeOf,
                                const std::vector<double>& texelWorld, int bandPixels = kSeamBandPixels);

}  // namespace shadowlab
