#include "shading/filters/moment_filter.h"

#include <algorithm>

namespace shadowlab {

std::string momentImageFormat(const FilterTechnique& technique, int momentBits) {
    const MomentTechnique* m = technique.moments;
    if (!m) return "";
    if (momentBits == 16) return m->channels == 2 ? "rg16f" : m->unorm16 ? "rgba16" : "rgba16f";
    return m->channels == 2 ? "rg32f" : "rgba32f";
}

int momentLevels(int resolution, bool mips) {
    int levels = 1;
    while (mips && (resolution >> levels) > 0) ++levels;
    return levels;
}

FilterTechnique momentsFilter(FilterKind kind, const char* name, std::initializer_list<const char*> ownKeys,
                              const MomentTechnique& moments) {
    FilterTechnique t{kind, name, /*bilinear=*/true,
                      [](const FilterSettings&) { return std::vector<glm::vec2>{{0.0f, 0.0f}}; },
                      [](const FilterSettings&) { return 1.0f; },
                      // The blur's half width and the bilinear read's texel; world widths differ per view: the
                      // widest blur bounds them.
                      [](const FilterSettings& filter) {
                          const double width = filter.blurUnit == BlurUnit::Texels ? blurTexels(filter, 0.0)
                                                                                   : kMaxBlurTexels;
                          return (width - 1.0) / 2.0 + 1.0;
                      }};
    t.keys = {"filter.momentBits", "filter.blurWidth", "filter.blurUnit", "filter.momentMips"};
    t.keys.insert(t.keys.end(), ownKeys);
    t.moments = &moments;
    return t;
}

float chebyshevUpperBound(float mean, float meanSquare, float z, float minVariance) {
    const float variance = std::max(meanSquare - mean * mean, minVariance);
    const float d = z - mean;
    const float pMax = variance / (variance + d * d);
    return z <= mean ? 1.0f : pMax;
}

float reduceBleeding(float pMax, float amount) { return std::clamp((pMax - amount) / (1.0f - amount), 0.0f, 1.0f); }

}  // namespace shadowlab
