#pragma once
// A static 2D kd-tree answering "how far is the nearest point?" (the true shadow boundary, in shadow-map texels).
#include <glm/ext/vector_double2.hpp>

#include <vector>

namespace shadowlab {

class PointTree {
public:
    explicit PointTree(std::vector<glm::dvec2> points = {});
    bool empty() const { return points_.empty(); }
    std::size_t size() const { return points_.size(); }
    // Distance to the nearest point; +infinity when there are none.
    double nearestDistance(const glm::dvec2& query) const;

private:
    void build(std::size_t begin, std::size_t end, int axis);
    void search(std::size_t begin, std::size_t end, int axis, const glm::dvec2& q, double& best2) const;
    std::vector<glm::dvec2> points_;  // in kd order: the median of each range splits it
};

}  // namespace shadowlab
