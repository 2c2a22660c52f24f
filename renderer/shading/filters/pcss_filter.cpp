// PCSS (Fernando 2005): a blocker search, a penumbra estimate from the light's size (lights.#.size), then a PCF of
// the Poisson disk rotated per pixel whose radius follows the penumbra. GLSL: shaders/shadow/techniques/pcss.glsl,
// the whole lookup; this is its CPU mirror for the pixel probe, step for step in float as the GPU computes.
#include "shading/filters/filter_technique.h"

#include "shading/filter_taps.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

namespace shadowlab {

namespace {

// pcss.glsl's pcssRotation: the pixel's hash, a point of the unit circle by its rational parametrization.
glm::vec2 rotationOf(glm::uvec2 p) {
    std::uint32_t h = p.x * 1664525u + p.y * 1013904223u;
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    const float t = float(h & 0xffffu) / 32767.5f - 1.0f;
    const float d = 1.0f + t * t;
    const glm::vec2 r((1.0f - t * t) / d, 2.0f * t / d);
    return (h & 0x10000u) != 0u ? -r : r;
}

glm::vec2 rotateTap(glm::vec2 o, glm::vec2 r) { return {r.x * o.x - r.y * o.y, r.y * o.x + r.x * o.y}; }

// pcss.glsl's pcssDistance: distance along a perspective view's axis of window depth z.
float distanceOf(const OwnLookupInput& in, float z) {
    const float n = in.nearPlane, f = in.farPlane;
    if (in.reversedZ) return n * f / (n + z * (f - n));
    return 2.0f * f * n / ((f + n) - (2.0f * z - 1.0f) * (f - n));
}

// pcss.glsl's pcssSpread: the light's width, in texels at the receiver, over the gap from a blocker at zB.
float spread(const OwnLookupInput& in, float zB) {
    if (in.perspective) {
        const float dR = in.distance > 0.0f ? in.distance : distanceOf(in, in.receiver);
        const float dB = distanceOf(in, zB);
        return in.lightSize * std::max(dR - dB, 0.0f) / dB / (in.texelWorld * dR);
    }
    return in.lightSize * std::max((in.receiver - zB) / in.depthPerWorld, 0.0f) / in.texelWorld;
}

OwnLookupResult mirror(const OwnLookupInput& in, const FilterSettings& filter) {
    OwnLookupResult out;
    const float texel = 1.0f / float(in.resolution);
    const float resolution = float(in.resolution);
    const glm::vec2 lo(0.5f * texel), hi(1.0f - 0.5f * texel);
    const glm::vec2 rotation = rotationOf(in.pixel);
    const auto& disk = poissonDisk();

    // 1. Blockers, over the region where the light's cone from the receiver crosses the map.
    const float nearDepth = in.reversedZ ? 1.0f : 0.0f;
    out.searchTexels = std::clamp(0.5f * spread(in, nearDepth), 1.0f, filter.blockerSearchTexels);
    float blockerSum = 0.0f;
    for (const glm::vec2& unit : disk) {
        const glm::vec2 tap = glm::clamp(in.tex + rotateTap(unit, rotation) * out.searchTexels * texel, lo, hi);
        const glm::vec2 cell(std::floor(tap.x * resolution), std::floor(tap.y * resolution));
        const auto blocksAt = [&](glm::vec2 at, float& stored) {
            stored = in.storedDepth(int(at.x), int(at.y));
            const float receiver = in.receiver + glm::dot(in.plane, at + 0.5f - in.tex * resolution);
            out.uncertain = out.uncertain || std::abs(double(stored) - double(receiver)) <= in.depthEps;
            return in.reversedZ ? stored > receiver : stored < receiver;
        };
        float stored = 0.0f;
        const bool blocks = blocksAt(cell, stored);
        // The GPU's coordinate differs by rounding: a tap on a texel's edge may read the neighbour, which matters
        // only where that one decides otherwise (a caster's silhouette).
        const glm::vec2 frac = tap * resolution - cell;
        for (int axis = 0; axis < 2; ++axis)
            for (const float step : {-1.0f, 1.0f}) {
                if ((step < 0.0f ? frac[axis] : 1.0f - frac[axis]) > float(in.texelEps)) continue;
                glm::vec2 other = cell;
                other[axis] += step;
                float otherStored = 0.0f;
                if (other[axis] >= 0.0f && other[axis] < resolution && blocksAt(other, otherStored) != blocks)
                    out.uncertain = true;
            }
        ++out.searchTaps;
        if (blocks) {
            blockerSum += stored;
            ++out.blockers;
        }
    }
    char text[320];
    if (out.blockers == 0) {
        std::snprintf(text, sizeof text,
                      "PCSS: blocker search radius %.3g texels (light size %.4g): 0 of %d taps nearer than the "
                      "receiver %.6g: lit, no filter",
                      double(out.searchTexels), double(in.lightSize), out.searchTaps, double(in.receiver));
        out.text = text;
        return out;
    }

    // 2. The penumbra from the blockers' mean depth; the filter's radius is half of it.
    out.blockerDepth = blockerSum / float(out.blockers);
    out.penumbraTexels = spread(in, out.blockerDepth);
    out.radiusTexels = std::clamp(0.5f * out.penumbraTexels, 1.0f, filter.penumbraMaxTexels);

    // 3. The rotated disk of that radius: the probe compares these taps as every filter's (bilinear).
    for (const glm::vec2& unit : disk) out.taps.push_back(rotateTap(unit, rotation) * out.radiusTexels);
    std::snprintf(text, sizeof text,
                  "PCSS: blocker search radius %.3g texels (light size %.4g): %d of %d taps nearer than the receiver "
                  "%.6g, mean blocker depth %.6g; penumbra %.3g texels -> filter radius %.3g texels (%g at most), "
                  "%zu taps rotated by (%.4f, %.4f)",
                  double(out.searchTexels), double(in.lightSize), out.blockers, out.searchTaps, double(in.receiver),
                  double(out.blockerDepth), double(out.penumbraTexels), double(out.radiusTexels),
                  double(filter.penumbraMaxTexels), out.taps.size(), double(rotation.x), double(rotation.y));
    out.text = text;
    return out;
}

const OwnLookup kPcss{
    "shadow/techniques/pcss.glsl",
    [](const FilterSettings& f) { return glm::vec4(f.blockerSearchTexels, f.penumbraMaxTexels, 0.0f, 0.0f); },
    mirror};

}  // namespace

const FilterTechnique& pcssFilter() {
    static const FilterTechnique technique = [] {
        FilterTechnique t{FilterKind::Pcss, "pcss", /*bilinear=*/true,
                          [](const FilterSettings&) {
                              return std::vector<glm::vec2>(poissonDisk().begin(), poissonDisk().end());
                          },
                          [](const FilterSettings&) { return 1.0f; },
                          // The widest of the search and the filter, and the bilinear tap's next texel.
                          [](const FilterSettings& filter) {
                              return double(std::max(filter.blockerSearchTexels, filter.penumbraMaxTexels)) + 1.0;
                          }};
        t.receiverPlane = true;
        t.keys = {"filter.blockerSearchTexels", "filter.penumbraMaxTexels"};
        // Its trade-off for `tune`: a wider search finds blockers of wider penumbrae (and costs nothing more: 16 reads
        // at any radius, sparser); a larger cap lets the penumbra grow as the light's size asks, at the price of
        // noisier, blurrier shadows. The light's size itself is not searched: it also moves the soft reference.
        t.tradeOff = {{"filter.blockerSearchTexels", 2.0, 64.0, 6, /*geometric=*/true},
                      {"filter.penumbraMaxTexels", 2.0, 64.0, 6, /*geometric=*/true}};
        t.ownLookup = &kPcss;
        t.cost = [](const FilterSettings& filter) {
            char text[200];
            std::snprintf(text, sizeof text,
                          "PCSS in the main pass: %d depth reads (blocker search, radius <= %g texels) + %d bilinear "
                          "comparisons (radius <= %g texels) per lookup; no comparisons where no blocker is found",
                          kPoissonTaps, double(filter.blockerSearchTexels), kPoissonTaps,
                          double(filter.penumbraMaxTexels));
            return std::string(text);
        };
        return t;
    }();
    return technique;
}

}  // namespace shadowlab
