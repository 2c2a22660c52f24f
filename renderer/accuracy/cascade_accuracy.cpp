#include "accuracy/cascade_accuracy.h"

#include "accuracy/accuracy_meter.h"
#include "accuracy/accuracy_metrics.h"

#include <algorithm>
#include <cmath>

namespace shadowlab {

CascadeAccuracy cascadeAccuracy(const AccuracyReport& report, const std::vector<std::int8_t>& cascadeOf,
                                const std::vector<double>& texelWorld, int bandPixels) {
    CascadeAccuracy out;
    out.seam.bandPixels = bandPixels;
    const int w = report.width, h = report.height;
    const std::size_t count = std::size_t(w) * std::size_t(h);
    if (cascadeOf.size() != count || report.pixelClass.size() != count || report.pixelShadow.size() != count ||
        report.pixelMeasured.size() != count || report.pixelMark.size() != count)
        return out;
    for (std::size_t c = 0; c < texelWorld.size(); ++c) {
        out.cascades.push_back({});
        out.cascades.back().cascade = int(c);
        out.cascades.back().texelWorldSize = texelWorld[c];
    }
    std::vector<double> errorSum(texelWorld.size(), 0.0);
    double bandError = 0.0, interiorError = 0.0;
    std::size_t bandWrong = 0, interiorWrong = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
            if (!report.pixelMeasured[i]) continue;
            const int c = cascadeOf[i];
            if (c < 0 || std::size_t(c) >= out.cascades.size()) {
                ++out.beyondShadowDistance;
                continue;
            }
            const bool lit = isLit(report.pixelClass[i]);
            const double error = std::abs(double(report.pixelShadow[i]) - (lit ? 1.0 : 0.0));
            const bool wrong = error >= kWrongError;
            CascadeNumbers& n = out.cascades[std::size_t(c)];
            ++n.measured;
            (lit ? n.lit : n.shadowed) += 1;
            n.acne += report.pixelMark[i] == PixelMark::Acne;
            n.leak += report.pixelMark[i] == PixelMark::Leak;
            n.wrong += wrong;
            errorSum[std::size_t(c)] += error;
            // In the band: another cascade holds a pixel within bandPixels (a split crosses the neighbourhood).
            bool band = false;
            for (int dy = -bandPixels; dy <= bandPixels && !band; ++dy)
                for (int dx = -bandPixels; dx <= bandPixels && !band; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                    const int other = cascadeOf[std::size_t(ny) * std::size_t(w) + std::size_t(nx)];
                    band = other >= 0 && other != c;
                }
            (band ? out.seam.band : out.seam.interior) += 1;
            (band ? bandError : interiorError) += error;
            (band ? bandWrong : interiorWrong) += wrong;
        }
    auto percent = [](std::size_t part, std::size_t whole) { return whole ? 100.0 * double(part) / double(whole) : 0.0; };
    for (std::size_t c = 0; c < out.cascades.size(); ++c) {
        CascadeNumbers& n = out.cascades[c];
        n.acnePercent = percent(n.acne, n.lit);
        n.leakPercent = percent(n.leak, n.shadowed);
        n.wrongPercent = percent(n.wrong, n.measured);
        n.meanError = n.measured ? errorSum[c] / double(n.measured) : 0.0;
    }
    out.seam.bandWrongPercent = percent(bandWrong, out.seam.band);
    out.seam.bandMeanError = out.seam.band ? bandError / double(out.seam.band) : 0.0;
    out.seam.interiorWrongPercent = percent(interiorWrong, out.seam.interior);
    out.seam.interiorMeanError = out.seam.interior ? interiorError / double(out.seam.interior) : 0.0;
    return out;
}

}  // namespace shadowlab
