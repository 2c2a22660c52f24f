#include "accuracy/cache_error.h"

#include "accuracy/accuracy_metrics.h"

#include <algorithm>
#include <cmath>

namespace shadowlab {

CacheError cacheErrorAgainst(const AccuracyReport& cached, const AccuracyReport& full) {
    CacheError e;
    const std::size_t count = std::min({cached.pixelShadow.size(), full.pixelShadow.size(),
                                        cached.pixelMeasured.size(), full.pixelMeasured.size()});
    double sum = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        if (!cached.pixelMeasured[i] || !full.pixelMeasured[i]) continue;
        ++e.measured;
        const double delta = std::abs(double(cached.pixelShadow[i]) - double(full.pixelShadow[i]));
        sum += delta;
        if (delta >= kWrongError) ++e.wrong;
    }
    if (e.measured) {
        e.wrongPercent = 100.0 * double(e.wrong) / double(e.measured);
        e.meanError = sum / double(e.measured);
    }
    return e;
}

}  // namespace shadowlab
