#include "accuracy/accuracy_metrics.h"

#include <algorithm>
#include <cmath>

namespace shadowlab {

double filterRadiusTexels(const FilterSettings& filter) {
    switch (filter.kind) {
        case FilterKind::Point: return 0.0;
        case FilterKind::Hardware2x2: return 1.0;
        case FilterKind::Pcf: return double(filter.kernel - 1) / 2.0;
        case FilterKind::Poisson: return double(filter.poissonRadius) + 1.0;
    }
    return 0.0;
}

double percentile(std::vector<double>& values, double p) {
    if (values.empty()) return 0.0;
    const double rank = std::ceil(p / 100.0 * double(values.size()));
    const std::size_t index = std::size_t(std::clamp(rank, 1.0, double(values.size()))) - 1;
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(index), values.end());
    return values[index];
}

MetricsResult computeMetrics(const std::vector<PixelClass>& classes, const std::vector<float>& shadowFactor,
                             const std::vector<std::uint8_t>& toolCovered, double k,
                             const std::function<double(std::size_t)>& distance) {
    MetricsResult r;
    AccuracyCounts& c = r.counts;
    c.pixels = classes.size();
    r.marks.assign(classes.size(), PixelMark::None);
    std::vector<double> mismatchDistances;
    for (std::size_t i = 0; i < classes.size(); ++i) {
        const PixelClass cls = classes[i];
        const bool surface = cls != PixelClass::Background;
        if (surface != (toolCovered[i] != 0)) ++c.coverageMismatch;
        switch (cls) {
            case PixelClass::Background: ++c.background; continue;
            case PixelClass::NonFinite: ++c.nonFinite; continue;
            case PixelClass::FacingAway: ++c.facingAway; continue;
            case PixelClass::OutsideCone: ++c.outsideCone; break;
            default: break;
        }
        if (!toolCovered[i]) continue;  // nothing of the tool's to compare (counted as a coverage mismatch)
        const float s = shadowFactor[i];
        if (!std::isfinite(s)) {
            ++c.nonFinite;
            continue;
        }
        ++c.measured;
        if (isLit(cls)) {
            ++c.lit;
            if (s < 0.5f) {
                ++c.mismatched;
                const double d = distance(i);
                mismatchDistances.push_back(d);
                if (d > k) {
                    ++c.acne;
                    r.marks[i] = PixelMark::Acne;
                } else {
                    ++c.mismatchedWithinK;
                    r.marks[i] = PixelMark::AcneNearEdge;
                }
            } else if (s < 1.0f && distance(i) > k) {
                ++c.faintAcne;
                r.marks[i] = PixelMark::FaintAcne;
            }
        } else {
            ++c.shadowed;
            if (s > 0.5f) {
                ++c.mismatched;
                const double d = distance(i);
                mismatchDistances.push_back(d);
                if (d > k) {
                    ++c.leak;
                    r.marks[i] = PixelMark::Leak;
                } else {
                    ++c.mismatchedWithinK;
                    r.marks[i] = PixelMark::LeakNearEdge;
                }
            }
        }
    }
    r.acnePercent = c.lit ? 100.0 * double(c.acne) / double(c.lit) : 0.0;
    r.faintAcnePercent = c.lit ? 100.0 * double(c.faintAcne) / double(c.lit) : 0.0;
    r.leakPercent = c.shadowed ? 100.0 * double(c.leak) / double(c.shadowed) : 0.0;
    r.edgeErrorP95Texels = percentile(mismatchDistances, 95.0);
    return r;
}

}  // namespace shadowlab
