#include "accuracy/accuracy_overlay.h"

#include "reference/parallel_rows.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace shadowlab {

namespace {

constexpr LegendEntry kAcne{"acne", 235, 40, 40};
constexpr LegendEntry kAcneNearEdge{"acne within k", 120, 45, 45};
constexpr LegendEntry kLeak{"leak", 50, 110, 255};
constexpr LegendEntry kLeakNearEdge{"leak within k", 40, 60, 125};
constexpr LegendEntry kBoundary{"true boundary", 255, 220, 0};
constexpr LegendEntry kBleeding{"light bleeding (V = 0, lit)", 40, 230, 230};
constexpr LegendEntry kOverDarkened{"over-darkening (V = 1, darkened)", 255, 130, 0};
constexpr LegendEntry kPenumbra{"true penumbra (0 < V < 1)", 150, 110, 200};

}  // namespace

const std::vector<LegendEntry>& errorLegend() {
    static const std::vector<LegendEntry> legend = {kAcne, kLeak, kAcneNearEdge, kLeakNearEdge, kBoundary};
    return legend;
}

const std::vector<LegendEntry>& causeLegend() {
    static const std::vector<LegendEntry> legend = [] {
        std::vector<LegendEntry> l;
        for (MismatchCause cause : allCauses()) {
            const CauseInfo& info = causeInfo(cause);
            l.push_back({info.name, info.red, info.green, info.blue});
        }
        l.push_back(kBoundary);
        return l;
    }();
    return legend;
}

const std::vector<LegendEntry>& softLegend() {
    static const std::vector<LegendEntry> legend = {kBleeding, kOverDarkened, kPenumbra};
    return legend;
}

const std::vector<LegendEntry>& overlayLegend(OverlayKind kind) {
    switch (kind) {
        case OverlayKind::Cause: return causeLegend();
        case OverlayKind::Soft: return softLegend();
        case OverlayKind::Error: break;
    }
    return errorLegend();
}

OverlayRgb shadedColour(const LegendEntry& entry, float lambert) {
    const float l = std::isfinite(lambert) ? std::clamp(lambert, 0.0f, 1.0f) : 0.0f;
    const float f = kOverlayMinShade + (1.0f - kOverlayMinShade) * l;
    const auto scale = [f](std::uint8_t c) { return std::uint8_t(std::lround(float(c) * f)); };
    return {scale(entry.red), scale(entry.green), scale(entry.blue)};
}

bool isShadeOf(const LegendEntry& entry, const std::uint8_t* rgb) {
    // The factor from the brightest channel; every channel must then agree within rounding.
    const std::uint8_t c[3] = {entry.red, entry.green, entry.blue};
    const int top = int(std::max_element(c, c + 3) - c);
    if (c[top] == 0) return rgb[0] == 0 && rgb[1] == 0 && rgb[2] == 0;
    const float f = float(rgb[top]) / float(c[top]);
    if (f < kOverlayMinShade - 1.0f / float(c[top]) || f > 1.0f + 0.5f / float(c[top])) return false;
    for (int k = 0; k < 3; ++k)
        if (std::abs(float(rgb[k]) - float(c[k]) * f) > 1.5f) return false;
    return true;
}

std::vector<std::uint8_t> dimmedPicture(int width, int height, const std::vector<PixelClass>& classes,
                                        const std::vector<float>& shadowFactor, const std::vector<float>& lambert,
                                        float ambient) {
    const std::size_t count = std::size_t(width) * std::size_t(height);
    std::vector<std::uint8_t> rgba(count * 4, 255);
    parallelRows(height, [&](int row) {
        const std::size_t first = std::size_t(row) * std::size_t(width);
        for (std::size_t i = first; i < first + std::size_t(width); ++i) {
            std::uint8_t grey[3] = {20, 22, 26};
            if (classes[i] != PixelClass::Background) {
                const float s = std::isfinite(shadowFactor[i]) ? std::clamp(shadowFactor[i], 0.0f, 1.0f) : 0.0f;
                const float light = ambient + (1.0f - ambient) * s * lambert[i];
                grey[0] = grey[1] = grey[2] = std::uint8_t(45.0f + 95.0f * std::clamp(light, 0.0f, 1.0f));
            }
            std::copy(grey, grey + 3, &rgba[i * 4]);
        }
    });
    return rgba;
}

