#include "light/light_space.h"

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

// World size of the margin added around fitted volumes so that geometry on the bounding sphere is not clipped.
double fitMargin(double radius) { return std::max(radius * 0.02, 1e-3); }

glm::dmat4 viewFromBasis(const glm::dmat3& basis, const glm::dvec3& eye) {
    // Inverse of the rigid transform [basis | eye]: rows are the basis vectors.
    glm::dmat4 view(1.0);
    for (int axis = 0; axis < 3; ++axis) {
        view[0][axis] = basis[axis].x;
        view[1][axis] = basis[axis].y;
        view[2][axis] = basis[axis].z;
        view[3][axis] = -glm::dot(basis[axis], eye);
    }
    return view;
}

}  // namespace

double LightSpace::texelSizeAt(double viewDepth) const {
    if (!perspective) return texelWorldSize;
    return 2.0 * tanHalfFov * std::max(viewDepth, nearPlane) / resolution;
}

double LightSpace::windowDepth(const glm::dvec4& clip) const {
    const double ndc = clip.z / clip.w;
    return reversedZ ? ndc : ndc * 0.5 + 0.5;
}

glm::dvec3 LightSpace::textureOf(const glm::dvec4& clip) const {
    return {clip.x / clip.w * 0.5 + 0.5, clip.y / clip.w * 0.5 + 0.5, windowDepth(clip)};
}

glm::dmat4 LightSpace::volumeViewProjection() const {
    if (!reversedZ) return viewProjection();
    // Reversed-Z's window depth d = z / w becomes GL's z' = w - 2 z (near -1, far 1).
    glm::dmat4 toGl(1.0);
    toGl[2][2] = -2.0;
    toGl[3][2] = 1.0;
    return toGl * viewProjection();
}

float conventionBorderDepth(float borderDepth, bool reversedZ) { return reversedZ ? 1.0f - borderDepth : borderDepth; }

namespace {

// The light's projections in its depth convention. Reversed-Z is the zero-to-one projection with near and far
// swapped: near -> 1, far -> 0 (glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE) in the shadow pass).
glm::dmat4 orthoProjection(double halfSize, double nearPlane, double farPlane, bool reversed) {
    if (reversed) return glm::orthoRH_ZO(-halfSize, halfSize, -halfSize, halfSize, farPlane, nearPlane);
    return glm::ortho(-halfSize, halfSize, -halfSize, halfSize, nearPlane, farPlane);
}

glm::dmat4 perspectiveProjection(double fovRadians, double nearPlane, double farPlane, bool reversed) {
    if (reversed) return glm::perspectiveRH_ZO(fovRadians, 1.0, farPlane, nearPlane);
    return glm::perspective(fovRadians, 1.0, nearPlane, farPlane);
}

}  // namespace

glm::dmat3 lightBasis(const glm::dvec3& directionIn) {
    const glm::dvec3 d = glm::normalize(directionIn);
    const glm::dvec3 down(0.0, -1.0, 0.0);
    // Base frame looking straight down: right = +x, up = -z, back = +y.
    const glm::dvec3 baseRight(1.0, 0.0, 0.0), baseUp(0.0, 0.0, -1.0), baseBack(0.0, 1.0, 0.0);
    const double c = glm::dot(down, d);
    if (c < -1.0 + 1e-9) {
        // Straight up: the minimal rotation is undefined (any half-turn works); pick the half-turn about x.
        return glm::dmat3(baseRight, -baseUp, -baseBack);
    }
    // Rodrigues' rotation taking `down` to d: R = I + [v]x + [v]x^2 / (1 + c), v = down x d.
    const glm::dvec3 v = glm::cross(down, d);
    const glm::dmat3 vx(glm::dvec3(0.0, v.z, -v.y), glm::dvec3(-v.z, 0.0, v.x), glm::dvec3(v.y, -v.x, 0.0));
    const glm::dmat3 rotation = glm::dmat3(1.0) + vx + (vx * vx) * (1.0 / (1.0 + c));
    glm::dvec3 right = glm::normalize(rotation * baseRight);
    glm::dvec3 back = -d;
    glm::dvec3 up = glm::normalize(glm::cross(back, right));
    right = glm::cross(up, back);
    (void)baseBack;
    return glm::dmat3(right, up, back);
}

