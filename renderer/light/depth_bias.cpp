#include "light/depth_bias.h"

#include <glm/ext/matrix_transform.hpp>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace shadowlab {

double depthStepAt(DepthFormat format, double depth) {
    switch (format) {
        case DepthFormat::D16: return 1.0 / 65535.0;
        case DepthFormat::D24: return 1.0 / 16777215.0;
        case DepthFormat::D32F: {
            // r = 2^(e - 23), e the exponent of the float depth: depth in [2^e, 2^(e+1)). A depth of 0 has no
            // exponent; the smallest normal float's stands in for it.
            const float stored = std::clamp(static_cast<float>(depth), std::numeric_limits<float>::min(), 1.0f);
            int exponent = 0;
            std::frexp(stored, &exponent);  // stored = mantissa * 2^exponent, mantissa in [0.5, 1)
            return std::ldexp(1.0, exponent - 1 - 23);
        }
    }
    return 0.0;
}

double clipDepthStepAt(double depth, bool reversedZ) {
    if (reversedZ) {  // zero-to-one clip depth is the window depth itself: a float's step there
        const float d = static_cast<float>(std::clamp(depth, 0.0, 1.0));
        return double(std::nextafter(d, 2.0f) - d);
    }
    const float ndc = std::abs(static_cast<float>(2.0 * std::clamp(depth, 0.0, 1.0) - 1.0));
    return 0.5 * double(std::nextafter(ndc, 2.0f) - ndc);
}

namespace {

// View distance from the light at window depth d (spot: perspective depth; directional: linear), either convention.
double viewDistanceAt(const LightSpace& light, double stored) {
    const double d = light.normalDepth(stored);
    const double n = light.nearPlane, f = light.farPlane;
    if (!light.perspective) return n + d * (f - n);
    return f * n / std::max(f - d * (f - n), 1e-300);
}

// Area-weighted median of (value, weight) pairs: the smallest value whose cumulative weight in value order reaches
// half the total; the plain median when every weight is 0. A weighted quickselect (each round partitions around
// the middle with nth_element and keeps the half that holds the answer): linear time, where sorting every receiver
// triangle of a large scene cost the first frame several milliseconds.
double weightedMedian(std::vector<std::pair<double, double>>& samples) {
    if (samples.empty()) return 0.0;
    double total = 0.0;
    for (const auto& s : samples) total += s.second;
    auto first = samples.begin(), last = samples.end();
    if (!(total > 0.0)) {
        const auto middle = first + std::ptrdiff_t(samples.size() / 2);
        std::nth_element(first, middle, last);
        return middle->first;
    }
    double needed = 0.5 * total;
    while (last - first > 1) {
        const auto middle = first + (last - first) / 2;
        std::nth_element(first, middle, last);
        double below = 0.0;  // the weight of the values before the middle one (none larger than it)
        for (auto it = first; it != middle; ++it) below += it->second;
        if (below >= needed) {
            last = middle;
            continue;
        }
        needed -= below;
        if (middle->second >= needed) return middle->first;
        needed -= middle->second;
        first = middle + 1;
    }
    return first != last ? first->first : std::prev(first)->first;  // rounding left the middle just examined
}

}  // namespace

double polygonOffsetDepth(const ShadowMapSettings& shadow, DepthFormat format, double maxDepth, double slope) {
    double o = double(shadow.slopeScaledDepthBias) * slope + double(shadow.depthBias) * depthStepAt(format, maxDepth);
    if (shadow.depthBiasClamp > 0.0f) o = std::min(o, double(shadow.depthBiasClamp));
    return o;
}

std::optional<glm::dvec2> windowDepthGradient(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 e1 = b - a, e2 = c - a;
    const double det = e1.x * e2.y - e2.x * e1.y;
    if (!(std::abs(det) > 0.0) || !std::isfinite(det)) return std::nullopt;
    return glm::dvec2((e1.z * e2.y - e2.z * e1.y) / det, (e2.z * e1.x - e1.z * e2.x) / det);
}

double windowDepthSlope(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const std::optional<glm::dvec2> g = windowDepthGradient(a, b, c);
    return g ? std::max(std::abs(g->x), std::abs(g->y)) : -1.0;
}

