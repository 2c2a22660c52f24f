#pragma once
// The moments pass on the CPU, for tests and the probe: a depth layer converted to the technique's moments (of the
// depth momentDepth gives), stored at its precision, blurred by the box of blurWeights (horizontal, then vertical,
// edge texels repeated, each result stored at the precision again), and its mip levels, as shaders/moments.comp.glsl
// computes them; a point light's cube blurred across its faces' edges (shaders/moments_cube_blur.comp.glsl).
#include "shading/filters/filter_technique.h"

#include <glm/vec4.hpp>

#include <array>
#include <vector>

namespace shadowlab {

// A view's depth convention as the moments pass reads it.
struct MomentDepthConvention {
    bool reversedZ = false;
    bool perspective = false;  // a spot view or cube face: window depth between nearPlane and farPlane
    float nearPlane = 0.0f, farPlane = 1.0f;
};

// The depth a moments map stores of a window depth (near 0, far 1): orthographic as is (reversed-Z flipped),
// perspective the distance along the view's axis normalised by near and far (shaders/shadow/linear_depth.glsl, in
// float as the GPU computes it).
float momentDepth(float window, const MomentDepthConvention& convention);

// One value as the storage holds it: fp32 as is, fp16 rounded to half, unorm16 clamped to [0, 1] in 1/65535 steps.
glm::vec4 storedMoments(const glm::vec4& value, const MomentTechnique& technique, int momentBits);

// `depth`: resolution x resolution stored depths (row 0 = bottom), in the map's convention.
std::vector<glm::vec4> momentsOfDepth(const std::vector<float>& depth, int resolution,
                                      const MomentDepthConvention& convention, const FilterSettings& filter,
                                      double blurWidthTexels);

// "No caster" as the storage holds it: the moments of the far plane (a cleared depth texel, in the moments' depth
// convention: 1), and whether stored moments are those (their first moment within a storage step of it).
glm::vec4 emptyMoments(const FilterSettings& filter);
bool isEmptyMoments(const glm::vec4& stored, const glm::vec4& empty);

// A point light's cube: its six faces in GL order (+X, -X, +Y, -Y, +Z, -Z), each resolution x resolution texels.
using CubeMoments = std::array<std::vector<glm::vec4>, 6>;

// A cube's depths (each face's in the map's convention) converted, then blurred across the faces' edges as
// shaders/moments_cube_blur.comp.glsl does: each texel's taps move by direction in the lookups' cube-face frame
// (cube_face_frame.h) and read the nearest texel of the face they reach; first along the frame's s (and its t near
// the edges), then along t reading each tap's face's blur along this face's s; each pass stored at the precision.
CubeMoments momentsOfCube(const std::array<std::vector<float>, 6>& depth, int resolution,
                          const MomentDepthConvention& convention, const FilterSettings& filter,
                          double blurWidthTexels);

// The mip level below a level of `size` x `size` texels (filter.momentMips): size / 2 (at least 1), each texel the
// mean of the 2x2 texels under it that hold a caster (emptyMoments where none does; an odd size's last row and column
// are left out), stored at the precision. The GPU builds level 1 from the unblurred moments (the blur runs after).
std::vector<glm::vec4> momentsMipLevel(const std::vector<glm::vec4>& level, int size, const FilterSettings& filter);

}  // namespace shadowlab
