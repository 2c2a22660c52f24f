#pragma once
// A compute dispatch in Vulkan (run on Mesa's lavapipe in the tests): an exported lookup (a moments technique's or
// PCSS's), compiled to SPIR-V, reads a map (one sampled 2D-array layer, in the exported format, through each sampler
// the export names) at a list of surface points and writes S for each. The check that the exported Vulkan GLSL
// computes ShadowLab's shadow. Not a product path.
#include "vulkan_compute_pass.h"

#include <glm/vec4.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace shadowlab::test {

struct LookupPassInput {
    std::vector<std::uint32_t> spirv;   // a compute shader: local_size_x 64, points at binding 10, S at binding 11
    VkFormat format = VK_FORMAT_R32G32_SFLOAT;  // VK_FORMAT_D32_SFLOAT: a depth map (comparison samplers)
    int resolution = 0;
    std::vector<std::uint8_t> texels;   // resolution^2 texels in `format`, row 0 first
    // The lookup's samplers of the map (sampler2DArray, sampler2DArrayShadow): the exported binding, its sampler.
    std::vector<std::pair<std::uint32_t, VkRunSampler>> maps;
    std::vector<glm::vec4> points;      // per point: world position (xyz), then its normal (xyz)
};

struct LookupPassResult {
    bool noDevice = false;
    std::string error;
    std::string deviceName;
    std::vector<float> shadow;  // one per point
};

LookupPassResult runLookupVulkan(const LookupPassInput& input);

// glslangValidator -V of a compute shader's text: its SPIR-V words, or empty with `error` set.
std::vector<std::uint32_t> compileCompute(const std::string& text, const std::string& name, std::string& error);

}  // namespace shadowlab::test