BiasTerm biasTerm(const LightSpace& light, double depth, double atDepth) {
    BiasTerm t;
    t.depth = depth;
    const double n = light.nearPlane, f = light.farPlane;
    if (!light.perspective) {
        t.world = depth * (f - n);
    } else {
        // d(z) = f (z - n) / (z (f - n)): dz = dd z^2 (f - n) / (f n) at the receiver's distance z.
        const double z = viewDistanceAt(light, atDepth);
        t.world = depth * z * z * (f - n) / (f * n);
    }
    const double texel = light.texelSizeAt(viewDistanceAt(light, atDepth));
    t.texels = texel > 0.0 ? t.world / texel : 0.0;
    return t;
}

ReceiverDepths receiverDepths(const Scene& scene, const LightSpace& light, const glm::dvec3& origin) {
    const glm::dmat4 toClip = light.viewProjection() * glm::translate(glm::dmat4(1.0), -origin);
    const double res = double(light.resolution);
    std::vector<std::pair<double, double>> depths, slopes;  // (value, texel area)
    ReceiverDepths r;
    r.minDepth = 1.0;
    r.maxDepth = 0.0;
    for (const Instance& inst : scene.instances) {
        const Mesh& mesh = scene.meshes[std::size_t(inst.mesh)];
        const glm::dmat4 m = toClip * glm::dmat4(inst.transform);
        std::vector<glm::dvec4> window(mesh.positions.size());  // x, y in texels, z window depth, w clip w
        for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
            const glm::dvec4 c = m * glm::dvec4(glm::dvec3(mesh.positions[i]), 1.0);
            const glm::dvec3 t = light.textureOf(c);
            window[i] = {t.x * res, t.y * res, t.z, c.w};
        }
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            const glm::dvec4& a = window[mesh.indices[t]];
            const glm::dvec4& b = window[mesh.indices[t + 1]];
            const glm::dvec4& c = window[mesh.indices[t + 2]];
            if (!(a.w > 0.0 && b.w > 0.0 && c.w > 0.0)) continue;  // behind a spot light
            if (std::max({a.x, b.x, c.x}) < 0.0 || std::min({a.x, b.x, c.x}) > res ||
                std::max({a.y, b.y, c.y}) < 0.0 || std::min({a.y, b.y, c.y}) > res)
                continue;  // outside the map
            const glm::dvec3 e1(b - a), e2(c - a);
            const double det = e1.x * e2.y - e2.x * e1.y;  // twice the area in texels
            // The triangle's farthest vertex from the light in either convention (reversed-Z: the smallest stored
            // depth), so both report the same receivers.
            const double depth = std::clamp(light.reversedZ ? std::min({a.z, b.z, c.z}) : std::max({a.z, b.z, c.z}),
                                            0.0, 1.0);
            if (!std::isfinite(det) || !std::isfinite(depth)) continue;
            const double area = 0.5 * std::abs(det);
            r.valid = true;
            r.minDepth = std::min(r.minDepth, depth);
            r.maxDepth = std::max(r.maxDepth, depth);
            depths.emplace_back(depth, area);
            if (area > 0.0)  // edge-on triangles have no finite slope and cover no texel
                slopes.emplace_back(windowDepthSlope(glm::dvec3(a), glm::dvec3(b), glm::dvec3(c)), area);
        }
    }
    if (!r.valid) return ReceiverDepths{};
    r.medianDepth = weightedMedian(depths);
    r.medianSlope = weightedMedian(slopes);
    return r;
}

