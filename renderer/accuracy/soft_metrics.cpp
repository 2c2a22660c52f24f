#include "accuracy/soft_metrics.h"

#include "accuracy/accuracy_metrics.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <optional>

namespace shadowlab {

namespace {

constexpr double kSameSurfaceCos = 0.86602540378;  // cos 30 degrees: a profile stays on one surface
constexpr double kOffPlane = 0.1;                  // ... and near the edge pixel's tangent plane

struct Profile {
    std::vector<double> s;  // world distance along the profile, increasing (negative toward the umbra)
    std::vector<std::size_t> pixel;
    std::size_t centre = 0;  // index of the edge pixel in s / pixel
};

struct Grid {
    const SoftMetricsInput& in;
    bool measured(int x, int y) const {
        return x >= 0 && y >= 0 && x < in.width && y < in.height && (*in.measured)[index(x, y)];
    }
    std::size_t index(int x, int y) const { return std::size_t(y) * std::size_t(in.width) + std::size_t(x); }
    double v(int x, int y) const { return (*in.visibility)[index(x, y)]; }

    // Step 2: d(V)/d(screen) along one axis, central where both neighbours are measured, else one-sided.
    double slope(int x, int y, int dx, int dy) const {
        const bool after = measured(x + dx, y + dy), before = measured(x - dx, y - dy);
        if (after && before) return 0.5 * (v(x + dx, y + dy) - v(x - dx, y - dy));
        if (after) return v(x + dx, y + dy) - v(x, y);
        if (before) return v(x, y) - v(x - dx, y - dy);
        return 0.0;
    }

    bool onSurfaceOf(std::size_t edge, std::size_t i) const {
        const glm::dvec3& n = (*in.normals)[edge];
        if (glm::dot(n, (*in.normals)[i]) < kSameSurfaceCos) return false;
        const glm::dvec3 d = (*in.points)[i] - (*in.points)[edge];
        return std::abs(glm::dot(d, n)) <= kOffPlane * glm::length(d);
    }

    // Step 3: the profile through edge pixel (x, y) along screen direction (dx, dy).
    Profile profile(int x, int y, double dx, double dy) const {
        const std::size_t edge = index(x, y);
        std::vector<std::size_t> side[2];
        for (int sign : {-1, 1}) {
            std::size_t last = edge;
            for (int t = 1; t <= kProfileSteps; ++t) {
                const int px = int(std::lround(x + sign * t * dx)), py = int(std::lround(y + sign * t * dy));
                if (!measured(px, py)) break;
                const std::size_t i = index(px, py);
                if (i == last) continue;  // a short step landed on the same pixel
                if (!onSurfaceOf(edge, i)) break;
                side[sign > 0].push_back(i);
                last = i;
            }
        }
        Profile p;
        for (auto it = side[0].rbegin(); it != side[0].rend(); ++it) p.pixel.push_back(*it);
        p.centre = p.pixel.size();
        p.pixel.push_back(edge);
        p.pixel.insert(p.pixel.end(), side[1].begin(), side[1].end());
        p.s.assign(p.pixel.size(), 0.0);
        for (std::size_t j = p.centre + 1; j < p.pixel.size(); ++j)
            p.s[j] = p.s[j - 1] + glm::length((*in.points)[p.pixel[j]] - (*in.points)[p.pixel[j - 1]]);
        for (std::size_t j = p.centre; j-- > 0;)
            p.s[j] = p.s[j + 1] - glm::length((*in.points)[p.pixel[j + 1]] - (*in.points)[p.pixel[j]]);
        return p;
    }
};

// Where F crosses `level` between samples a and b (linear), as a profile position.
double crossing(const Profile& p, const std::vector<double>& f, std::size_t a, std::size_t b, double level) {
    const double span = f[b] - f[a];
    const double w = span != 0.0 ? (level - f[a]) / span : 0.0;
    return p.s[a] + (p.s[b] - p.s[a]) * w;
}

// Step 4: F's 0.1..0.9 width on the profile, or nothing when F does not make the whole transition there.
// A width is resolved down to the pixels' footprint only: a hard step between two samples reads 0.8 x their distance.
std::optional<double> transitionWidth(const Profile& p, const std::vector<double>& f) {
    // The rising 0.5 crossing nearest the centre.
    std::optional<std::size_t> rise;
    for (std::size_t j = 0; j + 1 < f.size(); ++j) {
        if (!(f[j] < 0.5 && f[j + 1] >= 0.5)) continue;
        const auto distance = [&](std::size_t k) { return k > p.centre ? k - p.centre : p.centre - k; };
        if (!rise || distance(j) < distance(*rise)) rise = j;
    }
    if (!rise) return std::nullopt;
    std::optional<double> low, high;
    for (std::size_t j = *rise + 1; j-- > 0;) {
        if (f[j] <= kPenumbraLow) {
            low = crossing(p, f, j, j + 1, kPenumbraLow);
            break;
        }
    }
    for (std::size_t j = *rise; j < f.size(); ++j) {
        if (f[j] >= kPenumbraHigh) {
            high = j == 0 ? p.s[0] : crossing(p, f, j - 1, j, kPenumbraHigh);
            break;
        }
    }
    if (!low || !high) return std::nullopt;
    return *high - *low;
}

double median(std::vector<double> values) { return percentile(values, 50); }

}  // namespace

SoftMark softMark(double v, double s) {
    if (v == 0.0 && s > kVisibleStep) return SoftMark::Bleeding;
    if (v == 1.0 && s < kLitBelow) return SoftMark::OverDarkened;
    return SoftMark::None;
}

SoftAccuracy computeSoftMetrics(const SoftMetricsInput& in) {
    SoftAccuracy out;
    out.measured = true;
    SoftCounts& c = out.counts;
    const std::size_t count = std::size_t(in.width) * std::size_t(in.height);
    double errorSum = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        if (!(*in.measured)[i]) continue;
        const double v = (*in.visibility)[i], s = (*in.shadowFactor)[i];
        ++c.measured;
        const double error = std::abs(s - v);
        errorSum += error;
        if (error >= kWrongError) ++c.wrong;
        if (v == 0.0)
            ++c.umbra;
        else if (v == 1.0)
            ++c.fullyLit;
        else
            ++c.penumbra;
        const SoftMark mark = softMark(v, s);
        c.bleeding += mark == SoftMark::Bleeding;
        c.overDarkened += mark == SoftMark::OverDarkened;
    }
    const auto percent = [](std::size_t part, std::size_t whole) {
        return whole ? 100.0 * double(part) / double(whole) : 0.0;
    };
    out.wrongPercent = percent(c.wrong, c.measured);
    out.meanError = c.measured ? errorSum / double(c.measured) : 0.0;
    out.bleedingPercent = percent(c.bleeding, c.umbra);
    out.overDarkeningPercent = percent(c.overDarkened, c.fullyLit);

