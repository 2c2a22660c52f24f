#include "cli/accuracy_output.h"

#include "accuracy/cause_shares.h"
#include "cli/soft_accuracy_output.h"
#include "settings/settings_fields.h"

#include <algorithm>
#include <cstdio>
#include <iomanip>

namespace shadowlab::cli {

namespace {

// A cascaded light: each cascade's numbers and the seam's (cascade_accuracy.h); nothing for other lights.
void printCascades(std::ostream& out, const CascadeAccuracy& a) {
    if (a.cascades.empty()) return;
    out << "  per cascade (the pixels each holds; texel = the cascade's texel in world units):\n";
    for (const CascadeNumbers& n : a.cascades)
        out << "    cascade:" << n.cascade << "  texel " << std::setprecision(4) << n.texelWorldSize
            << std::setprecision(3) << "  acne " << n.acnePercent << " %  leak " << n.leakPercent << " %  wrong "
            << n.wrongPercent << " %  mean error " << std::setprecision(4) << n.meanError << std::setprecision(3)
            << "  (" << n.measured << " pixels)\n";
    if (a.beyondShadowDistance)
        out << "    beyond the shadow distance: " << a.beyondShadowDistance << " pixels (lit by the tool)\n";
    const SeamNumbers& s = a.seam;
    out << "  seams (pixels within " << s.bandPixels << " screen pixels of another cascade): wrong " << s.bandWrongPercent
        << " %, mean error " << std::setprecision(4) << s.bandMeanError << std::setprecision(3) << " over " << s.band
        << " pixels; interiors: wrong " << s.interiorWrongPercent << " %, mean error " << std::setprecision(4)
        << s.interiorMeanError << std::setprecision(3) << " over " << s.interior << " pixels\n";
}

nlohmann::json cascadesToJson(const CascadeAccuracy& a) {
    nlohmann::json cascades = nlohmann::json::array();
    for (const CascadeNumbers& n : a.cascades)
        cascades.push_back({{"view", "cascade:" + std::to_string(n.cascade)}, {"texelWorldSize", n.texelWorldSize},
                            {"pixels", n.measured}, {"acnePercent", n.acnePercent}, {"leakPercent", n.leakPercent},
                            {"wrongPercent", n.wrongPercent}, {"meanError", n.meanError}});
    const SeamNumbers& s = a.seam;
    return {{"cascades", cascades},
            {"beyondShadowDistance", a.beyondShadowDistance},
            {"seam",
             {{"bandPixels", s.bandPixels}, {"band", s.band}, {"interior", s.interior},
              {"bandWrongPercent", s.bandWrongPercent}, {"bandMeanError", s.bandMeanError},
              {"interiorWrongPercent", s.interiorWrongPercent}, {"interiorMeanError", s.interiorMeanError}}}};
}

}  // namespace

void printAccuracy(std::ostream& out, const AccuracyReport& r) {
    const AccuracyCounts& c = r.counts;
    out << std::fixed << std::setprecision(3);
    out << "accuracy, metrics version " << r.metricsVersion << " (" << r.width << "x" << r.height << ", k = "
        << std::setprecision(1) << r.kTexels << " texels = filter radius + 1 = " << std::setprecision(3)
        << r.kTexels * r.texelWorldSize << " world units; e = 1/255"
        << (r.soft.measured ? "; V = the hard reference, one ray to the light's centre" : "") << "):\n";
    out << "  acne         " << std::setw(8) << r.acnePercent << " %   (" << c.acne << " of " << c.lit
        << " truly lit pixels visibly darkened, S < 1-e, farther than k from a true edge; severity: mean 1-S = "
        << r.acneSeverity << ")\n";
    out << "  leak         " << std::setw(8) << r.leakPercent << " %   (" << c.leak << " of " << c.shadowed
        << " truly shadowed pixels visibly lit, S > e, farther than k from a true edge)\n";
    out << "  wrong pixels " << std::setw(8) << r.wrongPercent << " %   (" << c.wrong << " of " << c.measured
        << " measured pixels with |S-V| >= 0.5, edges included; " << c.wrongBeyondK << " beyond k)\n";
    out << "  mean error   " << std::setw(8) << std::setprecision(4) << r.meanError << "     (mean |S-V| over measured "
        << "pixels, edges included)\n" << std::setprecision(3);
    out << "  edge error   " << std::setw(8) << r.edgeErrorP95Texels << " texels = " << r.edgeErrorP95World
        << " world units = " << std::setprecision(1) << r.edgeErrorP95ScreenPixels << " screen pixels"
        << std::setprecision(3) << " (95th percentile over " << c.mismatched << " mismatched pixels; "
        << c.mismatchedWithinK << " of them within k)\n";
    if (!r.coarseMapWarning.empty()) out << "  WARNING: " << r.coarseMapWarning << "\n";
    out << "  causes of the " << c.mismatched << " mismatched pixels (" << c.wrong << " wrong):\n";
    for (MismatchCause cause : allCauses()) {
        const std::size_t n = c.causePixels[std::size_t(cause)];
        if (n == 0) continue;
        const CauseInfo& info = causeInfo(cause);
        // Each cause's share of what it explains: acne of acne, leak of leak, wrong of wrong (cause_shares.h).
        out << "    " << std::left << std::setw(42) << info.name << causeShares(r, cause) << std::right << "  -> "
            << info.remedy << "\n";
    }
    if (r.texelDensity.pixels)
        out << "  texel density " << std::setprecision(3) << r.texelDensity.median << " texels per screen pixel (median; 5th "
            << "percentile " << r.texelDensity.p5 << ", 95th " << r.texelDensity.p95 << "; below 1 the map is blockier "
            << "than the screen)\n";
    printCascades(out, r.cascades);
    out << "  pixels " << c.pixels << ": measured " << c.measured << ", background " << c.background
        << ", facing away " << c.facingAway << ", outside the cone " << c.outsideCone << ", beyond the range "
        << c.outOfRange << ", non-finite "
        << c.nonFinite << ", coverage mismatch " << c.coverageMismatch << ", true boundary " << c.boundaryPixels
        << "\n";
    out.unsetf(std::ios::floatfield);
    printSoftAccuracy(out, r.soft);
}

std::string legendText(OverlayKind kind) { return legendText(overlayLegend(kind)); }

std::string legendText(const std::vector<LegendEntry>& legend) {
    std::string text;
    for (const LegendEntry& e : legend) {
        char entry[120];
        std::snprintf(entry, sizeof entry, "%s#%02x%02x%02x = %s", text.empty() ? "" : ", ", e.red, e.green, e.blue,
                      e.name);
        text += entry;
    }
    return text;
}

void printAccuracyCost(std::ostream& out, const AccuracyReport& r) {
    const AccuracyCost& c = r.cost;
    out << std::fixed << std::setprecision(1);
    out << "reference cost:\n";
    if (c.bvhReused)
        out << "  BVH            reused (" << c.triangles << " triangles)\n";
    else if (c.bvhUpdated)
        out << "  BVH update     " << std::setprecision(3) << c.bvhUpdateMs << std::setprecision(1) << " ms ("
            << c.instancesMoved << " instances moved; the mesh BVHs kept, the top level re-committed)\n";
    else
        out << "  BVH build      " << c.bvhBuildMs << " ms (" << c.triangles
            << " triangles, Embree, on the other cores while the tool frame renders)\n";
    if (c.referenceReused) {
        out << "  reference      reused (same scene, light, camera and size)\n";
    } else {
        // 0 ms: the surface samples came from the cache (same camera and size; another light was traced).
        if (c.gbufferMs > 0.0)
            out << "  G-buffer       " << c.gbufferMs << " ms (draw " << c.gbufferDrawMs << " + read-back "
                << c.gbufferReadBackMs << " + double-precision surface rebuild " << c.gbufferRebuildMs << ")\n";
        else
            out << "  G-buffer       reused (same camera and size)\n";
        out << "  shadow rays    " << c.traceMs << " ms for " << c.rays << " rays on " << c.threads << " threads = "
            << std::setprecision(2) << c.raysPerSecond / 1e6 << " Mrays/s\n"
            << std::setprecision(1);
        out << "  true boundary  " << c.boundaryMs << " ms\n";
    }
    out << "  boundary probe " << c.probeMs << " ms (" << c.probedPixels
        << " pixels far from a visible edge probed for hidden ones)\n";
    out << "  tool frame     " << c.toolFrameMs << " ms (render " << c.toolRenderMs
        << ": scene upload, shadow pass, shadow-factor pass; read-back " << c.toolReadBackMs << ")\n";
    out << "  metrics        " << c.metricsMs << " ms (causes " << c.causesMs << "; overlays and per-pixel copies "
        << c.overlaysMs << ", made on other threads beside the numbers)\n";
    if (c.programsBuilt > 0)
        out << "  programs       " << c.programsBuilt << " GL programs built in " << c.programBuildMs
            << " ms (first use; inside the stages above)\n";
    out << "  total          " << c.totalMs << " ms\n";
    out.unsetf(std::ios::floatfield);
}

nlohmann::json accuracyToJson(const AccuracyReport& r) {
    const AccuracyCounts& c = r.counts;
    const AccuracyCost& k = r.cost;
    nlohmann::json causes = nlohmann::json::object();
    for (MismatchCause cause : allCauses())
        causes[causeInfo(cause).key] = {{"pixels", c.causePixels[std::size_t(cause)]},
                                        {"wrong", c.causeWrong[std::size_t(cause)]},
                                        {"percentOfWrong", r.causePercentOfWrong(cause)},
                                        {"acne", c.causeAcne[std::size_t(cause)]},
                                        {"percentOfAcne", r.causePercentOfAcne(cause)},
                                        {"leak", c.causeLeak[std::size_t(cause)]},
                                        {"percentOfLeak", r.causePercentOfLeak(cause)}};
    nlohmann::json json = numbersToJson(r);
    json.update(nlohmann::json{
        {"metricsVersion", r.metricsVersion},
        {"width", r.width},
        {"height", r.height},
        {"coarseMap", !r.coarseMapWarning.empty()},
        {"coarseMapWarning", r.coarseMapWarning},
        {"causes", causes},
        {"kTexels", r.kTexels},
        {"texelWorldSize", r.texelWorldSize},
        {"counts",
         {{"pixels", c.pixels}, {"background", c.background}, {"facingAway", c.facingAway},
          {"outsideCone", c.outsideCone}, {"outOfRange", c.outOfRange}, {"nonFinite", c.nonFinite}, {"measured", c.measured}, {"lit", c.lit},
          {"shadowed", c.shadowed}, {"acne", c.acne}, {"leak", c.leak}, {"wrong", c.wrong},
          {"wrongBeyondK", c.wrongBeyondK}, {"mismatched", c.mismatched}, {"mismatchedWithinK", c.mismatchedWithinK},
          {"shadowedNearEdge", c.shadowedNearEdge},
          {"boundaryPixels", c.boundaryPixels}, {"coverageMismatch", c.coverageMismatch}}},
        {"reference",
         {{"bvhReused", k.bvhReused}, {"referenceReused", k.referenceReused}, {"bvhBuildMs", k.bvhBuildMs},
          {"bvhUpdated", k.bvhUpdated}, {"bvhUpdateMs", k.bvhUpdateMs}, {"instancesMoved", k.instancesMoved},
          {"triangles", k.triangles}, {"gbufferMs", k.gbufferMs}, {"traceMs", k.traceMs}, {"rays", k.rays},
          {"raysPerSecond", k.raysPerSecond}, {"threads", k.threads}, {"boundaryMs", k.boundaryMs},
          {"probeMs", k.probeMs}, {"probedPixels", k.probedPixels},
          {"toolFrameMs", k.toolFrameMs}, {"toolRenderMs", k.toolRenderMs}, {"toolReadBackMs", k.toolReadBackMs},
{"gbufferDrawMs", k.gbufferDrawMs},
          {"gbufferReadBackMs", k.gbufferReadBackMs}, {"gbufferRebuildMs", k.gbufferRebuildMs},
          {"programsBuilt", k.programsBuilt}, {"programBuildMs", k.programBuildMs}, {"causesMs", k.causesMs},
          {"overlaysMs", k.overlaysMs}, {"metricsMs", k.metricsMs}, {"totalMs", k.totalMs}}},
    });
    json["texelDensity"] = {{"pixels", r.texelDensity.pixels}, {"p5", r.texelDensity.p5},
                            {"median", r.texelDensity.median}, {"p95", r.texelDensity.p95}};
    if (!r.cascades.cascades.empty()) json["cascaded"] = cascadesToJson(r.cascades);
    if (r.soft.measured) json["soft"] = softAccuracyToJson(r.soft);
    return json;
}

nlohmann::json numbersToJson(const AccuracyNumbers& n) {
    return {
        {"acnePercent", n.acnePercent},
        {"acneSeverity", n.acneSeverity},
        {"leakPercent", n.leakPercent},
        {"wrongPixelsPercent", n.wrongPercent},
        {"meanError", n.meanError},
        {"edgeErrorP95Texels", n.edgeErrorP95Texels},
        {"edgeErrorP95World", n.edgeErrorP95World},
        {"edgeErrorP95ScreenPixels", n.edgeErrorP95ScreenPixels},
    };
}

std::string lightLabel(std::size_t index, LightType type) {
    return "lights." + std::to_string(index) + " (" + lightTypeName(type) + ")";
}

namespace {

void printWhole(std::ostream& out, const ManyLightsReport& m) {
    const AccuracyNumbers& w = m.whole;
    const AccuracyCounts& c = w.counts;
    out << std::fixed << std::setprecision(3);
    out << "whole picture (" << m.lights.size() << " light" << (m.lights.size() == 1 ? "" : "s")
        << " measured; a pixel counts once, wrong when wrong for any light that reaches it):\n";
    out << "  acne         " << std::setw(8) << w.acnePercent << " %   (" << c.acne << " of " << c.lit
        << " pixels truly lit by some light show acne for at least one; severity " << w.acneSeverity << ")\n";
    out << "  leak         " << std::setw(8) << w.leakPercent << " %   (" << c.leak << " of " << c.shadowed
        << " pixels truly shadowed from some light leak for at least one)\n";
    out << "  wrong pixels " << std::setw(8) << w.wrongPercent << " %   (" << c.wrong << " of " << c.measured
        << " measured pixels wrong for at least one light; " << c.wrongBeyondK << " beyond k)\n";
    out << "  mean error   " << std::setw(8) << std::setprecision(4) << w.meanError
        << "     (mean over measured pixels of the largest |S-V| among the lights reaching them)\n"
        << std::setprecision(3);
    out << "  edge error   " << std::setw(8) << w.edgeErrorP95Texels << " texels = " << w.edgeErrorP95World
        << " world units = " << std::setprecision(1) << w.edgeErrorP95ScreenPixels << " screen pixels"
        << std::setprecision(3) << " (the largest light's)\n";
    out << "  causes of the " << c.mismatched << " mismatched pixels (each under its worst light's cause):\n";
    for (MismatchCause cause : allCauses()) {
        const std::size_t n = c.causePixels[std::size_t(cause)];
        if (n == 0) continue;
        out << "    " << std::left << std::setw(42) << causeInfo(cause).name << std::right << std::setw(8) << n
            << " pixels, " << std::setw(8) << c.causeWrong[std::size_t(cause)] << " wrong\n";
    }
    out << "  pixels " << c.pixels << ": measured " << c.measured << ", reached by no measured light "
        << m.unreached << "\n";
    if (const SoftAccuracy& soft = m.wholeSoft; soft.measured) {
        const SoftCounts& sc = soft.counts;
        out << "  soft (version 3; a sized light's soft V, a hard light's exact V; each pixel once):\n";
        out << "    wrong pixels   " << std::setw(8) << soft.wrongPercent << " %   (" << sc.wrong << " of "
            << sc.measured << " measured pixels with |S-V| >= 0.5 for some light)\n";
        out << "    mean error     " << std::setw(8) << std::setprecision(4) << soft.meanError
            << "     (mean of the largest |S-V| among the lights reaching a pixel)\n" << std::setprecision(3);
        out << "    bleeding       " << std::setw(8) << soft.bleedingPercent << " %   (" << sc.bleeding << " of "
            << sc.umbra << " pixels in some light's umbra that light lights)\n";
        out << "    over-darkening " << std::setw(8) << soft.overDarkeningPercent << " %   (" << sc.overDarkened
            << " of " << sc.fullyLit << " pixels fully lit by some light that light darkens)\n";
        out << "    penumbra width error " << std::setprecision(4) << soft.penumbra.errorWorld
            << " world units (the largest in magnitude of the lights')\n";
    }
    out.unsetf(std::ios::floatfield);
}

}  // namespace

void printManyLights(std::ostream& out, const ManyLightsReport& many) {
    for (const LightAccuracy& light : many.lights) {
        out << lightLabel(light.index, light.type) << ", measured alone (its shadow factor is the one it has in the "
            << "full frame):\n";
        printAccuracy(out, light.report);
        printAccuracyCost(out, light.report);
    }
    for (const NotMeasuredLight& n : many.notMeasured) out << "not measured: " << n.reason << "\n";
    printWhole(out, many);
}

nlohmann::json manyLightsToJson(const ManyLightsReport& many) {
    nlohmann::json lights = nlohmann::json::array();
    for (const LightAccuracy& light : many.lights) {
        nlohmann::json j = accuracyToJson(light.report);
        j["index"] = light.index;
        j["type"] = lightTypeName(light.type);
        lights.push_back(std::move(j));
    }
    nlohmann::json notMeasured = nlohmann::json::array();
    for (const NotMeasuredLight& n : many.notMeasured) notMeasured.push_back({{"index", n.index}, {"reason", n.reason}});
    const AccuracyNumbers& w = many.whole;
    const AccuracyCounts& c = w.counts;
    nlohmann::json causes = nlohmann::json::object();
    for (MismatchCause cause : allCauses())
        causes[causeInfo(cause).key] = {{"pixels", c.causePixels[std::size_t(cause)]},
                                        {"wrong", c.causeWrong[std::size_t(cause)]}};
    return {
        {"metricsVersion", kMetricsVersion},
        {"width", many.width},
        {"height", many.height},
        {"lights", lights},
        {"notMeasured", notMeasured},
        {"wholeSoft", many.wholeSoft.measured ? softAccuracyToJson(many.wholeSoft) : nlohmann::json(nullptr)},
        {"whole",
         {{"lightsMeasured", many.lights.size()}, {"acnePercent", w.acnePercent}, {"acneSeverity", w.acneSeverity},
          {"leakPercent", w.leakPercent}, {"wrongPixelsPercent", w.wrongPercent}, {"meanError", w.meanError},
          {"edgeErrorP95Texels", w.edgeErrorP95Texels}, {"edgeErrorP95World", w.edgeErrorP95World},
          {"edgeErrorP95ScreenPixels", w.edgeErrorP95ScreenPixels}, {"causes", causes},
          {"counts",
           {{"pixels", c.pixels}, {"measured", c.measured}, {"unreached", many.unreached}, {"lit", c.lit},
            {"shadowed", c.shadowed}, {"acne", c.acne}, {"leak", c.leak}, {"wrong", c.wrong},
            {"wrongBeyondK", c.wrongBeyondK}, {"mismatched", c.mismatched},
            {"mismatchedWithinK", c.mismatchedWithinK}}}}},
    };
}

}  // namespace shadowlab::cli
