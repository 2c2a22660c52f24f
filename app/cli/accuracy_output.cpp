#include "cli/accuracy_output.h"

#include <iomanip>

namespace shadowlab::cli {

void printAccuracy(std::ostream& out, const AccuracyReport& r) {
    const AccuracyCounts& c = r.counts;
    out << std::fixed << std::setprecision(3);
    out << "accuracy (" << r.width << "x" << r.height << ", k = " << std::setprecision(1) << r.kTexels
        << " texels = filter radius + 1):\n"
        << std::setprecision(3);
    out << "  acne        " << std::setw(8) << r.acnePercent << " %   (" << c.acne << " of " << c.lit
        << " truly lit pixels shadowed, farther than k from a true edge)\n";
    out << "  leak        " << std::setw(8) << r.leakPercent << " %   (" << c.leak << " of " << c.shadowed
        << " truly shadowed pixels lit, farther than k from a true edge)\n";
    out << "  faint acne  " << std::setw(8) << r.faintAcnePercent << " %   (" << c.faintAcne
        << " lit pixels darkened but S >= 0.5)\n";
    out << "  edge error  " << std::setw(8) << r.edgeErrorP95Texels << " texels (95th percentile over "
        << c.mismatched << " mismatched pixels; " << c.mismatchedWithinK << " of them within k)\n";
    out << "  pixels " << c.pixels << ": measured " << c.measured << ", background " << c.background
        << ", facing away " << c.facingAway << ", outside the cone " << c.outsideCone << ", non-finite "
        << c.nonFinite << ", coverage mismatch " << c.coverageMismatch << ", true boundary " << c.boundaryPixels
        << "\n";
    out.unsetf(std::ios::floatfield);
}

void printAccuracyCost(std::ostream& out, const AccuracyReport& r) {
    const AccuracyCost& c = r.cost;
    out << std::fixed << std::setprecision(1);
    out << "reference cost:\n";
    if (c.bvhReused)
        out << "  BVH            reused (" << c.triangles << " triangles)\n";
    else
        out << "  BVH build      " << c.bvhBuildMs << " ms (" << c.triangles << " triangles, Embree)\n";
    if (c.referenceReused) {
        out << "  reference      reused (same scene, light, camera and size)\n";
    } else {
        out << "  G-buffer       " << c.gbufferMs << " ms (pass + read-back + double-precision surface rebuild)\n";
        out << "  shadow rays    " << c.traceMs << " ms for " << c.rays << " rays on " << c.threads << " threads = "
            << std::setprecision(2) << c.raysPerSecond / 1e6 << " Mrays/s\n"
            << std::setprecision(1);
        out << "  true boundary  " << c.boundaryMs << " ms\n";
    }
    out << "  boundary probe " << c.probeMs << " ms (" << c.probedPixels
        << " pixels far from a visible edge probed for hidden ones)\n";
    out << "  tool frame     " << c.toolFrameMs << " ms (shadow pass + shadow-factor pass + read-back)\n";
    out << "  metrics        " << c.metricsMs << " ms (distances, numbers, overlay)\n";
    out << "  total          " << c.totalMs << " ms\n";
    out.unsetf(std::ios::floatfield);
}

nlohmann::json accuracyToJson(const AccuracyReport& r) {
    const AccuracyCounts& c = r.counts;
    const AccuracyCost& k = r.cost;
    return {
        {"width", r.width},
        {"height", r.height},
        {"acnePercent", r.acnePercent},
        {"leakPercent", r.leakPercent},
        {"faintAcnePercent", r.faintAcnePercent},
        {"edgeErrorP95Texels", r.edgeErrorP95Texels},
        {"kTexels", r.kTexels},
        {"texelWorldSize", r.texelWorldSize},
        {"counts",
         {{"pixels", c.pixels}, {"background", c.background}, {"facingAway", c.facingAway},
          {"outsideCone", c.outsideCone}, {"nonFinite", c.nonFinite}, {"measured", c.measured}, {"lit", c.lit},
          {"shadowed", c.shadowed}, {"acne", c.acne}, {"faintAcne", c.faintAcne}, {"leak", c.leak},
          {"mismatched", c.mismatched}, {"mismatchedWithinK", c.mismatchedWithinK},
          {"boundaryPixels", c.boundaryPixels}, {"coverageMismatch", c.coverageMismatch}}},
        {"reference",
         {{"bvhReused", k.bvhReused}, {"referenceReused", k.referenceReused}, {"bvhBuildMs", k.bvhBuildMs},
          {"triangles", k.triangles}, {"gbufferMs", k.gbufferMs}, {"traceMs", k.traceMs}, {"rays", k.rays},
          {"raysPerSecond", k.raysPerSecond}, {"threads", k.threads}, {"boundaryMs", k.boundaryMs},
          {"probeMs", k.probeMs}, {"probedPixels", k.probedPixels},
          {"toolFrameMs", k.toolFrameMs}, {"metricsMs", k.metricsMs}, {"totalMs", k.totalMs}}},
    };
}

}  // namespace shadowlab::cli