LightSpace orthoLightSpace(const LightSettings& light, const glm::dvec3& direction, const glm::dvec3& eye,
                           double halfSize, double nearPlane, double farPlane) {
    LightSpace ls;
    ls.perspective = false;
    ls.reversedZ = light.shadow.reversedZ;
    ls.direction = direction;
    ls.resolution = std::max(light.shadow.resolution, 1);
    ls.position = eye;
    ls.nearPlane = nearPlane;
    ls.farPlane = farPlane;
    ls.orthoSize = 2.0 * halfSize;
    ls.texelWorldSize = ls.orthoSize / ls.resolution;
    ls.view = viewFromBasis(lightBasis(direction), eye);
    ls.projection = orthoProjection(halfSize, nearPlane, farPlane, ls.reversedZ);
    return ls;
}

bool allFinite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

bool allFinite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

std::optional<LightSpace> buildLightSpace(const Settings& settings, const Bounds& bounds, const glm::dvec3& origin,
                                          std::string& error) {
    if (settings.lights.empty()) {
        error = "lights: the settings have no light";
        return std::nullopt;
    }
    return buildLightSpace(settings.lights[0], bounds, origin, error);
}

std::optional<LightSpace> buildLightSpace(const LightSettings& light, const Bounds& bounds, const glm::dvec3& origin,
                                          std::string& error) {
    if (light.type == LightType::Point) {
        error = "light: a point light has six views (buildCubeFaceSpaces)";
        return std::nullopt;
    }
    const ProjectionSettings& proj = light.projection;
    const glm::dvec3 dir(light.direction);
    const double dirLength = glm::length(dir);
    if (!std::isfinite(dirLength) || dirLength < 1e-12) {
        error = "light.direction: must be finite and non-zero";
        return std::nullopt;
    }
    LightSpace ls;
    ls.reversedZ = light.shadow.reversedZ;
    ls.direction = dir / dirLength;
    ls.resolution = std::max(light.shadow.resolution, 1);
    const glm::dmat3 basis = lightBasis(ls.direction);

    // The scene's bounding sphere, relative to the render origin (empty scenes get a unit sphere).
    const glm::dvec3 center = bounds.centreOrOrigin() - origin;
    const double radius = bounds.empty ? 1.0 : std::max(double(bounds.radius()), 1e-3);

    if (light.type == LightType::Directional) {
        // The eye sits on the scene's bounding sphere, on the side the light comes from; near/far are distances
        // from it along the light. Auto-fit takes [0, diameter], so manual values start from the same place.
        const double r = radius + fitMargin(radius);
        ls = proj.autoFit ? orthoLightSpace(light, ls.direction, center - ls.direction * r, r, 0.0, 2.0 * r)
                          : orthoLightSpace(light, ls.direction, center - ls.direction * r,
                                            0.5 * double(proj.orthoSize), proj.nearPlane, proj.farPlane);
    } else {
        ls.perspective = true;
        ls.position = glm::dvec3(light.position) - origin;
        const double coneDeg = std::clamp(double(light.spotConeDeg), 1.0, 170.0);
        ls.tanHalfFov = std::tan(glm::radians(coneDeg) * 0.5);
        const double distance = glm::length(center - ls.position);
        if (proj.autoFit) {
            ls.farPlane = distance + radius + fitMargin(radius);
            if (light.range > 0.0f) ls.farPlane = std::min(ls.farPlane, double(light.range));  // nothing lit beyond
            ls.nearPlane = std::max({distance - radius - fitMargin(radius), ls.farPlane * 1e-3, 1e-4});
        } else {
            ls.nearPlane = proj.nearPlane;
            ls.farPlane = proj.farPlane;
        }
        ls.texelWorldSize = 2.0 * ls.tanHalfFov * std::max(distance, ls.nearPlane) / ls.resolution;
        ls.view = viewFromBasis(basis, ls.position);
        ls.projection = perspectiveProjection(glm::radians(coneDeg), ls.nearPlane, ls.farPlane, ls.reversedZ);
    }
    if (!(ls.nearPlane < ls.farPlane)) {
        error = "projection: near (" + std::to_string(ls.nearPlane) + ") must be less than far (" +
                std::to_string(ls.farPlane) + ")";
        return std::nullopt;
    }
    if (!allFinite(ls.view) || !allFinite(ls.projection)) {
        error = "light: the light's matrices are not finite (check direction, position, size, near and far)";
        return std::nullopt;
    }
    return ls;
}

