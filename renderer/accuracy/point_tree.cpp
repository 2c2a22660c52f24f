#include "accuracy/point_tree.h"

#include <nanoflann.hpp>

#include <cmath>
#include <limits>

namespace shadowlab {

namespace {

// nanoflann's dataset interface over the points.
struct Cloud {
    std::vector<glm::dvec2> points;
    std::size_t kdtree_get_point_count() const { return points.size(); }
    double kdtree_get_pt(std::size_t i, std::size_t axis) const { return points[i][glm::length_t(axis)]; }
    template <class Box>
    bool kdtree_get_bbox(Box&) const {
        return false;  // let the tree compute its bounding box
    }
};

using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud>, Cloud, 2, std::size_t>;

}  // namespace

struct PointTree::Index {
    Cloud cloud;  // declared before the tree, which is built from it in its constructor
    Tree tree;
    explicit Index(std::vector<glm::dvec2> points) : cloud{std::move(points)}, tree(2, cloud) {}
};

PointTree::PointTree(std::vector<glm::dvec2> points)
    : index_(points.empty() ? nullptr : std::make_unique<Index>(std::move(points))) {}
PointTree::~PointTree() = default;
PointTree::PointTree(PointTree&&) noexcept = default;
PointTree& PointTree::operator=(PointTree&&) noexcept = default;

std::size_t PointTree::size() const { return index_ ? index_->cloud.points.size() : 0; }

double PointTree::nearestDistance(const glm::dvec2& query) const {
    if (!index_) return std::numeric_limits<double>::infinity();
    const double q[2] = {query.x, query.y};
    std::size_t nearest = 0;
    double distance2 = std::numeric_limits<double>::infinity();
    index_->tree.knnSearch(q, 1, &nearest, &distance2);
    return std::sqrt(distance2);
}

}  // namespace shadowlab
