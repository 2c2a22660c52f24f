#include "accuracy/point_tree.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowlab {

PointTree::PointTree(std::vector<glm::dvec2> points) : points_(std::move(points)) { build(0, points_.size(), 0); }

void PointTree::build(std::size_t begin, std::size_t end, int axis) {
    if (end - begin <= 1) return;
    const std::size_t mid = begin + (end - begin) / 2;
    std::nth_element(points_.begin() + std::ptrdiff_t(begin), points_.begin() + std::ptrdiff_t(mid),
                     points_.begin() + std::ptrdiff_t(end),
                     [axis](const glm::dvec2& a, const glm::dvec2& b) { return a[axis] < b[axis]; });
    build(begin, mid, 1 - axis);
    build(mid + 1, end, 1 - axis);
}

void PointTree::search(std::size_t begin, std::size_t end, int axis, const glm::dvec2& q, double& best2) const {
    if (begin >= end) return;
    const std::size_t mid = begin + (end - begin) / 2;
    const glm::dvec2 d = points_[mid] - q;
    best2 = std::min(best2, d.x * d.x + d.y * d.y);
    const double split = q[axis] - points_[mid][axis];
    // Near side first; the far side only if the splitting line is closer than the best so far.
    if (split < 0.0) {
        search(begin, mid, 1 - axis, q, best2);
        if (split * split < best2) search(mid + 1, end, 1 - axis, q, best2);
    } else {
        search(mid + 1, end, 1 - axis, q, best2);
        if (split * split < best2) search(begin, mid, 1 - axis, q, best2);
    }
}

double PointTree::nearestDistance(const glm::dvec2& query) const {
    if (points_.empty()) return std::numeric_limits<double>::infinity();
    double best2 = std::numeric_limits<double>::infinity();
    search(0, points_.size(), 0, query, best2);
    return std::sqrt(best2);
}

}  // namespace shadowlab
