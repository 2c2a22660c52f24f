#include "accuracy/accuracy_metrics.h"

#include "reference/parallel_rows.h"
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

namespace {

// One chunk's share of the metrics: its counts, sums and mismatched distances, in pixel order.
struct ChunkMetrics {
    AccuracyCounts counts;
    double errorSum = 0.0, severitySum = 0.0;
    std::vector<double> texels, world, screen;
};

// A fixed number of pixels a chunk, whatever the thread count: the sums add the same chunks in the same order, so
// the results are equal bit for bit on any number of cores.
constexpr std::size_t kChunkPixels = 8192;

void addCounts(AccuracyCounts& into, const AccuracyCounts& c) {
    into.background += c.background;
    into.nonFinite += c.nonFinite;
    into.facingAway += c.facingAway;
    into.outOfRange += c.outOfRange;
    into.outsideCone += c.outsideCone;
    into.coverageMismatch += c.coverageMismatch;
    into.measured += c.measured;
    into.lit += c.lit;
    into.shadowed += c.shadowed;
    into.wrong += c.wrong;
    into.mismatched += c.mismatched;
    into.wrongBeyondK += c.wrongBeyondK;
    into.mismatchedWithinK += c.mismatchedWithinK;
    into.acne += c.acne;
    into.leak += c.leak;
    for (std::size_t k = 0; k < kCauseCount; ++k) {
        into.causePixels[k] += c.causePixels[k];
        into.causeWrong[k] += c.causeWrong[k];
        into.causeAcne[k] += c.causeAcne[k];
        into.causeLeak[k] += c.causeLeak[k];
    }
}

}  // namespace

MetricsResult computeMetrics(const MetricsInput& in) {
    const std::vector<PixelClass>& classes = *in.classes;
    const std::vector<float>& shadowFactor = *in.shadowFactor;
    const std::vector<std::uint8_t>& toolCovered = *in.toolCovered;
    const double k = in.k;
    MetricsResult r;
    r.counts.pixels = classes.size();
    r.measured.assign(classes.size(), 0);
    r.marks.assign(classes.size(), PixelMark::None);
    r.causes.assign(classes.size(), MismatchCause::None);
    const std::size_t chunkCount = (classes.size() + kChunkPixels - 1) / kChunkPixels;
    std::vector<ChunkMetrics> chunks(chunkCount);
    parallelRows(int(chunkCount), [&](int chunk) {
        ChunkMetrics& out = chunks[std::size_t(chunk)];
        AccuracyCounts& c = out.counts;
        const std::size_t end = std::min(classes.size(), (std::size_t(chunk) + 1) * kChunkPixels);
        for (std::size_t i = std::size_t(chunk) * kChunkPixels; i < end; ++i) {
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
            out.errorSum += error;
            const bool wrong = error >= kWrongError;
            c.wrong += wrong;
            if (!visiblyWrong(lit, s)) continue;
            ++c.mismatched;
            const double d = in.distance(i);
            const bool beyondK = d > k;
            out.texels.push_back(d);
            if (in.worldPerTexel) out.world.push_back(d * in.worldPerTexel(i));
            if (in.worldPerTexel && in.worldPerPixel) {
                const double perPixel = in.worldPerPixel(i);
                out.screen.push_back(perPixel > 0.0 ? d * in.worldPerTexel(i) / perPixel : 0.0);
            }
            if (wrong && beyondK) ++c.wrongBeyondK;
            if (!beyondK) ++c.mismatchedWithinK;
            if (lit && beyondK) {
                ++c.acne;
                out.severitySum += 1.0 - double(s);
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
    });
    double errorSum = 0.0, severitySum = 0.0;
    std::vector<double> texels, world, screen;
    for (const ChunkMetrics& chunk : chunks) {
        addCounts(r.counts, chunk.counts);
        errorSum += chunk.errorSum;
        severitySum += chunk.severitySum;
        texels.insert(texels.end(), chunk.texels.begin(), chunk.texels.end());
        world.insert(world.end(), chunk.world.begin(), chunk.world.end());
        screen.insert(screen.end(), chunk.screen.begin(), chunk.screen.end());
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
