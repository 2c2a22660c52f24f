#include "accuracy/accuracy_overlay.h"

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

constexpr LegendEntry kAcne{"acne", 235, 40, 40};
constexpr LegendEntry kAcneNearEdge{"acne within k", 120, 45, 45};
constexpr LegendEntry kLeak{"leak", 50, 110, 255};
constexpr LegendEntry kLeakNearEdge{"leak within k", 40, 60, 125};
constexpr LegendEntry kBoundary{"true boundary", 255, 220, 0};

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

std::vector<std::uint8_t> dimmedPicture(int width, int height, const std::vector<PixelClass>& classes,
                                        const std::vector<float>& shadowFactor, const std::vector<float>& lambert,
                                        float ambient) {
    const std::size_t count = std::size_t(width) * std::size_t(height);
    std::vector<std::uint8_t> rgba(count * 4, 255);
    for (std::size_t i = 0; i < count; ++i) {
        std::uint8_t grey[3] = {20, 22, 26};
        if (classes[i] != PixelClass::Background) {
            const float s = std::isfinite(shadowFactor[i]) ? std::clamp(shadowFactor[i], 0.0f, 1.0f) : 0.0f;
            const float light = ambient + (1.0f - ambient) * s * lambert[i];
            grey[0] = grey[1] = grey[2] = std::uint8_t(45.0f + 95.0f * std::clamp(light, 0.0f, 1.0f));
        }
        std::copy(grey, grey + 3, &rgba[i * 4]);
    }
    return rgba;
}

std::vector<std::uint8_t> makeOverlay(OverlayKind kind, int width, int height, const std::vector<PixelClass>& classes,
                                      const std::vector<float>& shadowFactor, const std::vector<float>& lambert,
                                      const MetricsResult& metrics, const ShadowBoundary& boundary, float ambient) {
    const std::size_t count = std::size_t(width) * std::size_t(height);
    std::vector<std::uint8_t> rgba = dimmedPicture(width, height, classes, shadowFactor, lambert, ambient);
    auto put = [&](std::size_t i, const LegendEntry& e) {
        rgba[i * 4] = e.red;
        rgba[i * 4 + 1] = e.green;
        rgba[i * 4 + 2] = e.blue;
    };
    for (std::size_t i = 0; i < count; ++i) {
        if (classes[i] == PixelClass::Background) continue;
        const PixelMark mark = metrics.marks[i];
        bool counted = mark == PixelMark::Acne || mark == PixelMark::Leak;
        if (kind == OverlayKind::Cause && metrics.causes[i] != MismatchCause::None) {
            const CauseInfo& info = causeInfo(metrics.causes[i]);
            put(i, {"", info.red, info.green, info.blue});
            counted = metrics.causes[i] != MismatchCause::NearEdge;
        } else {
            switch (mark) {
                case PixelMark::Acne: put(i, kAcne); break;
                case PixelMark::AcneNearEdge: put(i, kAcneNearEdge); break;
                case PixelMark::Leak: put(i, kLeak); break;
                case PixelMark::LeakNearEdge: put(i, kLeakNearEdge); break;
                case PixelMark::None: break;  // the dimmed picture
            }
        }
        if (boundary.onBoundary(i) && !counted) put(i, kBoundary);
    }
    return rgba;
}

}  // namespace shadowlab
