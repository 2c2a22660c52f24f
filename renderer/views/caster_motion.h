#pragma once
// Casters that moved since the previous frame, and the texels of a view's map a caster can cover: what the planner
// needs to dirty only the views a motion touches and to redraw only the rectangle it covers (no GL).
#include "light/light_space.h"

#include <glm/ext/vector_double3.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace shadowlab {

// A caster's render-origin-relative bounding sphere; `finite` false: its size is unknown (it is always drawn).
struct CasterSphere {
    glm::dvec3 center{0.0};
    double radius = 0.0;
    bool finite = false;
    bool operator==(const CasterSphere&) const = default;
};

// One caster whose transform changed between the previous frame and this one.
struct MovedCaster {
    std::size_t caster = 0;  // its index in the frame's casters (PlanInputs::casters)
    std::string name;        // its node's path ("Traffic/car 3"), else "instance N"
    CasterSphere before, after;
};

// The frame's poses: `pose` counts the frames where a caster moved (a map records the pose it was drawn at);
// `moved` lists what moved from pose - 1 to pose this frame (empty when nothing moved: then pose stays).
struct CasterMotion {
    std::uint64_t pose = 0;
    std::vector<MovedCaster> moved;
};

// A rectangle of texels [x0, x1) x [y0, y1) of a map (GL's window coordinates: row 0 at the bottom).
struct TexelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool empty() const { return x1 <= x0 || y1 <= y0; }
    long long area() const { return empty() ? 0 : (long long)(x1 - x0) * (y1 - y0); }
    void extend(const TexelRect& r);
    bool overlaps(const TexelRect& r) const { return !empty() && !r.empty() && x0 < r.x1 && r.x0 < x1 && y0 < r.y1 && r.y0 < y1; }
    bool operator==(const TexelRect&) const = default;
};

// The texels of the view's map the caster can write: its sphere's projection (the corners of its box in light view
// space), widened by one texel so every texel whose centre a triangle covers is inside. The whole map where it
// cannot tell (a size unknown, or a sphere reaching the plane of a perspective view's eye).
TexelRect casterTexels(const CasterSphere& caster, const LightSpace& space);

}  // namespace shadowlab
