#include "raster_rounding_bound.h"

#include "light/depth_bias.h"

#include <glm/geometric.hpp>
#include <glm/mat2x2.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>

namespace shadowlab::test {

namespace {

struct WindowTriangle {
    glm::dvec2 p[3];
    double z[3];
    double dz[3];  // how far apart two float computations of each vertex's window depth may be
};

// A vertex in clip space with the bound on its float rounding, per component.
struct ClipVertex {
    glm::dvec4 clip;
    glm::dvec4 error;
};

constexpr double kUnitRoundoff = 0x1p-24;
constexpr double kDot4 = 4.0 * kUnitRoundoff / (1.0 - 4.0 * kUnitRoundoff);  // gamma_4: a float 4-term dot product

glm::dmat4 absolute(const glm::dmat4& m) {
    glm::dmat4 a;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) a[c][r] = std::abs(m[c][r]);
    return a;
}

// ||M||_F >= the spectral norm: a safe upper bound.
double frobenius(const glm::dmat2& m) {
    return std::sqrt(m[0][0] * m[0][0] + m[0][1] * m[0][1] + m[1][0] * m[1][0] + m[1][1] * m[1][1]);
}

// Every triangle the pass draws, clipped as the rasterizers clip it (without depth clamp, to 0 <= depth <= 1; with
// it, to w > 0 only) and fanned, in window space: x, y in texels, z the window depth. A clipped triangle's pieces keep
// its plane; their corners are new vertices, rounded like any other.
std::vector<WindowTriangle> windowTriangles(const DepthPassInput& input) {
    std::vector<WindowTriangle> out;
    const glm::dmat4 viewProjection(input.lightViewProjection);
    const glm::dmat4 absViewProjection = absolute(viewProjection);
    // Inside when every plane function is >= 0: z + w (GL clip depth) or z (zero-to-one) for near, w - z for far.
    std::vector<std::function<double(const glm::dvec4&)>> planes;
    if (input.raster.depthClampEnable) {
        planes.push_back([](const glm::dvec4& c) { return c.w - 1e-9; });
    } else {
        if (input.matrixZeroToOne) planes.push_back([](const glm::dvec4& c) { return c.z; });
        else planes.push_back([](const glm::dvec4& c) { return c.z + c.w; });
        planes.push_back([](const glm::dvec4& c) { return c.w - c.z; });
    }
    for (const DepthDraw& draw : input.draws) {
        const glm::dmat4 toClip = viewProjection * glm::dmat4(draw.model);
        for (std::uint32_t k = 0; k + 2 < draw.indexCount; k += 3) {
            // The shader's float products, model then light matrix: |fl(M x) - M x| <= gamma_4 |M| |x| each.
            std::vector<ClipVertex> polygon;
            for (std::uint32_t v = 0; v < 3; ++v) {
                const std::uint32_t index = input.indices[draw.firstIndex + k + v];
                const std::size_t vertex = std::size_t(std::int64_t(index) + draw.baseVertex);
                const glm::dvec4 p(glm::dvec3(input.positions[vertex]), 1.0);
                const glm::dvec4 world = glm::dmat4(draw.model) * p;
                const glm::dvec4 worldError = kDot4 * (absolute(glm::dmat4(draw.model)) * glm::abs(p));
                polygon.push_back({viewProjection * world,
                                   kDot4 * (absViewProjection * glm::abs(world)) + absViewProjection * worldError});
            }
            for (const auto& inside : planes) {  // Sutherland-Hodgman
                std::vector<ClipVertex> kept;
                for (std::size_t v = 0; v < polygon.size(); ++v) {
                    const ClipVertex& a = polygon[v];
                    const ClipVertex& b = polygon[(v + 1) % polygon.size()];
                    const double fa = inside(a.clip), fb = inside(b.clip);
                    if (fa >= 0.0) kept.push_back(a);
                    if ((fa >= 0.0) != (fb >= 0.0))
                        kept.push_back({a.clip + (b.clip - a.clip) * (fa / (fa - fb)), glm::max(a.error, b.error)});
                }
                polygon = std::move(kept);
            }
            if (polygon.size() < 3) continue;
            std::vector<glm::dvec4> window;  // x, y in texels, z window depth, w its rounding bound (both drivers)
            for (const ClipVertex& v : polygon) {
                const glm::dvec4& c = v.clip;
                const glm::dvec3 ndc = glm::dvec3(c) / c.w;
                const glm::dvec2 xy = (glm::dvec2(ndc) * 0.5 + 0.5) * double(input.resolution);
                // z / w in float: (|dz| + |z/w| |dw|) / |w| + u |z/w|; GL's window depth 0.5 z/w + 0.5 adds a rounding.
                const double ndcError = (v.error.z + std::abs(ndc.z) * v.error.w) / std::abs(c.w) +
                                        kUnitRoundoff * std::abs(ndc.z);
                const double depth = input.matrixZeroToOne ? ndc.z : 0.5 * ndc.z + 0.5;
                const double depthError = input.matrixZeroToOne ? ndcError : 0.5 * ndcError + kUnitRoundoff;
                window.push_back({xy, depth, 2.0 * depthError});  // each driver rounds its own way
            }
            for (std::size_t v = 1; v + 1 < window.size(); ++v) {
                WindowTriangle t;
                for (int j = 0; j < 3; ++j) {
                    const glm::dvec4& w = window[j == 0 ? 0 : v + std::size_t(j) - 1];
                    t.p[j] = glm::dvec2(w);
                    t.z[j] = w.z;
                    t.dz[j] = w.w;
                }
                out.push_back(t);
            }
        }
    }
    return out;
}

}  // namespace

