#pragma once
// DESIGN.md's accuracy measures from per-pixel buffers (no GL: unit-testable on synthetic buffers).
//   acne = #{V=1, S<0.5, dist>k} / #{V=1}      leak = #{V=0, S>0.5, dist>k} / #{V=0}
//   edge error = 95th percentile of dist over mismatched pixels, k = filter radius + 1 texel.
// Beyond DESIGN.md: faint acne = #{V=1, 0.5<=S<1, dist>k} / #{V=1} (visible moiré that is not acne by definition).
#include "accuracy/accuracy_meter.h"
#include "reference/visibility.h"

#include <functional>
#include <vector>

namespace shadowlab {

// How far a filter reads from the lookup position, in texels: point 0, hardware 2x2 1 (bilinear neighbours),
// N x N PCF (N-1)/2, Poisson its radius + 1 (its taps are bilinear).
double filterRadiusTexels(const FilterSettings& filter);
inline double acceptanceRadiusTexels(const FilterSettings& filter) { return filterRadiusTexels(filter) + 1.0; }

enum class PixelMark : std::uint8_t { None, Acne, AcneNearEdge, Leak, LeakNearEdge, FaintAcne };

struct MetricsResult {
    AccuracyCounts counts;
    double acnePercent = 0.0;
    double leakPercent = 0.0;
    double faintAcnePercent = 0.0;
    double edgeErrorP95Texels = 0.0;
    std::vector<PixelMark> marks;  // per pixel, for the overlay
};

// classes: the reference's verdict per pixel; shadowFactor: the tool's S per pixel; toolCovered: whether the tool's
// frame drew a surface there; distance(i): pixel i's distance to the true boundary in texels (only asked for pixels
// that need it). counts.boundaryPixels is left for the caller.
MetricsResult computeMetrics(const std::vector<PixelClass>& classes, const std::vector<float>& shadowFactor,
                             const std::vector<std::uint8_t>& toolCovered, double k,
                             const std::function<double(std::size_t)>& distance);

// The p-th percentile (0..100) by nearest rank; 0 for an empty list. Reorders values.
double percentile(std::vector<double>& values, double p);

}  // namespace shadowlab