    // The penumbra widths, one profile per true-edge pixel.
    const Grid grid{in};
    std::vector<double> reference, technique, error, referenceTexels, techniqueTexels, errorTexels;
    for (int y = 0; y < in.height; ++y) {
        for (int x = 0; x < in.width; ++x) {
            if (!grid.measured(x, y) || grid.v(x, y) < 0.5) continue;
            const bool edge = (grid.measured(x - 1, y) && grid.v(x - 1, y) < 0.5) ||
                              (grid.measured(x + 1, y) && grid.v(x + 1, y) < 0.5) ||
                              (grid.measured(x, y - 1) && grid.v(x, y - 1) < 0.5) ||
                              (grid.measured(x, y + 1) && grid.v(x, y + 1) < 0.5);
            if (!edge) continue;
            ++c.edgePixels;
            const double gx = grid.slope(x, y, 1, 0), gy = grid.slope(x, y, 0, 1);
            const double length = std::hypot(gx, gy);
            if (!(length > 0.0)) continue;
            const Profile p = grid.profile(x, y, gx / length, gy / length);
            std::vector<double> v, s;
            for (std::size_t i : p.pixel) {
                v.push_back((*in.visibility)[i]);
                s.push_back((*in.shadowFactor)[i]);
            }
            const std::optional<double> wv = transitionWidth(p, v), ws = transitionWidth(p, s);
            if (!wv || !ws) continue;
            ++c.profiles;
            reference.push_back(*wv);
            technique.push_back(*ws);
            error.push_back(*ws - *wv);
            const double texel = in.worldPerTexel ? in.worldPerTexel(grid.index(x, y)) : 0.0;
            if (texel > 0.0) {
                referenceTexels.push_back(*wv / texel);
                techniqueTexels.push_back(*ws / texel);
                errorTexels.push_back((*ws - *wv) / texel);
            }
        }
    }
    PenumbraWidths& w = out.penumbra;
    w.referenceWorld = median(reference);
    w.techniqueWorld = median(technique);
    w.errorWorld = median(error);
    w.referenceTexels = median(referenceTexels);
    w.techniqueTexels = median(techniqueTexels);
    w.errorTexels = median(errorTexels);
    return out;
}

}  // namespace shadowlab