RoundingBound rasterRoundingBound(const DepthPassInput& input, const std::vector<float>& glMap, int subPixelBits) {
    const int res = input.resolution;
    const double grid = std::ldexp(1.0, -subPixelBits);  // one subpixel step, in texels
    // The pass's bias as ShadowLab's settings state it (the snippet's factors, negated for reversed-Z, made positive),
    // to predict the depth each triangle writes: the texel's triangle is the one GL's value matches.
    ShadowMapSettings bias;
    if (input.raster.depthBiasEnable) {
        bias.depthBias = std::abs(input.raster.depthBiasConstantFactor);
        bias.slopeScaledDepthBias = std::abs(input.raster.depthBiasSlopeFactor);
        bias.depthBiasClamp = std::abs(input.raster.depthBiasClamp);
    } else {
        bias.depthBias = bias.slopeScaledDepthBias = bias.depthBiasClamp = 0.0f;
    }
    const DepthFormat format = input.format == VK_FORMAT_D16_UNORM ? DepthFormat::D16 : DepthFormat::D32F;
    const double towardFar = input.reversedZ ? -1.0 : 1.0;
    const double slopeFactor = double(bias.slopeScaledDepthBias);
    const double undeterminedBias =
        slopeFactor == 0.0 ? 0.0 : bias.depthBiasClamp > 0.0f ? double(bias.depthBiasClamp) : -1.0;
    const std::size_t texels = std::size_t(res) * std::size_t(res);
    RoundingBound out;
    out.depth.assign(texels, -1.0);
    std::vector<double> nearest(texels, std::numeric_limits<double>::infinity());  // |written - gl| of the chosen one

    for (const WindowTriangle& t : windowTriangles(input)) {
        const glm::dmat2 edges(t.p[1] - t.p[0], t.p[2] - t.p[0]);  // columns e1, e2
        const double det = glm::determinant(edges);
        if (!(std::abs(det) > 0.0)) continue;  // zero area: never rasterized
        const std::optional<glm::dvec2> gradient = windowDepthGradient(
            {t.p[0], t.z[0]}, {t.p[1], t.z[1]}, {t.p[2], t.z[2]});
        if (!gradient) continue;
        const glm::dvec2 g = *gradient;
        const glm::dmat2 inverse = glm::inverse(edges);
        const double offset = towardFar * polygonOffsetDepth(bias, format, std::max({t.z[0], t.z[1], t.z[2]}),
                                                             std::max(std::abs(g.x), std::abs(g.y)));
        const double kappa = frobenius(inverse) * 4.0 * grid;
        const bool determined = kappa < 0.5;
        // Each vertex's depth may differ by dz between the two (float products and division, bounded above): the
        // plane moves by up to max dz x the barycentric weights' sum at c, its gradient by ||E^-1|| |(dz1 + dz0,
        // dz2 + dz0)|.
        const double depthGradientChange =
            frobenius(inverse) * std::hypot(t.dz[0] + t.dz[1], t.dz[0] + t.dz[2]);
        const double vertexDepth = std::max({t.dz[0], t.dz[1], t.dz[2]});
        const double gradientChange =
            determined ? glm::length(g) * kappa / (1.0 - kappa) + depthGradientChange : 0.0;
        const double slopeTerm = slopeFactor * gradientChange;

        // Texels whose centre is inside, or within two grid steps of an edge.
        const double reach = 2.0 * grid;
        const int x0 = std::max(0, int(std::floor(std::min({t.p[0].x, t.p[1].x, t.p[2].x}) - reach - 0.5)));
        const int x1 = std::min(res - 1, int(std::ceil(std::max({t.p[0].x, t.p[1].x, t.p[2].x}) + reach - 0.5)));
        const int y0 = std::max(0, int(std::floor(std::min({t.p[0].y, t.p[1].y, t.p[2].y}) - reach - 0.5)));
        const int y1 = std::min(res - 1, int(std::ceil(std::max({t.p[0].y, t.p[1].y, t.p[2].y}) + reach - 0.5)));
        const double orientation = det > 0.0 ? 1.0 : -1.0;
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const glm::dvec2 c(x + 0.5, y + 0.5);
                bool inside = true;
                for (int e = 0; e < 3 && inside; ++e) {
                    const glm::dvec2 a = t.p[e], b = t.p[(e + 1) % 3];
                    const glm::dvec2 d = b - a;
                    // Signed distance of c from the edge, positive inside.
                    const double distance = orientation * (d.x * (c.y - a.y) - d.y * (c.x - a.x)) / glm::length(d);
                    inside = distance >= -reach;
                }
                if (!inside) continue;
                const std::size_t i = std::size_t(y) * std::size_t(res) + std::size_t(x);
                double written = t.z[0] + glm::dot(g, c - t.p[0]) + offset;
                if (input.raster.depthClampEnable) written = std::clamp(written, 0.0, 1.0);
                const double apart = std::abs(written - double(glMap[i]));
                if (apart >= nearest[i]) continue;
                nearest[i] = apart;
                if (!determined) {
                    // Thinner than the grid: its plane is not determined, but a depth it interpolates lies between
                    // its corners' depths, and its bias between the constant term and the clamp (none without a
                    // clamp unless the slope factor is 0).
                    out.depth[i] = undeterminedBias < 0.0 ? -1.0
                                                          : std::max({t.z[0], t.z[1], t.z[2]}) -
                                                                std::min({t.z[0], t.z[1], t.z[2]}) + vertexDepth +
                                                                undeterminedBias;
                    continue;
                }
                // The plane at c through the vertex nearest c: |dg| |c - p| + |g'| |dp|.
                double toVertex = std::numeric_limits<double>::infinity();
                for (const glm::dvec2& p : t.p) toVertex = std::min(toVertex, glm::length(c - p));
                // Barycentric weights of c (they sum to 1; beyond an edge by `reach` one is slightly negative).
                const glm::dvec2 w12 = inverse * (c - t.p[0]);
                const double weights = std::abs(1.0 - w12.x - w12.y) + std::abs(w12.x) + std::abs(w12.y);
                const double planeTerm = (gradientChange - depthGradientChange) * toVertex +
                                         (glm::length(g) + gradientChange) * std::sqrt(2.0) * grid +
                                         vertexDepth * weights;
                out.depth[i] = planeTerm + slopeTerm;
            }
    }
    for (std::size_t i = 0; i < texels; ++i) {
        const bool written = input.reversedZ ? glMap[i] > 0.0f : glMap[i] < 1.0f;
        if (!written) continue;
        if (std::isinf(nearest[i])) ++out.uncovered;
        else if (out.depth[i] < 0.0) ++out.undetermined;
    }
    return out;
}

}  // namespace shadowlab::test
