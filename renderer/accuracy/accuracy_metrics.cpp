#include "accuracy/accuracy_metrics.h"

#include "shading/filters/filter_technique.h"

#include <algorithm>
#include <cmath>

namespace shadowlab {

double filterRadiusTexels(const FilterSettings& filter) { return filterTechnique(filter.kind).radiusTexels(filter); }

std::size_t nearestRankIndex(std::size_t n, int percent) {
    const std::size_t rank = (std::size_t(std::clamp(percent, 0, 100)) * n + 99) / 100;
    return rank > 0 ? rank - 1 : 0;
}

double percentile(std::vector<double>& values, int percent) {
    if (values.empty()) return 0.0;
    const std::size_t index = nearestRankIndex(values.size(), percent);
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(index), values.end());
    return values[index];
}

MetricsResult computeMetrics(const MetricsInput& in) {
    const std::vector<PixelClass>& classes = *in.classes;
    const std::vector<float>& shadowFactor = *in.shadowFactor;
    const std::vector<std::uint8_t>& toolCovered = *in.toolCovered;
    const double k = in.k;
    MetricsResult r;
    AccuracyCounts& c = r.counts;
    c.pixels = classes.size();
    r.measured.assign(classes.size(), 0);
    r.marks.assign(classes.size(), PixelMark::None);
    r.causes.assign(classes.size(), MismatchCause::None);
    std::vector<double> texels, world, screen;
    double errorSum = 0.0, severitySum = 0.0;
    for (std::size_t i = 0; i < classes.size(); ++i) {
        const PixelClass cls = classes[i];
        const bool surface = cls != PixelClass::Background;
        if (surface != (toolCovered[i] != 0)) ++c.coverageMismatch;
        switch (cls) {
            case PixelClass::Background: ++c.background; continue;
            case PixelClass::NonFinite: ++c.nonFinite; continue;
            case PixelClass::FacingAway: ++c.facingAway; continue;
            case PixelClass::OutOfRange: ++c.outOfRange; continue;
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
        r.measured[i] = 1;
        const bool lit = isLit(cls);
        ++(lit ? c.lit : c.shadowed);
        const double error = std::abs(double(s) - (lit ? 1.0 : 0.0));
        errorSum += error;
        const bool wrong = error >= kWrongError;
        c.wrong += wrong;
        if (!visiblyWrong(lit, s)) continue;
        ++c.mismatched;
        const double d = in.distance(i);
        const bool beyondK = d > k;
        texels.push_back(d);
        if (in.worldPerTexel) world.push_back(d * in.worldPerTexel(i));
        if (in.worldPerTexel && in.worldPerPixel) {
            const double perPixel = in.worldPerPixel(i);
            screen.push_back(perPixel > 0.0 ? d * in.worldPerTexel(i) / perPixel : 0.0);
        }
        if (wrong && beyondK) ++c.wrongBeyondK;
        if (!beyondK) ++c.mismatchedWithinK;
        if (lit && beyondK) {
            ++c.acne;
            severitySum += 1.0 - double(s);
        }
        if (!lit && beyondK) ++c.leak;
        r.marks[i] = lit ? (beyondK ? PixelMark::Acne : PixelMark::AcneNearEdge)
                         : (beyondK ? PixelMark::Leak : PixelMark::LeakNearEdge);
        const MismatchCause cause = in.cause ? in.cause(i, d)
                                    : !beyondK ? MismatchCause::NearEdge
                                    : lit      ? MismatchCause::SelfShadowing
                                               : MismatchCause::BiasOverGap;
        r.causes[i] = cause;
        ++c.causePixels[std::size_t(cause)];
        if (wrong) ++c.causeWrong[std::size_t(cause)];
        if (beyondK) ++(lit ? c.causeAcne : c.causeLeak)[std::size_t(cause)];
    }
    setRatios(r, errorSum, severitySum);
    r.edgeErrorP95Texels = percentile(texels, kEdgeErrorPercentile);
    r.edgeErrorP95World = percentile(world, kEdgeErrorPercentile);
    r.edgeErrorP95ScreenPixels = percentile(screen, kEdgeErrorPercentile);
    return r;
}

void setRatios(AccuracyNumbers& r, double errorSum, double severitySum) {
    const AccuracyCounts& c = r.counts;
    r.acnePercent = c.lit ? 100.0 * double(c.acne) / double(c.lit) : 0.0;
    r.acneSeverity = c.acne ? severitySum / double(c.acne) : 0.0;
    r.leakPercent = c.shadowed ? 100.0 * double(c.leak) / double(c.shadowed) : 0.0;
    r.wrongPercent = c.measured ? 100.0 * double(c.wrong) / double(c.measured) : 0.0;
    r.meanError = c.measured ? errorSum / double(c.measured) : 0.0;
}

}  // namespace shadowlab
