#include "accuracy/compare_label.h"

#include <cstdio>

namespace shadowlab {

namespace {

std::string milliseconds(const std::optional<double>& ms) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f ms", ms.value_or(0.0));
    return ms ? text : "n/a";
}

}  // namespace

std::vector<std::string> compareLabel(const std::string& side, const std::string& name, const FrameStats& stats) {
    return {side + ": " + name, "shadow " + milliseconds(stats.shadowPass.milliseconds) + ", main " +
                                    milliseconds(stats.mainPass.milliseconds) + " (" +
                                    (stats.timingSource.rfind("GPU", 0) == 0 ? "GPU" : "CPU") + ")"};
}

std::string accuracyLine(const AccuracyNumbers& r) {
    char text[128];
    std::snprintf(text, sizeof text, "acne %.3f %%, leak %.3f %%, wrong %.3f %%", r.acnePercent, r.leakPercent,
                  r.wrongPercent);
    return text;
}

}  // namespace shadowlab