std::vector<std::uint8_t> makeOverlay(OverlayKind kind, int width, int height, const std::vector<PixelClass>& classes,
                                      const std::vector<float>& shadowFactor, const std::vector<float>& lambert,
                                      const MetricsResult& metrics, const ShadowBoundary& boundary, float ambient) {
    std::vector<std::uint8_t> rgba = dimmedPicture(width, height, classes, shadowFactor, lambert, ambient);
    auto put = [&](std::size_t i, const LegendEntry& e) {
        rgba[i * 4] = e.red;
        rgba[i * 4 + 1] = e.green;
        rgba[i * 4 + 2] = e.blue;
    };
    auto shade = [&](std::size_t i, const LegendEntry& e) {
        const OverlayRgb c = shadedColour(e, lambert[i]);
        put(i, {"", c.red, c.green, c.blue});
    };
    parallelRows(height, [&](int row) {
        const std::size_t first = std::size_t(row) * std::size_t(width);
        for (std::size_t i = first; i < first + std::size_t(width); ++i) {
            if (classes[i] == PixelClass::Background) continue;
            const PixelMark mark = metrics.marks[i];
            bool counted = mark == PixelMark::Acne || mark == PixelMark::Leak;
            if (kind == OverlayKind::Cause && metrics.causes[i] != MismatchCause::None) {
                const CauseInfo& info = causeInfo(metrics.causes[i]);
                shade(i, {"", info.red, info.green, info.blue});
                counted = metrics.causes[i] != MismatchCause::NearEdge;
            } else {
                switch (mark) {
                    case PixelMark::Acne: shade(i, kAcne); break;
                    case PixelMark::AcneNearEdge: shade(i, kAcneNearEdge); break;
                    case PixelMark::Leak: shade(i, kLeak); break;
                    case PixelMark::LeakNearEdge: shade(i, kLeakNearEdge); break;
                    case PixelMark::None: break;  // the dimmed picture
                }
            }
            if (boundary.onBoundary(i) && !counted) put(i, kBoundary);
        }
    });
    return rgba;
}

std::vector<std::uint8_t> makeSoftOverlay(int width, int height, const std::vector<PixelClass>& classes,
                                          const std::vector<float>& shadowFactor, const std::vector<float>& lambert,
                                          const std::vector<float>& visibility,
                                          const std::vector<std::uint8_t>& measured, float ambient) {
    std::vector<std::uint8_t> rgba = dimmedPicture(width, height, classes, shadowFactor, lambert, ambient);
    const std::size_t count = std::size_t(width) * std::size_t(height);
    for (std::size_t i = 0; i < count; ++i) {
        if (!measured[i]) continue;
        const float v = visibility[i];
        const SoftMark mark = softMark(v, shadowFactor[i]);
        const LegendEntry* entry = mark == SoftMark::Bleeding       ? &kBleeding
                                   : mark == SoftMark::OverDarkened ? &kOverDarkened
                                   : v > 0.0f && v < 1.0f           ? &kPenumbra
                                                                    : nullptr;
        if (!entry) continue;
        const OverlayRgb c = shadedColour(*entry, lambert[i]);
        rgba[i * 4] = c.red;
        rgba[i * 4 + 1] = c.green;
        rgba[i * 4 + 2] = c.blue;
    }
    return rgba;
}

std::string softOverlayCounts(const SoftAccuracy& soft) {
    const SoftCounts& c = soft.counts;
    char text[200];
    std::snprintf(text, sizeof text,
                  "light bleeding %zu of %zu umbra pixels (%.2f %%), over-darkening %zu of %zu fully lit pixels "
                  "(%.2f %%)",
                  c.bleeding, c.umbra, soft.bleedingPercent, c.overDarkened, c.fullyLit, soft.overDarkeningPercent);
    return text;
}

}  // namespace shadowlab
