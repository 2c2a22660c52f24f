#pragma once
// A depth-only pass in Vulkan (run on Mesa's lavapipe in the tests): the check that the rasterizer state ShadowLab
// exports for Vulkan renders the same shadow map as ShadowLab's GL pass. Not a product path.
#include <vulkan/vulkan.h>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace shadowlab::test {

// The fields of the exported VkPipelineRasterizationStateCreateInfo that the pass uses.
struct VulkanRaster {
    VkBool32 depthClampEnable = VK_FALSE;
    VkCullModeFlags cullMode = VK_CULL_MODE_NONE;
    VkFrontFace frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    VkBool32 depthBiasEnable = VK_FALSE;
    float depthBiasConstantFactor = 0.0f;
    float depthBiasClamp = 0.0f;
    float depthBiasSlopeFactor = 0.0f;
};

// Reads `shadowRaster.field = value;` lines of an exported snippet; `error` names the first line it cannot read.
VulkanRaster parseVulkanRaster(const std::string& snippet, std::string& error);

// The rest of what the exported snippet says the pass needs: the depth test ("depthCompareOp = ...; clear depth ..."),
// and the view's matrix (`static const float <name>[16] = {...};`, column-major). `error` names what is missing.
struct VulkanPassState {
    bool reversedZ = false;   // VK_COMPARE_OP_GREATER, clear 0.0
    glm::mat4 viewProjection{1.0f};
};
VulkanPassState parseVulkanPassState(const std::string& snippet, const std::string& matrixName, std::string& error);

struct DepthDraw {
    glm::mat4 model{1.0f};
    std::uint32_t firstIndex = 0;
    std::int32_t baseVertex = 0;
    std::uint32_t indexCount = 0;
    bool mirrored = false;     // flips the front face, as ShadowLab's GL pass does
    bool doubleSided = false;  // drawn without culling, as ShadowLab's GL pass does
};

struct DepthPassInput {
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> indices;
    std::vector<DepthDraw> draws;
    glm::mat4 lightViewProjection{1.0f};  // GL clip convention (depth [-1,1]); the shader remaps it
    int resolution = 0;
    VkFormat format = VK_FORMAT_D32_SFLOAT;  // D16_UNORM or D32_SFLOAT
    VulkanRaster raster;
    // false: the [0,1] clip depth an engine uses (the shader remaps GL's z); true: keep GL's [-1,1] clip depth through
    // VK_EXT_depth_clip_control, so only the rasterizer state differs from ShadowLab's GL pass.
    bool glClipDepth = false;
    // true: lightViewProjection already has clip depth [0,1] (the exported matrix: remapped, or reversed-Z's own), so
    // the shader passes it through unchanged.
    bool matrixZeroToOne = false;
    bool reversedZ = false;  // clear to 0, depth test GREATER (the exported depth state for reversed-Z)
};

struct DepthPassResult {
    bool noDevice = false;  // no Vulkan implementation or device at all
    std::string error;
    std::string deviceName;
    int subPixelPrecisionBits = 0;  // the rasterizer snaps vertices to 1/2^bits of a texel
    bool unsupported = false;  // the device lacks what the input asks for (e.g. VK_EXT_depth_clip_control)
    std::vector<float> depth;  // resolution^2, row 0 = clip y -1 (the same order as GL's glGetTextureImage)
};

DepthPassResult renderDepthVulkan(const DepthPassInput& input);

}  // namespace shadowlab::test
