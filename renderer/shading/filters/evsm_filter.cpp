// EVSM2 and EVSM4: VSM over exponentially warped depth, exp(c+ d) (and -exp(-c- d) for EVSM4), d = 2z - 1. The
// exponents are clamped to what the storage holds (maxWarpExponent: the second moment exp(2c) must stay finite).
// GLSL: shaders/shadow/techniques/evsm2.glsl, evsm4.glsl (warp: evsm_warp.glsl); this is their CPU mirror.
#include "shading/filters/moment_filter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace shadowlab {

namespace {

glm::vec2 warpDepth(float z, const glm::vec4& u) {
    const float d = 2.0f * z - 1.0f;
    return {std::exp(u.x * d), -std::exp(-u.y * d)};
}

float warpedBound(float mean, float meanSquare, float warped, float exponent, const glm::vec4& u) {
    const float slope = 2.0f * exponent * warped;
    return chebyshevUpperBound(mean, meanSquare, warped, u.z * slope * slope);
}

std::string clampMessage(const char* key, float asked, int bits) {
    char text[256];
    std::snprintf(text, sizeof text,
                  "%s %g is above what %d-bit moments hold (the warped second moment exp(2c) overflows %s above c = "
                  "%.3g); %.3g is used",
                  key, double(asked), bits, bits == 16 ? "fp16's 65504" : "fp32's 3.4e38",
                  bits == 16 ? 5.54 : 44.3, double(maxWarpExponent(bits)));
    return text;
}

glm::vec4 evsmUniforms(const FilterSettings& f) {
    const float limit = maxWarpExponent(f.momentBits);
    return {std::min(f.positiveExponent, limit), std::min(f.negativeExponent, limit), f.minVariance, f.bleedReduction};
}

std::vector<std::string> evsmClamps(const FilterSettings& f, bool negative) {
    std::vector<std::string> out;
    const float limit = maxWarpExponent(f.momentBits);
    if (f.positiveExponent > limit) out.push_back(clampMessage("filter.positiveExponent", f.positiveExponent, f.momentBits));
    if (negative && f.negativeExponent > limit)
        out.push_back(clampMessage("filter.negativeExponent", f.negativeExponent, f.momentBits));
    return out;
}

std::string explain(const glm::vec4& m, float z, const glm::vec4& u, bool negative) {
    const glm::vec2 w = warpDepth(z, u);
    const float pos = warpedBound(m.x, m.y, w.x, u.x, u);
    char text[320];
    int n = std::snprintf(text, sizeof text, "EVSM: c+ %.3g: warped mean %.6g, variance %.6g, receiver %.6g: bound %.4f",
                          double(u.x), double(m.x), double(m.y - m.x * m.x), double(w.x), double(pos));
    float bound = pos;
    if (negative) {
        const float neg = warpedBound(m.z, m.w, w.y, u.y, u);
        n += std::snprintf(text + n, sizeof text - std::size_t(n), "; c- %.3g: mean %.6g, receiver %.6g: bound %.4f",
                           double(u.y), double(m.z), double(w.y), double(neg));
        bound = std::min(pos, neg);
    }
    std::snprintf(text + n, sizeof text - std::size_t(n), "; after bleeding reduction %.2f: %.4f", double(u.w),
                  double(reduceBleeding(bound, u.w)));
    return text;
}

const MomentTechnique kEvsm2{
    2, false, "shadow/techniques/evsm2.glsl", evsmUniforms,
    [](float z, const glm::vec4& u) {
        const float p = warpDepth(z, u).x;
        return glm::vec4(p, p * p, 0.0f, 0.0f);
    },
    [](const glm::vec4& m, float z, const glm::vec4& u) {
        return reduceBleeding(warpedBound(m.x, m.y, warpDepth(z, u).x, u.x, u), u.w);
    },
    [](const glm::vec4& m, float z, const glm::vec4& u) { return explain(m, z, u, false); },
    [](const FilterSettings& f) { return evsmClamps(f, false); }};

const MomentTechnique kEvsm4{
    4, false, "shadow/techniques/evsm4.glsl", evsmUniforms,
    [](float z, const glm::vec4& u) {
        const glm::vec2 w = warpDepth(z, u);
        return glm::vec4(w.x, w.x * w.x, w.y, w.y * w.y);
    },
    [](const glm::vec4& m, float z, const glm::vec4& u) {
        const glm::vec2 w = warpDepth(z, u);
        return reduceBleeding(std::min(warpedBound(m.x, m.y, w.x, u.x, u), warpedBound(m.z, m.w, w.y, u.y, u)), u.w);
    },
    [](const glm::vec4& m, float z, const glm::vec4& u) { return explain(m, z, u, true); },
    [](const FilterSettings& f) { return evsmClamps(f, true); }};

}  // namespace

const FilterTechnique& evsm2Filter() {
    static const FilterTechnique technique = momentsFilter(
        FilterKind::Evsm2, "evsm2", {"filter.positiveExponent", "filter.minVariance", "filter.bleedReduction"}, kEvsm2);
    return technique;
}

const FilterTechnique& evsm4Filter() {
    static const FilterTechnique technique =
        momentsFilter(FilterKind::Evsm4, "evsm4",
                      {"filter.positiveExponent", "filter.negativeExponent", "filter.minVariance",
                       "filter.bleedReduction"},
                      kEvsm4);
    return technique;
}

}  // namespace shadowlab
