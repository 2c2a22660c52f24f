#include "accuracy/light_accuracy.h"

#include "accuracy/accuracy_metrics.h"
#include "accuracy/light_isolation.h"
#include "light/scene_lights.h"

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

// How bad light L's verdict at pixel i is (0: not mismatched), for picking the worst light; see the header.
int severity(const AccuracyReport& r, std::size_t i, double error) {
    const PixelMark mark = r.pixelMark[i];
    if (mark == PixelMark::None) return 0;
    const bool beyondK = mark == PixelMark::Acne || mark == PixelMark::Leak;
    return 1 + (beyondK ? 2 : 0) + (error >= 0.5 ? 1 : 0);
}

double errorAt(const AccuracyReport& r, std::size_t i) {
    return std::abs(double(r.pixelShadow[i]) - (isLit(r.pixelClass[i]) ? 1.0 : 0.0));
}

}  // namespace

void combineLights(ManyLightsReport& many) {
    many.whole = AccuracyNumbers{};
    many.unreached = 0;
    if (many.lights.empty()) return;
    const int width = many.lights.front().report.width, height = many.lights.front().report.height;
    many.width = width;
    many.height = height;
    const std::size_t count = std::size_t(width) * std::size_t(height);
    AccuracyCounts& c = many.whole.counts;
    for (const LightAccuracy& light : many.lights) {
        const AccuracyCounts& lc = light.report.counts;
        c.pixels = std::max(c.pixels, lc.pixels);
        c.background = std::max(c.background, lc.background);
        c.nonFinite = std::max(c.nonFinite, lc.nonFinite);
        c.coverageMismatch = std::max(c.coverageMismatch, lc.coverageMismatch);
        many.whole.edgeErrorP95Texels = std::max(many.whole.edgeErrorP95Texels, light.report.edgeErrorP95Texels);
        many.whole.edgeErrorP95World = std::max(many.whole.edgeErrorP95World, light.report.edgeErrorP95World);
        many.whole.edgeErrorP95ScreenPixels =
            std::max(many.whole.edgeErrorP95ScreenPixels, light.report.edgeErrorP95ScreenPixels);
    }
    many.overlayRgba.assign(count * 4, 255);
    many.causeOverlayRgba.assign(count * 4, 255);
    double errorSum = 0.0, severitySum = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        bool measured = false, lit = false, shadowed = false, acne = false, leak = false, wrong = false,
             wrongBeyondK = false, mismatched = false, allWithinK = true, surface = false, onBoundary = false;
        double worstError = 0.0, acneDepth = 0.0;
        const AccuracyReport* worst = nullptr;
        int worstSeverity = 0;
        double worstSeverityError = 0.0;
        for (const LightAccuracy& light : many.lights) {
            const AccuracyReport& r = light.report;
            surface = surface || r.pixelClass[i] != PixelClass::Background;
            onBoundary = onBoundary || r.pixelOnBoundary[i];
            if (!r.pixelMeasured[i]) continue;
            measured = true;
            const bool isLitHere = isLit(r.pixelClass[i]);
            (isLitHere ? lit : shadowed) = true;
            const double error = errorAt(r, i);
            worstError = std::max(worstError, error);
            const PixelMark mark = r.pixelMark[i];
            const bool beyondK = mark == PixelMark::Acne || mark == PixelMark::Leak;
            if (error >= 0.5) {
                wrong = true;
                wrongBeyondK = wrongBeyondK || beyondK;
            }
            if (mark != PixelMark::None) {
                mismatched = true;
                allWithinK = allWithinK && !beyondK;
            }
            if (mark == PixelMark::Acne) {
                acne = true;
                acneDepth = std::max(acneDepth, 1.0 - double(r.pixelShadow[i]));
            }
            leak = leak || mark == PixelMark::Leak;
            const int sev = severity(r, i, error);
            if (sev > worstSeverity || (sev > 0 && sev == worstSeverity && error > worstSeverityError)) {
                worstSeverity = sev;
                worstSeverityError = error;
                worst = &r;
            }
        }
        // The overlays: the worst light's colour, else any light's true boundary, else the mean dimmed picture.
        for (auto [target, pick] : {std::pair{&many.overlayRgba, &AccuracyReport::overlayRgba},
                                    std::pair{&many.causeOverlayRgba, &AccuracyReport::causeOverlayRgba}}) {
            std::uint8_t* out = &(*target)[i * 4];
            const AccuracyReport* from = worst;
            if (!from && onBoundary)
                for (const LightAccuracy& light : many.lights)
                    if (light.report.pixelOnBoundary[i]) from = &light.report;
            if (from) {
                std::copy_n(&((*from).*pick)[i * 4], 4, out);
            } else {
                for (int ch = 0; ch < 3; ++ch) {
                    unsigned sum = 0;
                    for (const LightAccuracy& light : many.lights) sum += ((light.report).*pick)[i * 4 + std::size_t(ch)];
                    out[ch] = std::uint8_t(sum / unsigned(many.lights.size()));
                }
            }
        }
        if (surface && !measured) ++many.unreached;
        if (!measured) continue;
        ++c.measured;
        c.lit += lit;
        c.shadowed += shadowed;
        errorSum += worstError;
        c.wrong += wrong;
        c.wrongBeyondK += wrongBeyondK;
        c.leak += leak;
        if (acne) {
            ++c.acne;
            severitySum += acneDepth;
        }
        if (!mismatched) continue;
        ++c.mismatched;
        c.mismatchedWithinK += allWithinK;
        const MismatchCause cause = worst->pixelCause[i];
        ++c.causePixels[std::size_t(cause)];
        c.causeWrong[std::size_t(cause)] += wrong;
        c.causeAcne[std::size_t(cause)] += acne;
        c.causeLeak[std::size_t(cause)] += leak;
    }
    AccuracyNumbers& w = many.whole;
    w.acnePercent = c.lit ? 100.0 * double(c.acne) / double(c.lit) : 0.0;
    w.acneSeverity = c.acne ? severitySum / double(c.acne) : 0.0;
    w.leakPercent = c.shadowed ? 100.0 * double(c.leak) / double(c.shadowed) : 0.0;
    w.wrongPercent = c.measured ? 100.0 * double(c.wrong) / double(c.measured) : 0.0;
    w.meanError = c.measured ? errorSum / double(c.measured) : 0.0;
}

