#include "vulkan_depth_pass.h"

#include "vulkan_support.h"

#include "shadow_depth_vk.vert.h"  // glslangValidator -V output: shadowDepthVkVert[]

#include <cstdlib>
#include <cstring>
#include <functional>
#include <map>
#include <sstream>
#include <stdexcept>

namespace shadowlab::test {

VulkanRaster parseVulkanRaster(const std::string& snippet, std::string& error) {
    static const std::map<std::string, std::uint32_t> tokens = {
        {"VK_TRUE", VK_TRUE},
        {"VK_FALSE", VK_FALSE},
        {"VK_CULL_MODE_NONE", VK_CULL_MODE_NONE},
        {"VK_CULL_MODE_BACK_BIT", VK_CULL_MODE_BACK_BIT},
        {"VK_CULL_MODE_FRONT_BIT", VK_CULL_MODE_FRONT_BIT},
        {"VK_FRONT_FACE_CLOCKWISE", VK_FRONT_FACE_CLOCKWISE},
        {"VK_FRONT_FACE_COUNTER_CLOCKWISE", VK_FRONT_FACE_COUNTER_CLOCKWISE},
        {"VK_POLYGON_MODE_FILL", VK_POLYGON_MODE_FILL}};
    VulkanRaster r;
    std::istringstream in(snippet);
    std::string line;
    int found = 0;
    while (std::getline(in, line)) {
        const std::string prefix = "shadowRaster.";
        if (line.rfind(prefix, 0) != 0) continue;
        const std::size_t eq = line.find(" = ");
        const std::size_t semi = line.find(';');
        if (eq == std::string::npos || semi == std::string::npos) {
            error = "cannot read: " + line;
            return r;
        }
        const std::string field = line.substr(prefix.size(), eq - prefix.size());
        const std::string value = line.substr(eq + 3, semi - eq - 3);
        const auto token = tokens.find(value);
        const std::uint32_t asToken = token != tokens.end() ? token->second : 0;
        const float asFloat = token == tokens.end() ? std::strtof(value.c_str(), nullptr) : 0.0f;
        ++found;
        if (field == "depthClampEnable") r.depthClampEnable = asToken;
        else if (field == "cullMode") r.cullMode = asToken;
        else if (field == "frontFace") r.frontFace = VkFrontFace(asToken);
        else if (field == "depthBiasEnable") r.depthBiasEnable = asToken;
        else if (field == "depthBiasConstantFactor") r.depthBiasConstantFactor = asFloat;
        else if (field == "depthBiasClamp") r.depthBiasClamp = asFloat;
        else if (field == "depthBiasSlopeFactor") r.depthBiasSlopeFactor = asFloat;
        else --found;
    }
    if (found != 7) error = "expected 7 rasterizer fields in the snippet, found " + std::to_string(found);
    return r;
}

VulkanPassState parseVulkanPassState(const std::string& snippet, const std::string& matrixName, std::string& error) {
    VulkanPassState state;
    const bool greater = snippet.find("depthCompareOp = VK_COMPARE_OP_GREATER; clear depth 0.0.") != std::string::npos;
    const bool less = snippet.find("depthCompareOp = VK_COMPARE_OP_LESS; clear depth 1.0.") != std::string::npos;
    if (greater == less) {
        error = "the snippet states no single depth test (VK_COMPARE_OP_LESS / GREATER)";
        return state;
    }
    state.reversedZ = greater;
    const std::string head = "static const float " + matrixName + "[16] = {";
    const std::size_t at = snippet.find(head);
    if (at == std::string::npos) {
        error = "no matrix " + matrixName + " in the snippet";
        return state;
    }
    const char* p = snippet.c_str() + at + head.size();
    for (int i = 0; i < 16; ++i) {
        char* end = nullptr;
        const float v = std::strtof(p, &end);
        if (end == p) {
            error = "cannot read element " + std::to_string(i) + " of " + matrixName;
            return state;
        }
        state.viewProjection[i / 4][i % 4] = v;
        p = end;
        while (*p == 'f' || *p == ',' || *p == ' ') ++p;
    }
    return state;
}

DepthPassResult renderDepthVulkan(const DepthPassInput& input) {
    DepthPassResult result;
    VkCleanup cleanup;
    try {
        const VkFirstDevice first = vkFirstDevice(cleanup, "shadowlab-vulkan-check");
        if (!first.gpu) {
            result.noDevice = true;
            result.error = first.error;
            return result;
        }
        const VkPhysicalDevice gpu = first.gpu;
        VkPhysicalDeviceProperties props;
        vkGetPhysicalDeviceProperties(gpu, &props);
        result.deviceName = props.deviceName;
        result.subPixelPrecisionBits = int(props.limits.subPixelPrecisionBits);
        VkPhysicalDeviceFeatures available;
        vkGetPhysicalDeviceFeatures(gpu, &available);
        if (input.raster.depthClampEnable && !available.depthClamp) throw std::runtime_error("device lacks depthClamp");
        if (input.raster.depthBiasClamp != 0.0f && !available.depthBiasClamp)
            throw std::runtime_error("device lacks depthBiasClamp");
        VkFormatProperties formatProps;
        vkGetPhysicalDeviceFormatProperties(gpu, input.format, &formatProps);
        if (!(formatProps.optimalTilingFeatures & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT))
            throw std::runtime_error("depth format not renderable on " + result.deviceName);

        if (input.glClipDepth) {
            if (!vkHasExtension(gpu, VK_EXT_DEPTH_CLIP_CONTROL_EXTENSION_NAME)) {
                result.unsupported = true;
                result.error = result.deviceName + " lacks " VK_EXT_DEPTH_CLIP_CONTROL_EXTENSION_NAME;
                return result;
            }
        }
        std::uint32_t familyCount = 0;
        vkGetPhysicalDeviceQueueFamilyProperties(gpu, &familyCount, nullptr);
        std::vector<VkQueueFamilyProperties> families(familyCount);
        vkGetPhysicalDeviceQueueFamilyProperties(gpu, &familyCount, families.data());
        std::uint32_t family = familyCount;
        for (std::uint32_t i = 0; i < familyCount; ++i)
            if (families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) {
                family = i;
                break;
            }
        if (family == familyCount) throw std::runtime_error("no graphics queue");
        const float priority = 1.0f;
        VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
        queueInfo.queueFamilyIndex = family;
        queueInfo.queueCount = 1;
        queueInfo.pQueuePriorities = &priority;
        VkPhysicalDeviceFeatures features{};
        features.depthClamp = input.raster.depthClampEnable;
        features.depthBiasClamp = input.raster.depthBiasClamp != 0.0f ? VK_TRUE : VK_FALSE;
        VkDeviceCreateInfo deviceInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
        deviceInfo.queueCreateInfoCount = 1;
        deviceInfo.pQueueCreateInfos = &queueInfo;
        deviceInfo.pEnabledFeatures = &features;
        VkPhysicalDeviceDepthClipControlFeaturesEXT clipControl{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DEPTH_CLIP_CONTROL_FEATURES_EXT};
        clipControl.depthClipControl = VK_TRUE;
        const char* clipControlName = VK_EXT_DEPTH_CLIP_CONTROL_EXTENSION_NAME;
        if (input.glClipDepth) {
            deviceInfo.pNext = &clipControl;
            deviceInfo.enabledExtensionCount = 1;
            deviceInfo.ppEnabledExtensionNames = &clipControlName;
        }
        VkDevice device = VK_NULL_HANDLE;
        vkCheck(vkCreateDevice(gpu, &deviceInfo, nullptr, &device), "vkCreateDevice");
        cleanup.steps.push_back([=] { vkDestroyDevice(device, nullptr); });
        VkQueue queue = VK_NULL_HANDLE;
        vkGetDeviceQueue(device, family, 0, &queue);

        // Host-visible buffers: vertices, indices, the read-back copy.
        auto makeBuffer = [&](VkDeviceSize size, VkBufferUsageFlags usage, const void* data) {
            return vkHostBuffer(gpu, device, cleanup, size, usage, data);
        };
        const auto vertices = makeBuffer(input.positions.size() * sizeof(glm::vec3), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                                         input.positions.data());
        const auto indices = makeBuffer(input.indices.size() * sizeof(std::uint32_t), VK_BUFFER_USAGE_INDEX_BUFFER_BIT,
                                        input.indices.data());
        const std::uint32_t res = std::uint32_t(input.resolution);
        const bool d16 = input.format == VK_FORMAT_D16_UNORM;
        const VkDeviceSize texelBytes = d16 ? 2 : 4;
        const auto readback = makeBuffer(VkDeviceSize(res) * res * texelBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, nullptr);

        VkImageCreateInfo imageInfo{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
        imageInfo.imageType = VK_IMAGE_TYPE_2D;
        imageInfo.format = input.format;
        imageInfo.extent = {res, res, 1};
        imageInfo.mipLevels = 1;
        imageInfo.arrayLayers = 1;
        imageInfo.samples = VK_SAMPLE_COUNT_1_BIT;
        imageInfo.tiling = VK_IMAGE_TILING_OPTIMAL;
        imageInfo.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        VkImage image = VK_NULL_HANDLE;
        vkCheck(vkCreateImage(device, &imageInfo, nullptr, &image), "vkCreateImage");
        cleanup.steps.push_back([=] { vkDestroyImage(device, image, nullptr); });
        VkMemoryRequirements imageReq;
        vkGetImageMemoryRequirements(device, image, &imageReq);
        VkMemoryAllocateInfo imageAlloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        imageAlloc.allocationSize = imageReq.size;
        imageAlloc.memoryTypeIndex = vkMemoryType(gpu, imageReq.memoryTypeBits, 0);
        VkDeviceMemory imageMemory = VK_NULL_HANDLE;
        vkCheck(vkAllocateMemory(device, &imageAlloc, nullptr, &imageMemory), "vkAllocateMemory (image)");
        cleanup.steps.push_back([=] { vkFreeMemory(device, imageMemory, nullptr); });
        vkCheck(vkBindImageMemory(device, image, imageMemory, 0), "vkBindImageMemory");
        VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        viewInfo.image = image;
        viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
        viewInfo.format = input.format;
        viewInfo.subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1};
        VkImageView view = VK_NULL_HANDLE;
        vkCheck(vkCreateImageView(device, &viewInfo, nullptr, &view), "vkCreateImageView");
        cleanup.steps.push_back([=] { vkDestroyImageView(device, view, nullptr); });

        VkAttachmentDescription depthAttachment{};
        depthAttachment.format = input.format;
        depthAttachment.samples = VK_SAMPLE_COUNT_1_BIT;
        depthAttachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        depthAttachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        depthAttachment.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
        depthAttachment.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
        depthAttachment.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        depthAttachment.finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
        VkAttachmentReference depthRef{0, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
        VkSubpassDescription subpass{};
        subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
        subpass.pDepthStencilAttachment = &depthRef;
        VkSubpassDependency toCopy{};
        toCopy.srcSubpass = 0;
        toCopy.dstSubpass = VK_SUBPASS_EXTERNAL;
        toCopy.srcStageMask = VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
        toCopy.dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
        toCopy.srcAccessMask = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
        toCopy.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
        VkRenderPassCreateInfo passInfo{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
        passInfo.attachmentCount = 1;
        passInfo.pAttachments = &depthAttachment;
        passInfo.subpassCount = 1;
        passInfo.pSubpasses = &subpass;
        passInfo.dependencyCount = 1;
        passInfo.pDependencies = &toCopy;
        VkRenderPass renderPass = VK_NULL_HANDLE;
        vkCheck(vkCreateRenderPass(device, &passInfo, nullptr, &renderPass), "vkCreateRenderPass");
        cleanup.steps.push_back([=] { vkDestroyRenderPass(device, renderPass, nullptr); });
        VkFramebufferCreateInfo fbInfo{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
        fbInfo.renderPass = renderPass;
        fbInfo.attachmentCount = 1;
        fbInfo.pAttachments = &view;
        fbInfo.width = res;
        fbInfo.height = res;
        fbInfo.layers = 1;
        VkFramebuffer framebuffer = VK_NULL_HANDLE;
        vkCheck(vkCreateFramebuffer(device, &fbInfo, nullptr, &framebuffer), "vkCreateFramebuffer");
        cleanup.steps.push_back([=] { vkDestroyFramebuffer(device, framebuffer, nullptr); });

        VkShaderModuleCreateInfo moduleInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
        moduleInfo.codeSize = sizeof(shadowDepthVkVert);
        moduleInfo.pCode = shadowDepthVkVert;
        VkShaderModule module = VK_NULL_HANDLE;
        vkCheck(vkCreateShaderModule(device, &moduleInfo, nullptr, &module), "vkCreateShaderModule");
        cleanup.steps.push_back([=] { vkDestroyShaderModule(device, module, nullptr); });
        VkPushConstantRange pushRange{VK_SHADER_STAGE_VERTEX_BIT, 0, 2 * sizeof(glm::mat4)};
        VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
        layoutInfo.pushConstantRangeCount = 1;
        layoutInfo.pPushConstantRanges = &pushRange;
        VkPipelineLayout layout = VK_NULL_HANDLE;
        vkCheck(vkCreatePipelineLayout(device, &layoutInfo, nullptr, &layout), "vkCreatePipelineLayout");
        cleanup.steps.push_back([=] { vkDestroyPipelineLayout(device, layout, nullptr); });

        // One pipeline per (cull mode, front face) the draws need: the exported state, with double-sided
        // materials unculled and mirrored instances' front face flipped, as in ShadowLab's GL pass.
        std::map<std::pair<VkCullModeFlags, VkFrontFace>, VkPipeline> pipelines;
        auto pipelineFor = [&](const DepthDraw& draw) {
            const VkCullModeFlags cull = draw.doubleSided ? VkCullModeFlags(VK_CULL_MODE_NONE) : input.raster.cullMode;
            VkFrontFace front = input.raster.frontFace;
            if (draw.mirrored)
                front = front == VK_FRONT_FACE_CLOCKWISE ? VK_FRONT_FACE_COUNTER_CLOCKWISE : VK_FRONT_FACE_CLOCKWISE;
            auto& pipeline = pipelines[{cull, front}];
            if (pipeline != VK_NULL_HANDLE) return pipeline;
            VkPipelineShaderStageCreateInfo stage{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
            stage.stage = VK_SHADER_STAGE_VERTEX_BIT;
            stage.module = module;
            stage.pName = "main";
            const VkBool32 remapDepth = input.glClipDepth || input.matrixZeroToOne ? VK_FALSE : VK_TRUE;
            const VkSpecializationMapEntry remapEntry{0, 0, sizeof(VkBool32)};
            const VkSpecializationInfo specialization{1, &remapEntry, sizeof remapDepth, &remapDepth};
            stage.pSpecializationInfo = &specialization;
            VkVertexInputBindingDescription binding{0, sizeof(glm::vec3), VK_VERTEX_INPUT_RATE_VERTEX};
            VkVertexInputAttributeDescription attribute{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0};
            VkPipelineVertexInputStateCreateInfo vertexInput{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
            vertexInput.vertexBindingDescriptionCount = 1;
            vertexInput.pVertexBindingDescriptions = &binding;
            vertexInput.vertexAttributeDescriptionCount = 1;
            vertexInput.pVertexAttributeDescriptions = &attribute;
            VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
            assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
            // Positive height: framebuffer row 0 is clip y = -1, like GL's row 0 (hence the exported CLOCKWISE).
            VkViewport viewport{0.0f, 0.0f, float(res), float(res), 0.0f, 1.0f};
            VkRect2D scissor{{0, 0}, {res, res}};
            VkPipelineViewportStateCreateInfo viewportState{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
            viewportState.viewportCount = 1;
            viewportState.pViewports = &viewport;
            viewportState.scissorCount = 1;
            viewportState.pScissors = &scissor;
            VkPipelineViewportDepthClipControlCreateInfoEXT negativeOneToOne{
                VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_DEPTH_CLIP_CONTROL_CREATE_INFO_EXT};
            negativeOneToOne.negativeOneToOne = VK_TRUE;
            if (input.glClipDepth) viewportState.pNext = &negativeOneToOne;
            VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
            raster.depthClampEnable = input.raster.depthClampEnable;
            raster.polygonMode = VK_POLYGON_MODE_FILL;
            raster.cullMode = cull;
            raster.frontFace = front;
            raster.depthBiasEnable = input.raster.depthBiasEnable;
            raster.depthBiasConstantFactor = input.raster.depthBiasConstantFactor;
            raster.depthBiasClamp = input.raster.depthBiasClamp;
            raster.depthBiasSlopeFactor = input.raster.depthBiasSlopeFactor;
            raster.lineWidth = 1.0f;
            VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
            multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
            VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
            depth.depthTestEnable = VK_TRUE;
            depth.depthWriteEnable = VK_TRUE;
            depth.depthCompareOp = input.reversedZ ? VK_COMPARE_OP_GREATER : VK_COMPARE_OP_LESS;
            VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
            VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
            info.stageCount = 1;
            info.pStages = &stage;
            info.pVertexInputState = &vertexInput;
            info.pInputAssemblyState = &assembly;
            info.pViewportState = &viewportState;
            info.pRasterizationState = &raster;
            info.pMultisampleState = &multisample;
            info.pDepthStencilState = &depth;
            info.pColorBlendState = &blend;
            info.layout = layout;
            info.renderPass = renderPass;
            vkCheck(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline),
                  "vkCreateGraphicsPipelines");
            const VkPipeline created = pipeline;
            cleanup.steps.push_back([=] { vkDestroyPipeline(device, created, nullptr); });
            return pipeline;
        };

        VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
        poolInfo.queueFamilyIndex = family;
        VkCommandPool pool = VK_NULL_HANDLE;
        vkCheck(vkCreateCommandPool(device, &poolInfo, nullptr, &pool), "vkCreateCommandPool");
        cleanup.steps.push_back([=] { vkDestroyCommandPool(device, pool, nullptr); });
        VkCommandBufferAllocateInfo cbInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        cbInfo.commandPool = pool;
        cbInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        cbInfo.commandBufferCount = 1;
        VkCommandBuffer cb = VK_NULL_HANDLE;
        vkCheck(vkAllocateCommandBuffers(device, &cbInfo, &cb), "vkAllocateCommandBuffers");
        VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        vkCheck(vkBeginCommandBuffer(cb, &begin), "vkBeginCommandBuffer");
        VkClearValue clear{};
        clear.depthStencil = {input.reversedZ ? 0.0f : 1.0f, 0};
        VkRenderPassBeginInfo passBegin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
        passBegin.renderPass = renderPass;
        passBegin.framebuffer = framebuffer;
        passBegin.renderArea = {{0, 0}, {res, res}};
        passBegin.clearValueCount = 1;
        passBegin.pClearValues = &clear;
        for (const DepthDraw& draw : input.draws) pipelineFor(draw);  // created before recording
        vkCmdBeginRenderPass(cb, &passBegin, VK_SUBPASS_CONTENTS_INLINE);
        const VkDeviceSize zero = 0;
        vkCmdBindVertexBuffers(cb, 0, 1, &vertices.first, &zero);
        vkCmdBindIndexBuffer(cb, indices.first, 0, VK_INDEX_TYPE_UINT32);
        for (const DepthDraw& draw : input.draws) {
            vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelineFor(draw));
            const glm::mat4 push[2] = {input.lightViewProjection, draw.model};
            vkCmdPushConstants(cb, layout, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof push, push);
            vkCmdDrawIndexed(cb, draw.indexCount, 1, draw.firstIndex, draw.baseVertex, 0);
        }
        vkCmdEndRenderPass(cb);
        VkBufferImageCopy copy{};
        copy.imageSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, 1};
        copy.imageExtent = {res, res, 1};
        vkCmdCopyImageToBuffer(cb, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.first, 1, &copy);
        VkBufferMemoryBarrier toHost{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
        toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        toHost.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        toHost.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        toHost.buffer = readback.first;
        toHost.size = VK_WHOLE_SIZE;
        vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1, &toHost,
                             0, nullptr);
        vkCheck(vkEndCommandBuffer(cb), "vkEndCommandBuffer");
        VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        VkFence fence = VK_NULL_HANDLE;
        vkCheck(vkCreateFence(device, &fenceInfo, nullptr, &fence), "vkCreateFence");
        cleanup.steps.push_back([=] { vkDestroyFence(device, fence, nullptr); });
        VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
        submit.commandBufferCount = 1;
        submit.pCommandBuffers = &cb;
        vkCheck(vkQueueSubmit(queue, 1, &submit, fence), "vkQueueSubmit");
        vkCheck(vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");

        void* mapped = nullptr;
        vkCheck(vkMapMemory(device, readback.second, 0, VK_WHOLE_SIZE, 0, &mapped), "vkMapMemory (read back)");
        result.depth.resize(std::size_t(res) * res);
        for (std::size_t i = 0; i < result.depth.size(); ++i) {
            if (d16) {
                std::uint16_t v;
                std::memcpy(&v, static_cast<const char*>(mapped) + i * 2, 2);
                result.depth[i] = float(double(v) / 65535.0);
            } else {
                std::memcpy(&result.depth[i], static_cast<const char*>(mapped) + i * 4, 4);
            }
        }
        vkUnmapMemory(device, readback.second);
    } catch (const std::exception& e) {
        result.error = e.what();
        result.depth.clear();
    }
    return result;
}

}  // namespace shadowlab::test
