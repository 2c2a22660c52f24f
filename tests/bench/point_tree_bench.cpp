// PointTree's build and query CPU time (docs/performance.md): boundary-like points (half-texel steps along circles,
// as shadow_boundary.cpp's midpoints of pixel pairs lie along shadow edges) and uniform points in a 4096² map, 1M and
// 10k of each, 1M uniform queries; the best of 3 runs. The checksum (the sum of the distances) keeps the work and lets
// two implementations be compared. Not built by default: cmake --build build --target point_tree_bench.
#include "accuracy/point_tree.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <numbers>
#include <random>
#include <vector>

using namespace shadowlab;

namespace {

// CPU time of this process in ms: on a shared machine wall time is not comparable between runs.
double cpuMs() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

// Circles of random centre and radius, points half a texel apart and snapped to half texels (pixel-pair midpoints).
std::vector<glm::dvec2> boundaryLike(std::size_t count, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(0.0, 4096.0);
    std::vector<glm::dvec2> points;
    while (points.size() < count) {
        const glm::dvec2 centre(u(rng), u(rng));
        const double radius = 20.0 + u(rng) / 8.0;
        const int steps = int(2.0 * std::numbers::pi * radius / 0.5);
        for (int i = 0; i < steps && points.size() < count; ++i) {
            const double a = 2.0 * std::numbers::pi * i / steps;
            points.emplace_back(std::round((centre.x + radius * std::cos(a)) * 2.0) / 2.0,
                                std::round((centre.y + radius * std::sin(a)) * 2.0) / 2.0);
        }
    }
    return points;
}

std::vector<glm::dvec2> uniform(std::size_t count, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(0.0, 4096.0);
    std::vector<glm::dvec2> points(count);
    for (glm::dvec2& p : points) p = {u(rng), u(rng)};
    return points;
}

}  // namespace

int main() {
    std::mt19937_64 rng(42);
    for (std::size_t count : {std::size_t(1000000), std::size_t(10000)}) {
        for (const bool edges : {true, false}) {
            const std::vector<glm::dvec2> points = edges ? boundaryLike(count, rng) : uniform(count, rng);
            const std::vector<glm::dvec2> queries = uniform(1000000, rng);
            double build = 1e30, query = 1e30, checksum = 0.0;
            for (int run = 0; run < 3; ++run) {
                const double t0 = cpuMs();
                const PointTree tree(points);
                const double t1 = cpuMs();
                double sum = 0.0;
                for (const glm::dvec2& q : queries) sum += tree.nearestDistance(q);
                const double t2 = cpuMs();
                build = std::min(build, t1 - t0);
                query = std::min(query, t2 - t1);
                checksum = sum;
            }
            std::printf("%s, %zu points: build %.1f ms, 1M queries %.1f ms, checksum %.6f\n",
                        edges ? "boundary-like" : "uniform", count, build, query, checksum);
        }
    }
}
