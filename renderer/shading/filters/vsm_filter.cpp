// VSM: two moments (depth, depth squared), Chebyshev's bound with a minimum variance and a light-bleeding
// reduction. GLSL: shaders/shadow/techniques/vsm.glsl (this is its CPU mirror, in float as the GPU computes).
#include "shading/filters/moment_filter.h"

#include <cstdio>

namespace shadowlab {

namespace {

const MomentTechnique kVsm{
    2, false, "shadow/techniques/vsm.glsl",
    [](const FilterSettings& f) { return glm::vec4(f.minVariance, f.bleedReduction, 0.0f, 0.0f); },
    [](float z, const glm::vec4&) { return glm::vec4(z, z * z, 0.0f, 0.0f); },
    [](const glm::vec4& m, float z, const glm::vec4& u) {
        return reduceBleeding(chebyshevUpperBound(m.x, m.y, z, u.x), u.y);
    },
    [](const glm::vec4& m, float z, const glm::vec4& u) {
        char text[256];
        std::snprintf(text, sizeof text,
                      "VSM: mean %.6g, variance %.6g (minimum %.3g), receiver %.6g: Chebyshev bound %.4f, after "
                      "bleeding reduction %.2f: %.4f",
                      double(m.x), double(m.y - m.x * m.x), double(u.x), double(z),
                      double(chebyshevUpperBound(m.x, m.y, z, u.x)), double(u.y),
                      double(reduceBleeding(chebyshevUpperBound(m.x, m.y, z, u.x), u.y)));
        return std::string(text);
    }};

}  // namespace

const FilterTechnique& vsmFilter() {
    static const FilterTechnique technique =
        momentsFilter(FilterKind::Vsm, "vsm", {"filter.minVariance", "filter.bleedReduction"}, kVsm);
    return technique;
}

}  // namespace shadowlab
