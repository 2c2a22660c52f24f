#include "shading/filters/filter_technique.h"

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace shadowlab {

const std::vector<const FilterTechnique*>& filterTechniques() {
    static const std::vector<const FilterTechnique*> table = {
        &pointFilter(), &hardware2x2Filter(), &pcfFilter(), &poissonFilter(),
        &vsmFilter(),   &evsm2Filter(),       &evsm4Filter(), &msmFilter(), &pcssFilter(),
    };
    return table;
}

const FilterTechnique& filterTechnique(FilterKind kind) {
    for (const FilterTechnique* technique : filterTechniques())
        if (technique->kind == kind) return *technique;
    throw std::logic_error("no filter technique for FilterKind " + std::to_string(int(kind)));
}

double blurTexels(const FilterSettings& filter, double texelWorldSize, bool* clamped) {
    double texels = filter.blurWidth;
    if (filter.blurUnit == BlurUnit::World) texels = texelWorldSize > 0.0 ? filter.blurWidth / texelWorldSize : 1.0;
    if (clamped) *clamped = texels > kMaxBlurTexels;
    return std::clamp(texels, 1.0, kMaxBlurTexels);
}

std::vector<float> blurWeights(double widthTexels) {
    const double half = (std::max(widthTexels, 1.0) - 1.0) / 2.0;  // taps beyond the centre, fractional
    const int r = int(std::ceil(half - 1e-9));
    std::vector<float> w(std::size_t(2 * r + 1), 1.0f);
    if (r > 0 && half < double(r)) w.front() = w.back() = float(half - double(r - 1));
    float sum = 0.0f;
    for (float v : w) sum += v;
    for (float& v : w) v /= sum;
    return w;
}

double tradeOffTop(const TradeOffRange& range, const Settings& settings) {
    return range.limit ? std::min(range.high, range.limit(settings)) : range.high;
}

std::vector<double> tradeOffCandidates(const TradeOffRange& range, const Settings& settings) {
    const double high = std::max(tradeOffTop(range, settings), range.low);
    const int steps = std::max(range.steps, 2);
    std::vector<double> values;
    for (int i = 0; i < steps; ++i) {
        const double t = double(i) / double(steps - 1);
        double v = range.geometric && range.low > 0.0 ? range.low * std::pow(high / range.low, t)
                                                      : range.low + (high - range.low) * t;
        // Stored as float: keep the top exactly at the limit (float(5.54) must not round above it).
        v = i == steps - 1 ? high : std::min(v, high);
        if (values.empty() || v > values.back()) values.push_back(v);
    }
    return values;
}

float lightSpread(const LightSettings& light) {
    const double size = std::max(double(light.size), 0.0);
    if (light.type == LightType::Directional)
        return float(2.0 * std::tan(glm::radians(size) * 0.5));  // the soft reference's disc (soft_visibility.cpp)
    return float(2.0 * size);
}

float maxWarpExponent(int momentBits) { return momentBits == 16 ? 5.54f : 42.0f; }

}  // namespace shadowlab
