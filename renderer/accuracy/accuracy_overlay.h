#pragma once
// The accuracy overlays. Error: red = acne (a truly lit receiver visibly darkened), blue = leak (light where the
// reference is in shadow), both darker within k texels of a true boundary (the filter's blur, not counted), yellow =
// the true shadow boundary as a thin line; everything else dimmed (grey: the tool's S x Lambert). Cause: every
// mismatched pixel in its cause's colour (mismatch_cause.h), the rest as in the error overlay. A coloured pixel keeps
// the surface's shading (its colour times a factor from its Lambert term), so shapes read under the colours. Soft
// (a light with a size, against the soft reference V; soft_metrics.h): cyan = light bleeding (V = 0 lit by the
// technique), orange = over-darkening (V = 1 darkened), lavender = the true penumbra (0 < V < 1), the rest dimmed.
// The legends are the one source of these colours for the CLI and the editor.
#include "accuracy/accuracy_metrics.h"
#include "accuracy/shadow_boundary.h"
#include "accuracy/soft_metrics.h"

#include <cstdint>
#include <string>
#include <vector>

namespace shadowlab {

struct LegendEntry {
    const char* name;
    std::uint8_t red, green, blue;
};
const std::vector<LegendEntry>& errorLegend();
const std::vector<LegendEntry>& causeLegend();  // every cause, then the true boundary
const std::vector<LegendEntry>& softLegend();   // bleeding, over-darkening, the true penumbra

enum class OverlayKind { Error, Cause, Soft };
const std::vector<LegendEntry>& overlayLegend(OverlayKind kind);

// A coloured pixel is its legend colour times kOverlayMinShade + (1 - kOverlayMinShade) x Lambert: the surface's
// shading without its shadow (an acne pixel stays red however dark the tool drew it). The floor keeps each colour
// apart from the others' shades (acne's darkest red is brighter than "acne within k" at full light).
constexpr float kOverlayMinShade = 0.55f;
struct OverlayRgb {
    std::uint8_t red, green, blue;
};
OverlayRgb shadedColour(const LegendEntry& entry, float lambert);
// Whether `rgb` is `entry`'s colour at some shading (for tests and tools that read an overlay picture back).
bool isShadeOf(const LegendEntry& entry, const std::uint8_t* rgb);

// The picture every overlay colours over, RGBA8, row 0 = top: background dark, every surface grey by the tool's
// S x Lambert with the ambient term.
std::vector<std::uint8_t> dimmedPicture(int width, int height, const std::vector<PixelClass>& classes,
                                        const std::vector<float>& shadowFactor, const std::vector<float>& lambert,
                                        float ambient);

// The error or cause overlay (the soft one: makeSoftOverlay). RGBA8, row 0 = top (the buffers' order).
std::vector<std::uint8_t> makeOverlay(OverlayKind kind, int width, int height, const std::vector<PixelClass>& classes,
                                      const std::vector<float>& shadowFactor, const std::vector<float>& lambert,
                                      const MetricsResult& metrics, const ShadowBoundary& boundary, float ambient);

// The soft overlay: every measured pixel by its SoftMark against the soft V (row 0 = top, as `visibility`); the
// true penumbra tinted so the bleeding reads against where the reference has light.
std::vector<std::uint8_t> makeSoftOverlay(int width, int height, const std::vector<PixelClass>& classes,
                                          const std::vector<float>& shadowFactor, const std::vector<float>& lambert,
                                          const std::vector<float>& visibility,
                                          const std::vector<std::uint8_t>& measured, float ambient);

// The soft overlay's counts in words: "light bleeding 1234 of 17020 umbra pixels (7.25 %), over-darkening 12 of
// 40000 fully lit pixels (0.03 %)".
std::string softOverlayCounts(const SoftAccuracy& soft);

}  // namespace shadowlab
