#include "light/volume_overlap.h"

#include <glm/ext/vector_double4.hpp>
#include <glm/matrix.hpp>

#include <array>
#include <cmath>

namespace shadowlab {

namespace {

std::array<glm::dvec4, 8> corners(const glm::dmat4& clipFromWorld) {
    const glm::dmat4 worldFromClip = glm::inverse(clipFromWorld);
    std::array<glm::dvec4, 8> out;
    for (int i = 0; i < 8; ++i) {
        const glm::dvec4 ndc((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0, 1.0);
        glm::dvec4 p = worldFromClip * ndc;
        out[std::size_t(i)] = p / p.w;
    }
    return out;
}

// True when every corner of `other` lies outside one face plane of `volume`.
bool separatedByAFaceOf(const glm::dmat4& volume, const std::array<glm::dvec4, 8>& other) {
    const glm::dmat4 m = glm::transpose(volume);  // rows of the clip matrix
    for (int axis = 0; axis < 3; ++axis) {
        for (double side : {-1.0, 1.0}) {
            // Inside: w + side * coordinate >= 0 (x <= w, x >= -w, ...).
            const glm::dvec4 plane = m[3] + side * m[axis];
            bool allOutside = true;
            for (const glm::dvec4& c : other)
                if (glm::dot(plane, c) >= 0.0) {
                    allOutside = false;
                    break;
                }
            if (allOutside) return true;
        }
    }
    return false;
}

}  // namespace

bool volumesOverlap(const glm::dmat4& a, const glm::dmat4& b) {
    const std::array<glm::dvec4, 8> ca = corners(a), cb = corners(b);
    for (const auto* set : {&ca, &cb})
        for (const glm::dvec4& c : *set)
            if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z)) return true;  // cannot tell
    return !separatedByAFaceOf(a, cb) && !separatedByAFaceOf(b, ca);
}

}  // namespace shadowlab