const std::array<CubeFace, 6>& cubeFaces() {
    // GL's cube-map face order and orientation (OpenGL 4.5, table 8.19): rendering each face with this look
    // direction and up vector, through a 90-degree perspective, puts a direction's texel where samplerCube reads it.
    static const std::array<CubeFace, 6> faces = {{
        {"+X", {1.0, 0.0, 0.0}, {0.0, -1.0, 0.0}},
        {"-X", {-1.0, 0.0, 0.0}, {0.0, -1.0, 0.0}},
        {"+Y", {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}},
        {"-Y", {0.0, -1.0, 0.0}, {0.0, 0.0, -1.0}},
        {"+Z", {0.0, 0.0, 1.0}, {0.0, -1.0, 0.0}},
        {"-Z", {0.0, 0.0, -1.0}, {0.0, -1.0, 0.0}},
    }};
    return faces;
}

std::optional<std::array<LightSpace, 6>> buildCubeFaceSpaces(const LightSettings& light, const Bounds& bounds,
                                                             const glm::dvec3& origin, std::string& error) {
    const glm::dvec3 position = glm::dvec3(light.position) - origin;
    const glm::dvec3 center = bounds.centreOrOrigin() - origin;
    const double radius = bounds.empty ? 1.0 : std::max(double(bounds.radius()), 1e-3);
    const double distance = glm::length(center - position);
    double nearPlane = light.projection.nearPlane, farPlane = light.projection.farPlane;
    if (light.projection.autoFit) {
        // Far: the farthest point of the scene's sphere (or the range, if nearer); near: a thousandth of that, so
        // casters close to the light still cast and D24/D32F keep their precision where the receivers are.
        farPlane = distance + radius + fitMargin(radius);
        if (light.range > 0.0f) farPlane = std::min(farPlane, double(light.range));
        nearPlane = std::max(farPlane * 1e-3, 1e-4);
    }
    if (!(nearPlane < farPlane)) {
        error = "projection: near (" + std::to_string(nearPlane) + ") must be less than far (" +
                std::to_string(farPlane) + ")";
        return std::nullopt;
    }
    std::array<LightSpace, 6> spaces;
    for (int face = 0; face < 6; ++face) {
        const CubeFace& f = cubeFaces()[std::size_t(face)];
        LightSpace& ls = spaces[std::size_t(face)];
        ls.perspective = true;
        ls.cubeFace = face;
        ls.reversedZ = light.shadow.reversedZ;
        ls.position = position;
        ls.direction = f.look;
        ls.resolution = std::max(light.shadow.resolution, 1);
        ls.tanHalfFov = 1.0;  // 90 degrees
        ls.nearPlane = nearPlane;
        ls.farPlane = farPlane;
        ls.texelWorldSize = 2.0 * std::max(std::min(distance, farPlane), nearPlane) / ls.resolution;
        // Columns right, up, back of the face's camera (lookAt with GL's up vector for the face).
        const glm::dvec3 back = -f.look;
        const glm::dvec3 right = glm::normalize(glm::cross(f.up, back));
        const glm::dvec3 up = glm::cross(back, right);
        ls.view = viewFromBasis(glm::dmat3(right, up, back), position);
        ls.projection = perspectiveProjection(glm::radians(90.0), nearPlane, farPlane, ls.reversedZ);
        if (!allFinite(ls.view) || !allFinite(ls.projection)) {
            error = "light: the point light's matrices are not finite (check position, near and far)";
            return std::nullopt;
        }
    }
    return spaces;
}

}  // namespace shadowlab
