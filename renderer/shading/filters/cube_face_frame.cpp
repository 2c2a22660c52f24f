// CPU mirror of shaders/shadow/cube_face_depth.glsl, step for step in float, and the sampler's cube addressing.
#include "shading/filters/cube_face_frame.h"

#include "views/view_select.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace shadowlab {

CubeFaceFrame cubeFaceFrame(glm::vec3 fromLight, float texelStep) {
    const glm::vec3 a = glm::abs(fromLight);
    const int axis = cubeFaceOf(glm::dvec3(fromLight)) / 2;
    CubeFaceFrame f;
    f.fromLight = fromLight;
    f.s = axis == 0 ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    f.t = axis == 1 ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    f.major = std::max(a.x, std::max(a.y, a.z));
    f.texel = 2.0f * texelStep * f.major;
    return f;
}

glm::vec3 cubeFaceTap(const CubeFaceFrame& frame, glm::vec2 offsetTexels) {
    const glm::vec2 o = offsetTexels * frame.texel;
    return frame.fromLight + o.x * frame.s + o.y * frame.t;
}

float faceDepth(glm::vec3 fromLight, glm::vec3 tapDirection, float nearPlane, float farPlane, bool reversedZ) {
    const int face = cubeFaceOf(glm::dvec3(tapDirection));
    glm::vec3 axis(0.0f);
    axis[face / 2] = face % 2 == 0 ? 1.0f : -1.0f;
    const float n = nearPlane, f = farPlane;
    const float z = std::max(glm::dot(fromLight, axis), n);
    if (reversedZ) return n * (f - z) / (z * (f - n));
    return ((f + n) / (f - n) - 2.0f * f * n / ((f - n) * z)) * 0.5f + 0.5f;
}

namespace {

// Table 8.19: a face's sc and tc as directions (the face's s and t axes) and its axis.
struct FaceAxes {
    glm::dvec3 sc, tc, ma;
};
const FaceAxes& faceAxes(int face) {
    static const FaceAxes axes[6] = {
        {{0, 0, -1}, {0, -1, 0}, {1, 0, 0}},  {{0, 0, 1}, {0, -1, 0}, {-1, 0, 0}},
        {{1, 0, 0}, {0, 0, 1}, {0, 1, 0}},    {{1, 0, 0}, {0, 0, -1}, {0, -1, 0}},
        {{1, 0, 0}, {0, -1, 0}, {0, 0, 1}},   {{-1, 0, 0}, {0, -1, 0}, {0, 0, -1}},
    };
    return axes[face];
}

}  // namespace

CubeCoordinate cubeCoordinate(const glm::dvec3& direction) {
    CubeCoordinate c;
    c.face = cubeFaceOf(direction);
    const FaceAxes& f = faceAxes(c.face);
    const double ma = std::abs(glm::dot(direction, f.ma));
    c.st = glm::dvec2(glm::dot(direction, f.sc) / ma + 1.0, glm::dot(direction, f.tc) / ma + 1.0) * 0.5;
    return c;
}

std::optional<CubeTexel> seamlessTexel(int face, int x, int y, int resolution) {
    const bool outX = x < 0 || x >= resolution, outY = y < 0 || y >= resolution;
    if (!outX && !outY) return CubeTexel{face, x, y};
    if (outX && outY) return std::nullopt;
    // The texel's centre on the face's plane, extended past its edge, is a direction of the neighbouring face.
    const FaceAxes& f = faceAxes(face);
    const double sc = 2.0 * (x + 0.5) / resolution - 1.0, tc = 2.0 * (y + 0.5) / resolution - 1.0;
    return nearestCubeTexel(f.ma + sc * f.sc + tc * f.tc, resolution);
}

glm::mat3 cubeFaceBasis(int face) {
    const FaceAxes& f = faceAxes(face);
    return glm::mat3(glm::vec3(f.sc), glm::vec3(f.tc), glm::vec3(f.ma));
}

glm::vec3 cubeTexelDirection(int face, int x, int y, int resolution) {
    const glm::mat3 basis = cubeFaceBasis(face);
    const float step = 1.0f / float(resolution);
    const glm::vec2 c = (glm::vec2(float(x), float(y)) + 0.5f) * (2.0f * step) - 1.0f;
    return basis[2] + c.x * basis[0] + c.y * basis[1];
}

CubeTexel nearestCubeTexel(const glm::dvec3& direction, int resolution) {
    const CubeCoordinate c = cubeCoordinate(direction);
    const auto texelOf = [resolution](double u) { return std::clamp(int(std::floor(u * resolution)), 0, resolution - 1); };
    return {c.face, texelOf(c.st.x), texelOf(c.st.y)};
}

}  // namespace shadowlab
