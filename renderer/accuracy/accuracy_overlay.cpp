#include "accuracy/accuracy_overlay.h"

#include <algorithm>
#include <cmath>

namespace shadowlab {

std::vector<std::uint8_t> makeOverlay(int width, int height, const std::vector<PixelClass>& classes,
                                      const std::vector<float>& shadowFactor, const std::vector<float>& lambert,
                                      const std::vector<PixelMark>& marks, const ShadowBoundary& boundary,
                                      float ambient) {
    const std::size_t count = std::size_t(width) * std::size_t(height);
    std::vector<std::uint8_t> rgba(count * 4, 255);
    auto put = [&](std::size_t i, int r, int g, int b) {
        rgba[i * 4] = std::uint8_t(r);
        rgba[i * 4 + 1] = std::uint8_t(g);
        rgba[i * 4 + 2] = std::uint8_t(b);
    };
    for (std::size_t i = 0; i < count; ++i) {
        if (classes[i] == PixelClass::Background) {
            put(i, 20, 22, 26);
            continue;
        }
        const float s = std::isfinite(shadowFactor[i]) ? std::clamp(shadowFactor[i], 0.0f, 1.0f) : 0.0f;
        const float light = ambient + (1.0f - ambient) * s * lambert[i];
        const int grey = int(45.0f + 95.0f * std::clamp(light, 0.0f, 1.0f));
        switch (marks[i]) {
            case PixelMark::Acne: put(i, 235, 40, 40); break;
            case PixelMark::AcneNearEdge: put(i, 120, 45, 45); break;
            case PixelMark::Leak: put(i, 50, 110, 255); break;
            case PixelMark::LeakNearEdge: put(i, 40, 60, 125); break;
            case PixelMark::FaintAcne: put(i, 210, 130, 60); break;
            case PixelMark::None: put(i, grey, grey, grey); break;
        }
        const bool counted = marks[i] == PixelMark::Acne || marks[i] == PixelMark::Leak;
        if (boundary.onBoundary(i) && !counted) put(i, 255, 220, 0);
    }
    return rgba;
}

}  // namespace shadowlab