ManyLightsReport measureLights(AccuracyMeter& meter, const Scene& scene, const Settings& settings,
                               const Camera& camera, int width, int height, std::optional<std::size_t> only,
                               AccuracyProgress* progress) {
    ManyLightsReport many;
    std::vector<std::size_t> indices;
    if (only) {
        if (std::string why = unmeasurableReason(settings, scene, *only); !why.empty()) {
            many.error = why;
            return many;
        }
        indices.push_back(*only);
    } else {
        const std::vector<LightSettings> lights = effectiveLights(settings, scene);
        indices = castingLights(settings, scene);
        for (std::size_t i = 0; i < lights.size(); ++i)
            if (std::find(indices.begin(), indices.end(), i) == indices.end())
                many.notMeasured.push_back({i, unmeasurableReason(settings, scene, i)});
        if (indices.empty()) {
            many.error = "no light casts a shadow (every light is off or has castsShadows=false): nothing to measure";
            return many;
        }
    }
    const float base = progress ? progress->base : 0.0f, span = progress ? progress->span : 1.0f;
    for (std::size_t j = 0; j < indices.size(); ++j) {
        std::string error;
        const std::optional<Settings> one = isolateLight(settings, scene, indices[j], error);
        if (!one) {
            many.error = error;
            return many;
        }
        if (progress) {
            progress->base = base + span * float(j) / float(indices.size());
            progress->span = span / float(indices.size());
        }
        LightAccuracy light;
        light.index = indices[j];
        light.type = one->lights[0].type;
        light.report = meter.measure(scene, *one, camera, width, height, progress);
        light.report.soft.light = indices[j];
        if (progress) {
            progress->base = base;
            progress->span = span;
        }
        if (!light.report.ok) {
            many.cancelled = light.report.cancelled;
            many.error = messageForLight(light.report.error, indices[j]);
            return many;
        }
        many.lights.push_back(std::move(light));
    }
    combineLights(many);
    many.ok = true;
    return many;
}

}  // namespace shadowlab