BiasReport biasReport(const ShadowMapSettings& shadow, DepthFormat format, const LightSpace& light,
                      const ReceiverDepths& receivers) {
    BiasReport b;
    b.valid = receivers.valid;
    b.shadow = shadow;
    b.format = format;
    // Without receivers (an empty view) the light's far end stands in: the old [0.5, 1) assumption, said as such.
    // Reversed-Z stores the nearest receivers at the largest depth.
    const double lowest = receivers.valid ? receivers.minDepth : light.farDepth();
    const double highest = receivers.valid ? receivers.maxDepth : light.farDepth();
    const double nearDepth = light.reversedZ ? highest : lowest;
    const double farDepth = light.reversedZ ? lowest : highest;
    const double median = receivers.valid ? receivers.medianDepth : light.farDepth();
    b.receiverDepthMin = nearDepth;
    b.receiverDepthMax = farDepth;
    b.receiverDepthMedian = median;
    b.stepNear = depthStepAt(format, nearDepth);
    b.stepFar = depthStepAt(format, farDepth);
    b.constantNear = biasTerm(light, double(shadow.depthBias) * b.stepNear, nearDepth);
    b.constantFar = biasTerm(light, double(shadow.depthBias) * b.stepFar, farDepth);
    b.medianSlope = receivers.medianSlope;
    b.slope = biasTerm(light, double(shadow.slopeScaledDepthBias) * receivers.medianSlope, median);
    b.clamp = biasTerm(light, double(shadow.depthBiasClamp), median);
    const double total = polygonOffsetDepth(shadow, format, median, receivers.medianSlope);
    b.total = biasTerm(light, total, median);
    const bool nearCoarser = clipDepthStepAt(nearDepth, light.reversedZ) >= clipDepthStepAt(farDepth, light.reversedZ);
    const double coarsest = nearCoarser ? nearDepth : farDepth;
    b.clipPrecision = biasTerm(light, clipDepthStepAt(coarsest, light.reversedZ), coarsest);
    b.texelWorldSize = light.texelSizeAt(viewDistanceAt(light, median));
    b.normalOffsetWorld = double(shadow.normalOffset) * b.texelWorldSize;
    return b;
}

namespace {

std::string format(const char* pattern, auto... values) {
    char buf[256];
    std::snprintf(buf, sizeof buf, pattern, values...);
    return buf;
}

std::string units(const BiasTerm& t) {
    return format("%.3g depth = %.3g world units = %.3g texels", t.depth, t.world, t.texels);
}

// "2^-40" for a power of two, else the number.
std::string step(double r) {
    int exponent = 0;
    const double mantissa = std::frexp(r, &exponent);
    return mantissa == 0.5 ? format("2^%d", exponent - 1) : format("%.3g", r);
}

}  // namespace

std::vector<std::string> describeBias(const BiasReport& b) {
    const ShadowMapSettings& shadow = b.shadow;
    std::vector<std::string> lines;
    const std::string where = b.valid ? "" : " (no receiver in the light's volume: taken at the far depth)";
    // Two lines when the nearest and farthest receivers get different amounts (D32F's exponent, a spot's depth).
    const bool varies = b.stepNear != b.stepFar ||
                        std::abs(b.constantNear.world - b.constantFar.world) > 0.01 * std::abs(b.constantFar.world);
    if (varies) {
        lines.push_back(format("DepthBias %g x r%s%s:", double(shadow.depthBias),
                               b.format == DepthFormat::D32F ? " (D32F: r follows the depth's exponent)" : "",
                               where.c_str()));
        lines.push_back(format("  nearest receivers (depth %.3g, r = %s): ", b.receiverDepthMin,
                               step(b.stepNear).c_str()) + units(b.constantNear));
        lines.push_back(format("  farthest receivers (depth %.3g, r = %s): ", b.receiverDepthMax,
                               step(b.stepFar).c_str()) + units(b.constantFar));
    } else {
        lines.push_back(format("DepthBias %g x r (r = %s at receiver depths %.3g..%.3g)%s: ", double(shadow.depthBias),
                               step(b.stepNear).c_str(), b.receiverDepthMin, b.receiverDepthMax, where.c_str()) +
                        units(b.constantNear));
    }
    lines.push_back(format("SlopeScaledDepthBias %g x median depth slope %.3g per texel: ",
                           double(shadow.slopeScaledDepthBias), b.medianSlope) + units(b.slope));
    lines.push_back(shadow.depthBiasClamp > 0.0f
                        ? format("DepthBiasClamp %g: ", double(shadow.depthBiasClamp)) + units(b.clamp)
                        : std::string("DepthBiasClamp: none"));
    lines.push_back("depth precision of the float clip space at the receivers: " + units(b.clipPrecision) +
                    (b.total.depth < b.clipPrecision.depth ? " (more than the total bias: expect acne)" : ""));
    lines.push_back(format("total at the median receiver (depth %.3g): ", b.receiverDepthMedian) + units(b.total) +
                    format("; normal offset %.3g world units (texel %.3g world units)", b.normalOffsetWorld,
                           b.texelWorldSize));
    return lines;
}

double depthBiasUnitTexels(const LightSpace& light, DepthFormat format, const ReceiverDepths& receivers) {
    const double median = receivers.valid ? receivers.medianDepth : light.farDepth();
    return biasTerm(light, depthStepAt(format, median), median).texels;
}

}  // namespace shadowlab
