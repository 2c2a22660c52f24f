#pragma once
// Changing shadow.depthFormat keeps what DepthBias means, not its number. DepthBias counts the format's minimum
// resolvable difference r, and r differs by orders of magnitude between formats (D32F: 2^-24 near depth 1, D16:
// 1/65535), so the same number is a very different world distance: 2 (d32f) read as d16 is 512 times more bias and
// every shadow detaches. The new DepthBias is the old one times r(old) / r(new) at the receivers' median depth, the
// same depth offset and so the same world-space bias there. SlopeScaledDepthBias and DepthBiasClamp are in window
// depth for every format and stay as they are.
#include "settings/settings.h"

#include <optional>
#include <string>

namespace shadowlab {

struct DepthFormatChange {
    ShadowMapSettings shadow;  // the new format, DepthBias re-expressed
    std::string note;          // e.g. "DepthBias 2 (d32f) -> 0.0078 (d16), same world bias"; "" when unchanged
};

// `receiverDepth`: the receivers' median stored depth (BiasReport::receiverDepthMedian); without one, depth 0.75 (0.25
// for reversed-Z, where the same receivers are stored at 1 - d).
DepthFormatChange changeDepthFormat(const ShadowMapSettings& shadow, DepthFormat to,
                                    std::optional<double> receiverDepth);

}  // namespace shadowlab
