#include "light/depth_format_change.h"

#include "light/depth_bias.h"
#include "settings/settings_fields.h"

#include <cstdio>

namespace shadowlab {

namespace {

// The preset key table's name of a format ("d32f").
std::string formatKey(DepthFormat format) {
    return findSettingsField("shadow.depthFormat")->choices.at(std::size_t(format));
}

}  // namespace

DepthFormatChange changeDepthFormat(const ShadowMapSettings& shadow, DepthFormat to,
                                    std::optional<double> receiverDepth) {
    DepthFormatChange change{shadow, {}};
    change.shadow.format = to;
    if (to == shadow.format || shadow.depthBias == 0.0f) return change;
    // The stored depth decides D32F's r: reversed-Z stores the same receivers at 1 - d.
    const double depth = receiverDepth.value_or(shadow.reversedZ ? 0.25 : 0.75);
    const double ratio = depthStepAt(shadow.format, depth) / depthStepAt(to, depth);
    change.shadow.depthBias = float(double(shadow.depthBias) * ratio);
    char text[160];
    std::snprintf(text, sizeof text, "DepthBias %.4g (%s) -> %.4g (%s), same world bias", double(shadow.depthBias),
                  formatKey(shadow.format).c_str(), double(change.shadow.depthBias), formatKey(to).c_str());
    change.note = text;
    return change;
}

}  // namespace shadowlab
