#pragma once
// A chain of compute dispatches in Vulkan (run on Mesa's lavapipe in the tests): images of one layer (sampled and
// stored, with mip levels), host buffers (uniform blocks, storage), and per dispatch a SPIR-V shader with the
// descriptors it reads at the bindings the export names. A barrier between dispatches; images and buffers read back
// at the end. The exported Vulkan shaders (lookups, moments convert / blur / mips) run through it. Not a product path.
#include <vulkan/vulkan.h>

#include <glm/vec4.hpp>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace shadowlab::test {

struct VkRunImage {
    VkFormat format = VK_FORMAT_R32_SFLOAT;  // a depth format (D32) is sampled through its depth aspect
    int size = 0;                            // width = height of level 0
    int levels = 1;
    int texelBytes = 4;
    std::vector<std::uint8_t> texels;        // level 0, row 0 first; empty: starts as zeros
};

struct VkRunSampler {
    bool linear = false;
    VkSamplerMipmapMode mipmap = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    float maxLod = 0.0f;
    VkSamplerAddressMode address = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    glm::vec4 border{0.0f};                  // a custom border colour (VK_EXT_custom_border_color) unless 0 or 1
    bool compare = false;
    VkCompareOp compareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
};

struct VkRunBinding {
    std::uint32_t binding = 0;
    VkDescriptorType type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    int image = -1;        // COMBINED_IMAGE_SAMPLER (a 2D-array view of every level) / STORAGE_IMAGE (a 2D view)
    int level = 0;         // STORAGE_IMAGE: the level written or read
    VkRunSampler sampler;  // COMBINED_IMAGE_SAMPLER
    int buffer = -1;       // UNIFORM_BUFFER / STORAGE_BUFFER
};

struct VkRunDispatch {
    std::vector<std::uint32_t> spirv;
    std::vector<VkRunBinding> bindings;
    std::uint32_t groupsX = 1, groupsY = 1;
};

struct VkRun {
    std::vector<VkRunImage> images;
    std::vector<std::vector<std::uint8_t>> buffers;  // initial contents (an output buffer: its size in zeros)
    std::vector<VkRunDispatch> dispatches;
};

struct VkRunResult {
    bool noDevice = false;
    std::string error;
    std::string deviceName;
    std::vector<std::vector<std::uint8_t>> images;   // per image its levels one after another (depth images: empty)
    std::vector<std::vector<std::uint8_t>> buffers;  // per buffer its contents after the last dispatch
};

VkRunResult runComputeVulkan(const VkRun& run);

// A std140 uniform block holding `values` as an array of 16-byte elements (a float or int array's stride), or one
// value at offset 0 (values of up to 4 words).
std::vector<std::uint8_t> std140Array(const std::vector<float>& values);
template <typename T>
std::vector<std::uint8_t> std140Value(const T& value) {
    std::vector<std::uint8_t> bytes(16, 0);
    static_assert(sizeof(T) <= 16);
    std::memcpy(bytes.data(), &value, sizeof(T));
    return bytes;
}

}  // namespace shadowlab::test
