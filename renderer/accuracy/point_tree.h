#pragma once
// A static 2D k-d tree answering "how far is the nearest point?" (the true shadow boundary, in shadow-map texels).
// The tree is nanoflann's (Debian libnanoflann-dev); its header stays in point_tree.cpp.
#include <glm/ext/vector_double2.hpp>

#include <memory>
#include <vector>

namespace shadowlab {

class PointTree {
public:
    explicit PointTree(std::vector<glm::dvec2> points = {});
    ~PointTree();
    PointTree(PointTree&&) noexcept;
    PointTree& operator=(PointTree&&) noexcept;

    bool empty() const { return size() == 0; }
    std::size_t size() const;
    // Distance to the nearest point; +infinity when there are none.
    double nearestDistance(const glm::dvec2& query) const;

private:
    struct Index;                   // the points and nanoflann's tree over them, which keeps a reference to them:
    std::unique_ptr<Index> index_;  // on the heap, so a PointTree moves without invalidating it; null when empty
};

}  // namespace shadowlab
