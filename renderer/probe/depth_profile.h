#pragma once
// The depth profile (issue 13): along a screen-space line of a captured frame, per pixel, the receiver's light-space
// depth, the map's stored depth at the lookup texel (the staircase of texels) and the bias, with the samples where
// the surface shadows itself (acne) or a caster in front is hidden by the bias (Peter Panning). Built on PixelProbe:
// the numbers are the probe's, nothing is recomputed here.
#include "probe/pixel_probe.h"

#include <glm/ext/vector_int2.hpp>

#include <string>
#include <vector>

namespace shadowlab {

struct ProfileSample {
    double t = 0.0;         // distance from the line's start, pixels
    int x = 0, y = 0;       // pixel, y down from the top
    bool surface = false;   // false: background or outside the map's surfaces (no numbers)
    double receiver = 0.0;  // the receiver's window depth in the map (at the normal-offset lookup)
    double stored = 0.0;    // the map's depth at the lookup texel, the caster's bias included
    double bias = 0.0;      // this surface's bias as a caster (min(constant + slope, clamp)), depth
    double threshold = 0.0; // receiver - bias: the comparison receiver <= stored read as "stored - bias >= this"
    double selfReach = 0.0; // how far the surface itself can lie behind a texel it rasterized (slope x distance)
    double shadow = 0.0;    // S, as the GPU wrote it
    bool acne = false;      // shadowed (some taps) only by texels of the surface itself: no caster in front
    bool peterPanning = false;  // lit at the lookup texel although a caster lies in front by less than the bias
};

struct DepthProfile {
    bool ok = false;
    std::string error;
    glm::ivec2 from{0}, to{0};
    std::vector<ProfileSample> samples;  // one per pixel along the line (Bresenham-like, both ends included)
    int surfaces = 0, acne = 0, peterPanning = 0;
};

// The pixels of the line from `from` to `to` (both inside the captured view), one per step of its longer axis.
std::vector<glm::ivec2> profilePixels(glm::ivec2 from, glm::ivec2 to);

// The profile of the frame `probe` captured; `from`/`to` outside the view give !ok with a message.
// `lightView`: look every sample up in that one of probe.views() (default: the view holding each point).
DepthProfile depthProfile(const PixelProbe& probe, glm::ivec2 from, glm::ivec2 to,
                          std::optional<std::size_t> lightView = std::nullopt);

}  // namespace shadowlab
