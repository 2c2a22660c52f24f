#include "accuracy/bias_units.h"

#include <cmath>

namespace shadowlab {

double depthBiasUnitTexels(const LightSpace& light, DepthFormat format) {
    double step = std::ldexp(1.0, -24);  // D32F at depths in [0.5, 1), as GL's polygon offset uses it
    if (format == DepthFormat::D16) step = 1.0 / 65535.0;
    if (format == DepthFormat::D24) step = 1.0 / 16777215.0;
    const double range = light.farPlane - light.nearPlane;
    double world = step * range;
    if (light.perspective) {
        // Perspective depth d(z) = f(z - n) / (z (f - n)): dz = dd z^2 (f - n) / (f n), at the texel's distance.
        const double z = light.texelWorldSize * light.resolution / (2.0 * light.tanHalfFov);
        world = step * z * z * range / (light.farPlane * light.nearPlane);
    }
    return light.texelWorldSize > 0.0 ? world / light.texelWorldSize : 0.0;
}

}  // namespace shadowlab
