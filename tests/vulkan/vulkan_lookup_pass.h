#pragma once
// A compute dispatch in Vulkan (run on Mesa's lavapipe in the tests): the exported lookup of a moments technique,
// compiled to SPIR-V, reads a map (one sampled 2D-array layer, in the exported format and sampler) at a list of surface
// points and writes S for each. The check that the exported Vulkan GLSL computes ShadowLab's shadow. Not a product path.
#include <vulkan/vulkan.h>

#include <glm/vec4.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace shadowlab::test {

struct LookupPassInput {
    std::vector<std::uint32_t> spirv;   // a compute shader: local_size_x 64, points at binding 10, S at binding 11
    std::uint32_t mapBinding = 0;       // the sampler2DArray the lookup reads (the exported binding)
    VkFormat format = VK_FORMAT_R32G32_SFLOAT;
    int resolution = 0;
    std::vector<std::uint8_t> texels;   // resolution^2 texels in `format`, row 0 first
    VkSamplerAddressMode addressMode = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER;
    glm::vec4 border{0.0f};             // a custom border colour (VK_EXT_custom_border_color) unless 0,0,0,0 or 1,1,1,1
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
