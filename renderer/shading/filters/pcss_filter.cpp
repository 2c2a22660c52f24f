// PCSS (Fernando 2005): a blocker search, a penumbra estimate from the light's size (lights.#.size), then a PCF of
// its disk (pcssDisk) rotated per pixel whose radius follows the penumbra. GLSL: shaders/shadow/techniques/pcss.glsl,
// the whole lookup; this is its CPU mirror for the pixel probe, step for step in float as the GPU computes.
#include "shading/filters/filter_technique.h"

#include "shading/filters/cube_face_frame.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>

namespace shadowlab {

namespace {

// PCSS's disk: 16 taps spread uniformly over the unit disc's area (Vogel's spiral: radius sqrt((i + 0.5) / 16), the
// golden angle apart). A disc light's visibility across a straight edge is the share of the disc beyond it, so taps
// that sample the disc by area give that profile: its 10..90 % width is 1.37 radii, the disc's 1.38. The `poisson`
// filter's disk spans the square [-1, 1]² (taps up to 1.23 from the centre): averaged over the per-pixel rotations
// its 10..90 % width is 1.83 radii, the 1.33x wider penumbra PCSS measured with it.
const std::vector<glm::vec2>& pcssDisk() {
    static const std::vector<glm::vec2> disk = [] {
        constexpr int kTaps = 16;
        const double goldenAngle = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
        std::vector<glm::vec2> taps;
        for (int i = 0; i < kTaps; ++i) {
            const double r = std::sqrt((i + 0.5) / kTaps), a = i * goldenAngle;
            taps.emplace_back(float(r * std::cos(a)), float(r * std::sin(a)));
        }
        return taps;
    }();
    return disk;
}

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

// One blocker-search read: the stored depth the GPU's nearest tap reads and whether it blocks; `uncertain` when float
// rounding may change the decision (the depths within depthEps, or the tap within texelEps of a texel edge whose
// neighbour decides otherwise).
struct SearchRead {
    float stored = 0.0f;
    bool blocks = false;
    bool uncertain = false;
    bool neighbour = false;  // uncertain because a neighbouring texel may be read (else only the depth test flips)
};

bool blocksAt(const OwnLookupInput& in, float stored, float receiver) {
    return in.reversedZ ? stored > receiver : stored < receiver;
}

// A 2D view: the tap's texel, the receiver's plane at its centre.
SearchRead read2D(const OwnLookupInput& in, glm::vec2 offsetTexels) {
    const float resolution = float(in.resolution);
    const float texel = 1.0f / resolution;
    const glm::vec2 lo(0.5f * texel), hi(1.0f - 0.5f * texel);
    const glm::vec2 tap = glm::clamp(in.tex + offsetTexels * texel, lo, hi);
    const glm::vec2 cell(std::floor(tap.x * resolution), std::floor(tap.y * resolution));
    SearchRead out;
    bool near = false;  // the last read's depths within rounding
    const auto readAt = [&](glm::vec2 at, float& stored) {
        stored = in.storedDepth(-1, int(at.x), int(at.y));
        const float receiver = in.receiver + glm::dot(in.plane, at + 0.5f - in.tex * resolution);
        near = std::abs(double(stored) - double(receiver)) <= in.depthEps;
        return blocksAt(in, stored, receiver);
    };
    out.blocks = readAt(cell, out.stored);
    out.uncertain = near;
    const glm::vec2 frac = tap * resolution - cell;
    for (int axis = 0; axis < 2; ++axis)
        for (const float step : {-1.0f, 1.0f}) {
            if ((step < 0.0f ? frac[axis] : 1.0f - frac[axis]) > float(in.texelEps)) continue;
            glm::vec2 other = cell;
            other[axis] += step;
            float otherStored = 0.0f;
            if (other[axis] >= 0.0f && other[axis] < resolution && (readAt(other, otherStored) != out.blocks || near))
                out.uncertain = out.neighbour = true;
        }
    return out;
}

// A cube face (pcss.glsl's shadowCube): the tap's direction selects a face, its nearest texel there, compared with the
// receiver's depth in that face. Near a texel's edge the neighbour (across a face's edge: the next face's) may be read.
SearchRead readCube(const OwnLookupInput& in, const CubeFaceFrame& frame, glm::vec2 offsetTexels) {
    const glm::vec3 d = cubeFaceTap(frame, offsetTexels);
    const CubeCoordinate c = cubeCoordinate(glm::dvec3(d));
    const int res = in.resolution;
    const glm::dvec2 coord = c.st * double(res);
    const int x = std::clamp(int(std::floor(coord.x)), 0, res - 1), y = std::clamp(int(std::floor(coord.y)), 0, res - 1);
    SearchRead out;
    const float receiver = faceDepth(in.fromLight, d, in.nearPlane, in.farPlane, in.reversedZ);
    out.stored = in.storedDepth(c.face, x, y);
    out.blocks = blocksAt(in, out.stored, receiver);
    out.uncertain = std::abs(double(out.stored) - double(receiver)) <= in.depthEps;
    for (int axis = 0; axis < 2; ++axis)
        for (const int step : {-1, 1}) {
            const double frac = coord[axis] - std::floor(coord[axis]);
            if ((step < 0 ? frac : 1.0 - frac) > in.texelEps) continue;
            const std::optional<CubeTexel> other =
                seamlessTexel(c.face, axis == 0 ? x + step : x, axis == 1 ? y + step : y, res);
            if (!other) continue;
            glm::vec3 axisOfFace(0.0f);
            axisOfFace[other->face / 2] = other->face % 2 == 0 ? 1.0f : -1.0f;
            const float otherReceiver = other->face == c.face
                                            ? receiver
                                            : faceDepth(in.fromLight, axisOfFace, in.nearPlane, in.farPlane, in.reversedZ);
            const float stored = in.storedDepth(other->face, other->x, other->y);
            if (blocksAt(in, stored, otherReceiver) != out.blocks ||
                std::abs(double(stored) - double(otherReceiver)) <= in.depthEps)
                out.uncertain = out.neighbour = true;
        }
    return out;
}

OwnLookupResult mirror(const OwnLookupInput& in, const FilterSettings& filter) {
    OwnLookupResult out;
    const glm::vec2 rotation = rotationOf(in.pixel);
    const std::vector<glm::vec2>& disk = pcssDisk();
    const CubeFaceFrame frame = cubeFaceFrame(in.fromLight, 1.0f / float(in.resolution));

    // 1. Blockers, over the region where the light's cone from the receiver crosses the map.
    const float nearDepth = in.reversedZ ? 1.0f : 0.0f;
    out.searchTexels = std::clamp(0.5f * spread(in, nearDepth), 1.0f, filter.blockerSearchTexels);
    std::vector<SearchRead> reads;
    for (const glm::vec2& unit : disk) {
        const glm::vec2 offset = rotateTap(unit, rotation) * out.searchTexels;
        reads.push_back(in.cube ? readCube(in, frame, offset) : read2D(in, offset));
        out.uncertain = out.uncertain || reads.back().uncertain;
    }
    out.searchTaps = int(reads.size());

    // 2. The penumbra from the blockers' mean depth (in the GPU's order); the filter's radius is half of it.
    // 3. The rotated disk of that radius: the probe compares these taps as every filter's (bilinear).
    const auto filterOf = [&](std::uint32_t flipped, OwnLookupResult& o) {
        float blockerSum = 0.0f;
        for (std::size_t k = 0; k < reads.size(); ++k)
            if (reads[k].blocks != (((flipped >> k) & 1u) != 0u)) {
                blockerSum += reads[k].stored;
                ++o.blockers;
            }
        if (o.blockers == 0) return;
        o.blockerDepth = blockerSum / float(o.blockers);
        o.penumbraTexels = spread(in, o.blockerDepth);
        o.radiusTexels = std::clamp(0.5f * o.penumbraTexels, 1.0f, filter.penumbraMaxTexels);
        for (const glm::vec2& unit : disk) {
            o.taps.push_back(rotateTap(unit, rotation) * o.radiusTexels);
            if (in.cube) o.directions.push_back(cubeFaceTap(frame, o.taps.back()));
        }
    };
    filterOf(0u, out);

    // A search test within rounding: the outcomes the GPU may reach instead, when only depth tests are in doubt (each
    // either way) and few enough to list.
    std::vector<std::size_t> doubtful;
    bool listable = true;
    for (std::size_t k = 0; k < reads.size(); ++k)
        if (reads[k].uncertain) {
            listable = listable && !reads[k].neighbour;
            doubtful.push_back(k);
        }
    constexpr std::size_t kMaxDoubtful = 4;
    out.alternativesComplete = out.uncertain && listable && doubtful.size() <= kMaxDoubtful;
    if (out.alternativesComplete)
        for (std::uint32_t subset = 1; subset < (1u << doubtful.size()); ++subset) {
            std::uint32_t flipped = 0u;
            for (std::size_t j = 0; j < doubtful.size(); ++j)
                if ((subset >> j) & 1u) flipped |= 1u << doubtful[j];
            OwnLookupResult alternative;
            alternative.searchTexels = out.searchTexels;
            alternative.searchTaps = out.searchTaps;
            filterOf(flipped, alternative);
            out.alternatives.push_back(std::move(alternative));
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
                          [](const FilterSettings&) { return pcssDisk(); },
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
                          int(pcssDisk().size()), double(filter.blockerSearchTexels), int(pcssDisk().size()),
                          double(filter.penumbraMaxTexels));
            return std::string(text);
        };
        return t;
    }();
    return technique;
}

}  // namespace shadowlab
