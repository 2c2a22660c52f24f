#include "probe/pixel_footprint.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <cmath>

namespace shadowlab {

std::optional<PositionDerivatives> fineDerivatives(const glm::dmat4& viewProjection, int width, int height, int x,
                                                   int yFromTop, const glm::dvec3 triangle[3]) {
    const glm::dmat4 inverse = glm::inverse(viewProjection);
    const glm::dvec3 normal = glm::cross(triangle[1] - triangle[0], triangle[2] - triangle[0]);
    bool ok = true;
    // Where the ray through window pixel (wx, wy)'s centre meets the plane: two points of the ray (clip depths 0 and
    // 0.5 lie between near and far in either depth convention).
    const auto at = [&](int wx, int wy) {
        const glm::dvec2 ndc(2.0 * (wx + 0.5) / width - 1.0, 2.0 * (wy + 0.5) / height - 1.0);
        const glm::dvec4 a = inverse * glm::dvec4(ndc, 0.0, 1.0), b = inverse * glm::dvec4(ndc, 0.5, 1.0);
        const glm::dvec3 o = glm::dvec3(a) / a.w, d = glm::dvec3(b) / b.w - o;
        const double facing = glm::dot(d, normal);
        if (!(std::abs(facing) > 0.0)) ok = false;
        return o + d * (glm::dot(triangle[0] - o, normal) / facing);
    };
    const int wx = x, wy = height - 1 - yFromTop;
    const int qx = wx & ~1, qy = wy & ~1;  // the quad's lower-left pixel
    PositionDerivatives r{at(qx + 1, wy) - at(qx, wy), at(wx, qy + 1) - at(wx, qy)};
    if (!ok) return std::nullopt;
    return r;
}

}  // namespace shadowlab
