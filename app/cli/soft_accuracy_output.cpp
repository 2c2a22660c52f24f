#include "cli/soft_accuracy_output.h"

#include <iomanip>

namespace shadowlab::cli {

void printSoftAccuracy(std::ostream& out, const SoftAccuracy& s) {
    if (!s.measured) return;
    const SoftCounts& c = s.counts;
    const PenumbraWidths& w = s.penumbra;
    out << std::fixed << std::setprecision(3);
    out << "  soft light lights." << s.light << " (size " << s.size << " " << s.sizeUnit
        << (s.sizeUnit == "degrees" ? " angular diameter" : " radius") << ", " << s.rays
        << " rays per pixel), metrics version " << s.metricsVersion
        << ", against the soft reference V = the share of rays reaching the light's disc:\n";
    out << "    wrong pixels   " << std::setw(8) << s.wrongPercent << " %   (" << c.wrong << " of " << c.measured
        << " measured pixels with |S-V| >= 0.5)\n";
    out << "    mean error     " << std::setw(8) << std::setprecision(4) << s.meanError
        << "     (mean |S-V| over measured pixels)\n" << std::setprecision(3);
    out << "    bleeding       " << std::setw(8) << s.bleedingPercent << " %   (" << c.bleeding << " of " << c.umbra
        << " umbra pixels, V = 0, that the technique lights, S > e)\n";
    out << "    over-darkening " << std::setw(8) << s.overDarkeningPercent << " %   (" << c.overDarkened << " of "
        << c.fullyLit << " fully lit pixels, V = 1, that the technique darkens, S < 1-e)\n";
    out << "    penumbra width error " << std::setprecision(4) << w.errorWorld << " world units = " << w.errorTexels
        << " texels (technique minus reference, median over " << c.profiles << " profiles across " << c.edgePixels
        << " true-edge pixels; 0.1..0.9 widths: technique " << w.techniqueWorld << " world units = "
        << w.techniqueTexels << " texels, reference " << w.referenceWorld << " world units = " << w.referenceTexels
        << " texels)\n";
    out << std::setprecision(1) << "    soft reference " << s.traceMs << " ms for " << s.tracedRays << " rays on "
        << s.threads << " threads" << (s.tracedRays == 0 ? " (reused: same light, size and ray count)" : "") << "\n";
    out.unsetf(std::ios::floatfield);
}

nlohmann::json softAccuracyToJson(const SoftAccuracy& s) {
    const SoftCounts& c = s.counts;
    const PenumbraWidths& w = s.penumbra;
    return {
        {"metricsVersion", s.metricsVersion},
        {"light", s.light},
        {"size", s.size},
        {"sizeUnit", s.sizeUnit},
        {"rays", s.rays},
        {"wrongPixelsPercent", s.wrongPercent},
        {"meanError", s.meanError},
        {"bleedingPercent", s.bleedingPercent},
        {"overDarkeningPercent", s.overDarkeningPercent},
        {"penumbraWidth",
         {{"errorWorld", w.errorWorld}, {"errorTexels", w.errorTexels}, {"techniqueWorld", w.techniqueWorld},
          {"techniqueTexels", w.techniqueTexels}, {"referenceWorld", w.referenceWorld},
          {"referenceTexels", w.referenceTexels}, {"profiles", c.profiles}, {"edgePixels", c.edgePixels}}},
        {"counts",
         {{"measured", c.measured}, {"umbra", c.umbra}, {"fullyLit", c.fullyLit}, {"penumbra", c.penumbra},
          {"wrong", c.wrong}, {"bleeding", c.bleeding}, {"overDarkened", c.overDarkened}}},
        {"reference", {{"traceMs", s.traceMs}, {"rays", s.tracedRays}, {"threads", s.threads}}},
    };
}

}  // namespace shadowlab::cli
