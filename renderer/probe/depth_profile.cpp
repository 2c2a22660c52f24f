#include "probe/depth_profile.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace shadowlab {

std::vector<glm::ivec2> profilePixels(glm::ivec2 from, glm::ivec2 to) {
    const glm::ivec2 d = to - from;
    const int steps = std::max(std::abs(d.x), std::abs(d.y));
    std::vector<glm::ivec2> pixels;
    pixels.reserve(std::size_t(steps) + 1);
    for (int i = 0; i <= steps; ++i) {
        const double t = steps == 0 ? 0.0 : double(i) / steps;
        pixels.emplace_back(int(std::lround(from.x + d.x * t)), int(std::lround(from.y + d.y * t)));
    }
    return pixels;
}

namespace {

// Fills the sample's numbers from the probe's report at its pixel. Depths are in the normal convention (0 near, 1 far)
// whatever the map's: a reversed-Z map's stored d reads as 1 - d (exact in double), so the profile draws alike.
void classify(const PixelProbeReport& r, ProfileSample& s) {
    const auto normal = [&](double d) { return r.reversedZ ? 1.0 - d : d; };
    s.surface = true;
    s.receiver = normal(r.receiverDepth);
    s.bias = r.bias.total.depth;
    s.threshold = s.receiver - s.bias;
    s.shadow = r.shadowGpu;
    // The stored depth at the texel the lookup falls in: the tap texel that is that texel (every filter's centre
    // tap reads it, nearest or bilinear); a filter without one leaves the first tap's first texel.
    s.stored = r.taps.empty() || r.taps[0].texels.empty() ? 0.0 : normal(r.taps[0].texels[0].stored);
    for (const ProbeTap& tap : r.taps)
        for (const ProbeTexel& texel : tap.texels)
            if (!texel.border && texel.texel == r.texel) s.stored = normal(texel.stored);
    // Each tap texel that compares "shadowed" is the surface itself when the receiver lies behind the texel's
    // unbiased depth by no more than the surface's own slope can carry it over the distance from that texel's
    // centre (plus the GPU's rounding); further behind, something else is in front.
    bool selfShadowed = false, otherCaster = false;
    double reachAtLookup = 0.0;
    for (const ProbeTap& tap : r.taps)
        for (const ProbeTexel& texel : tap.texels) {
            const glm::dvec2 centre = glm::dvec2(texel.texel) + 0.5;
            const double distance = glm::length(r.texelCoord - centre) + 0.75;
            const double reach = r.bias.depthSlope * distance + r.depthUncertainty + r.bias.step;
            if (texel.texel == r.texel) reachAtLookup = reach;
            const double gap = s.receiver - (normal(texel.stored) - s.bias);  // > 0: receiver behind the caster
            if (!texel.lit && texel.weight > 0.0) (gap <= reach ? selfShadowed : otherCaster) = true;
        }
    s.selfReach = reachAtLookup;
    s.acne = selfShadowed && !otherCaster && r.inCone;
    const double gapAtLookup = s.receiver - (s.stored - s.bias);
    s.peterPanning = s.receiver <= s.stored && gapAtLookup > reachAtLookup && s.bias > 0.0;
}

}  // namespace

DepthProfile depthProfile(const PixelProbe& probe, glm::ivec2 from, glm::ivec2 to, std::optional<std::size_t> lightView) {
    DepthProfile p;
    p.from = from;
    p.to = to;
    if (!probe.captured()) {
        p.error = "no frame captured to profile";
        return p;
    }
    const SurfaceSamples& view = probe.samples();
    for (const auto& [name, point] : {std::pair{"from", from}, std::pair{"to", to}})
        if (point.x < 0 || point.y < 0 || point.x >= view.width || point.y >= view.height) {
            p.error = std::string("the line's ") + name + " point " + std::to_string(point.x) + "," +
                      std::to_string(point.y) + " is outside the " + std::to_string(view.width) + "x" +
                      std::to_string(view.height) + " view";
            return p;
        }
    const double length = glm::length(glm::dvec2(to - from));
    const std::vector<glm::ivec2> pixels = profilePixels(from, to);
    for (std::size_t i = 0; i < pixels.size(); ++i) {
        ProfileSample s;
        s.x = pixels[i].x;
        s.y = pixels[i].y;
        s.t = pixels.size() > 1 ? length * double(i) / double(pixels.size() - 1) : 0.0;
        const PixelProbeReport r = probe.at(s.x, s.y, nullptr, lightView);
        if (r.ok) {
            classify(r, s);
            ++p.surfaces;
            p.acne += s.acne;
            p.peterPanning += s.peterPanning;
        }
        p.samples.push_back(s);
    }
    p.ok = true;
    return p;
}

}  // namespace shadowlab
