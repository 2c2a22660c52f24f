#pragma once
// A point light's cube faces as its lookups read them, in float as the GPU computes: the CPU mirror of
// shaders/shadow/cube_face_depth.glsl (the lookup face's tangent frame, a tap's direction across it, the receiver's
// depth in the face a direction selects), and what the sampler then does with a direction (OpenGL 4.5, 8.13: the face
// it selects and its texture coordinate; with seamless filtering, a texel beyond a face's edge is the neighbouring
// face's). PCSS's mirror (pcss_filter.cpp), the pixel probe and the moments pass's cube blur mirror
// (moments_mirror.cpp) read cube taps through these.
#include <glm/ext/vector_double2.hpp>
#include <glm/ext/vector_double3.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <optional>

namespace shadowlab {

// cube_face_depth.glsl's CubeFaceFrame: the lookup's face's two tangent axes and a texel's width there.
struct CubeFaceFrame {
    glm::vec3 fromLight{0.0f};  // the lookup from the light
    glm::vec3 s{0.0f}, t{0.0f};
    float major = 0.0f;  // the lookup's distance along its face's axis
    float texel = 0.0f;  // 2 / resolution x major
};

// cubeFaceFrame: `texelStep` is LightData.shadow.z, float(1 / resolution).
CubeFaceFrame cubeFaceFrame(glm::vec3 fromLight, float texelStep);
// cubeFaceTap: the direction of a tap `offsetTexels` across the face from the lookup.
glm::vec3 cubeFaceTap(const CubeFaceFrame& frame, glm::vec2 offsetTexels);
// faceDepth: the receiver's window depth in the face `tapDirection` selects (not clamped to the far plane).
float faceDepth(glm::vec3 fromLight, glm::vec3 tapDirection, float nearPlane, float farPlane, bool reversedZ);

// The face a direction selects (views/view_select.h's cubeFaceOf) and its texture coordinate s, t in [0, 1]
// (table 8.19: s = (sc / |ma| + 1) / 2, t likewise), as the face's light space maps it (light/light_space.cpp's
// cubeFaces).
struct CubeCoordinate {
    int face = 0;
    glm::dvec2 st{0.0};
};
CubeCoordinate cubeCoordinate(const glm::dvec3& direction);

struct CubeTexel {
    int face = 0;
    int x = 0, y = 0;
};
// Texel (x, y) of `face`, at most one texel beyond its edge, as seamless cube filtering reads it: itself inside the
// face, else the texel of the neighbouring face that holds the extended texel's centre. nullopt beyond both edges
// (a corner, where the specification leaves the texel to the implementation).
std::optional<CubeTexel> seamlessTexel(int face, int x, int y, int resolution);

// A face's s and t directions and its axis (table 8.19) as the columns of a matrix: the moments pass's cube blur gets
// them as a uniform (shaders/moments_cube_blur.comp.glsl).
glm::mat3 cubeFaceBasis(int face);
// The direction of texel (x, y)'s centre on `face`, in float as moments_cube_blur.comp.glsl computes it.
glm::vec3 cubeTexelDirection(int face, int x, int y, int resolution);
// The texel a nearest sampler reads for a direction: the face it selects, its texel holding s, t.
CubeTexel nearestCubeTexel(const glm::dvec3& direction, int resolution);

}  // namespace shadowlab
