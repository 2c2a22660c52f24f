// MSM, Hamburger 4 moments (Peters & Klein, I3D 2015) with a moment bias; at 16 bits the paper's optimized
// quantization into unorm storage. GLSL: shaders/shadow/techniques/msm.glsl; this is its CPU mirror (float).
#include "shading/filters/moment_filter.h"

#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace shadowlab {

namespace {

// The paper's transform and its inverse, as msm.glsl writes them (glm and GLSL fill columns alike).
const glm::mat4 kEncode(-2.07224649f, 13.7948857237f, 0.105877704f, 9.7924062118f,  //
                        32.23703778f, -59.4683975703f, -1.9077466311f, -33.7652110555f,
                        -68.571074599f, 82.0359750338f, 9.3496555107f, 47.9456096605f,
                        39.3703274134f, -35.364903257f, -6.6543490743f, -23.9728048165f);
const glm::mat4 kDecode(0.2227744146f, 0.1549679261f, 0.1451988946f, 0.163127443f,  //
                        0.0771972861f, 0.1394629426f, 0.2120202157f, 0.2591432266f,
                        0.7926986636f, 0.7963415838f, 0.7258694464f, 0.6539092497f,
                        0.0319417555f, -0.1722823173f, -0.2758014811f, -0.3376131734f);
constexpr float kOffset = 0.035955884801f;

glm::vec4 rawMoments(const glm::vec4& stored, const glm::vec4& u) {
    if (u.z == 0.0f) return stored;
    glm::vec4 q = stored;
    q.x -= kOffset;
    return kDecode * q;
}

// The shadowed share (before 1 - it and the bleeding reduction), as msm.glsl computes it.
float hamburger(const glm::vec4& stored, float z, const glm::vec4& u) {
    const glm::vec4 b = glm::mix(rawMoments(stored, u), glm::vec4(0.5f), u.x);
    const float l32d22 = -b.x * b.y + b.z;
    const float d22 = -b.x * b.x + b.y;
    const float squaredDepthVariance = -b.y * b.y + b.w;
    const float d33d22 = squaredDepthVariance * d22 - l32d22 * l32d22;
    const float invD22 = 1.0f / d22;
    const float l32 = l32d22 * invD22;
    glm::vec3 c(1.0f, z, z * z);
    c.y -= b.x;
    c.z -= b.y + l32 * c.y;
    c.y *= invD22;
    c.z *= d22 / d33d22;
    c.y -= l32 * c.z;
    c.x -= c.y * b.x + c.z * b.y;
    const float p = c.y / c.z, q = c.x / c.z;
    const float r = std::sqrt(std::max(p * p * 0.25f - q, 0.0f));
    const float z1 = -p * 0.5f - r, z2 = -p * 0.5f + r;
    const glm::vec4 sw = z2 < z ? glm::vec4(z1, z, 1.0f, 1.0f) : (z1 < z ? glm::vec4(z, z1, 0.0f, 1.0f) : glm::vec4(0.0f));
    const float quotient = (sw.x * z2 - b.x * (sw.x + z2) + b.y) / ((z2 - sw.y) * (z - z1));
    return std::clamp(sw.z + sw.w * quotient, 0.0f, 1.0f);
}

const MomentTechnique kMsm{
    4, /*unorm16=*/true, "shadow/techniques/msm.glsl",
    [](const FilterSettings& f) {
        return glm::vec4(f.momentBias, f.bleedReduction, f.momentBits == 16 ? 1.0f : 0.0f, 0.0f);
    },
    [](float z, const glm::vec4& u) {
        const float z2 = z * z;
        const glm::vec4 b(z, z2, z2 * z, z2 * z2);
        if (u.z == 0.0f) return b;
        glm::vec4 q = kEncode * b;
        q.x += kOffset;
        return q;
    },
    [](const glm::vec4& m, float z, const glm::vec4& u) { return reduceBleeding(1.0f - hamburger(m, z, u), u.y); },
    [](const glm::vec4& m, float z, const glm::vec4& u) {
        const glm::vec4 b = rawMoments(m, u);
        char text[256];
        std::snprintf(text, sizeof text,
                      "MSM: moments %.6g %.6g %.6g %.6g (bias %.3g), receiver %.6g: shadowed share %.4f, after "
                      "bleeding reduction %.2f: lit %.4f",
                      double(b.x), double(b.y), double(b.z), double(b.w), double(u.x), double(z),
                      double(hamburger(m, z, u)), double(u.y), double(reduceBleeding(1.0f - hamburger(m, z, u), u.y)));
        return std::string(text);
    }};

}  // namespace

const FilterTechnique& msmFilter() {
    static const FilterTechnique technique =
        momentsFilter(FilterKind::Msm, "msm", {"filter.momentBias", "filter.bleedReduction"}, kMsm);
    return technique;
}

}  // namespace shadowlab
