#include "vulkan_compute_pass.h"

#include "vulkan_support.h"

#include <algorithm>
#include <stdexcept>

namespace shadowlab::test {

namespace {

bool vkRunIsDepth(VkFormat format) {
    return format == VK_FORMAT_D32_SFLOAT || format == VK_FORMAT_D16_UNORM || format == VK_FORMAT_X8_D24_UNORM_PACK32;
}

bool vkRunStandardBorder(const glm::vec4& border) { return border == glm::vec4(0.0f) || border == glm::vec4(1.0f); }

std::size_t vkRunLevelBytes(const VkRunImage& image, int level) {
    const std::size_t side = std::size_t(std::max(image.size >> level, 1));
    return side * side * std::size_t(image.texelBytes);
}

}  // namespace

std::vector<std::uint8_t> std140Array(const std::vector<float>& values) {
    std::vector<std::uint8_t> bytes(std::max<std::size_t>(values.size(), 1) * 16, 0);
    for (std::size_t i = 0; i < values.size(); ++i) std::memcpy(bytes.data() + 16 * i, &values[i], 4);
    return bytes;
}

VkRunResult runComputeVulkan(const VkRun& run) {
    VkRunResult result;
    VkCleanup cleanup;
    try {
        const VkFirstDevice first = vkFirstDevice(cleanup, "shadowlab-vulkan-compute-check");
        if (!first.gpu) {
            result.noDevice = true;
            result.error = first.error;
            return result;
        }
        const VkPhysicalDevice gpu = first.gpu;
        result.deviceName = first.name;
        std::uint32_t familyCount = 0;
        vkGetPhysicalDeviceQueueFamilyProperties(gpu, &familyCount, nullptr);
        std::vector<VkQueueFamilyProperties> families(familyCount);
        vkGetPhysicalDeviceQueueFamilyProperties(gpu, &familyCount, families.data());
        std::uint32_t family = familyCount;
        for (std::uint32_t i = 0; i < familyCount && family == familyCount; ++i)
            if (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) family = i;
        if (family == familyCount) throw std::runtime_error("no compute queue");
        // A border that is neither transparent black nor opaque white needs VK_EXT_custom_border_color.
        bool customBorders = false;
        for (const VkRunDispatch& d : run.dispatches)
            for (const VkRunBinding& b : d.bindings)
                customBorders |= b.type == VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER && !vkRunStandardBorder(b.sampler.border);
        const char* customBorderName = VK_EXT_CUSTOM_BORDER_COLOR_EXTENSION_NAME;
        if (customBorders && !vkHasExtension(gpu, customBorderName))
            throw std::runtime_error(result.deviceName + " lacks " + customBorderName);
        const float priority = 1.0f;
        VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
        queueInfo.queueFamilyIndex = family;
        queueInfo.queueCount = 1;
        queueInfo.pQueuePriorities = &priority;
        VkPhysicalDeviceCustomBorderColorFeaturesEXT borderFeature{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_CUSTOM_BORDER_COLOR_FEATURES_EXT};
        borderFeature.customBorderColors = VK_TRUE;
        VkDeviceCreateInfo deviceInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
        deviceInfo.queueCreateInfoCount = 1;
        deviceInfo.pQueueCreateInfos = &queueInfo;
        if (customBorders) {
            deviceInfo.pNext = &borderFeature;
            deviceInfo.enabledExtensionCount = 1;
            deviceInfo.ppEnabledExtensionNames = &customBorderName;
        }
        VkDevice device = VK_NULL_HANDLE;
        vkCheck(vkCreateDevice(gpu, &deviceInfo, nullptr, &device), "vkCreateDevice");
        cleanup.steps.push_back([=] { vkDestroyDevice(device, nullptr); });
        VkQueue queue = VK_NULL_HANDLE;
        vkGetDeviceQueue(device, family, 0, &queue);

        // Buffers: host-visible, every usage a binding may ask for.
        std::vector<std::pair<VkBuffer, VkDeviceMemory>> buffers;
        for (const std::vector<std::uint8_t>& contents : run.buffers)
            buffers.push_back(vkHostBuffer(gpu, device, cleanup, contents.size(),
                                           VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                           contents.data()));

        // Images: one layer, their levels; uploaded (or cleared) and left in GENERAL for every later use.
        std::vector<VkImage> images;
        std::vector<VkBuffer> staging(run.images.size(), VK_NULL_HANDLE);
        std::vector<VkBuffer> readBack(run.images.size(), VK_NULL_HANDLE);
        std::vector<VkDeviceMemory> readBackMemory(run.images.size(), VK_NULL_HANDLE);
        for (std::size_t i = 0; i < run.images.size(); ++i) {
            const VkRunImage& spec = run.images[i];
            const bool depth = vkRunIsDepth(spec.format);
            VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
            info.imageType = VK_IMAGE_TYPE_2D;
            info.format = spec.format;
            info.extent = {std::uint32_t(spec.size), std::uint32_t(spec.size), 1};
            info.mipLevels = std::uint32_t(spec.levels);
            info.arrayLayers = 1;
            info.samples = VK_SAMPLE_COUNT_1_BIT;
            info.tiling = VK_IMAGE_TILING_OPTIMAL;
            info.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                         (depth ? 0u : VK_IMAGE_USAGE_STORAGE_BIT);
            VkImage image = VK_NULL_HANDLE;
            vkCheck(vkCreateImage(device, &info, nullptr, &image), "vkCreateImage");
            cleanup.steps.push_back([=] { vkDestroyImage(device, image, nullptr); });
            VkMemoryRequirements req;
            vkGetImageMemoryRequirements(device, image, &req);
            VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
            alloc.allocationSize = req.size;
            alloc.memoryTypeIndex = vkMemoryType(gpu, req.memoryTypeBits, 0);
            VkDeviceMemory memory = VK_NULL_HANDLE;
            vkCheck(vkAllocateMemory(device, &alloc, nullptr, &memory), "vkAllocateMemory (image)");
            cleanup.steps.push_back([=] { vkFreeMemory(device, memory, nullptr); });
            vkCheck(vkBindImageMemory(device, image, memory, 0), "vkBindImageMemory");
            images.push_back(image);
            if (!spec.texels.empty())
                staging[i] = vkHostBuffer(gpu, device, cleanup, spec.texels.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                          spec.texels.data()).first;
            if (!depth) {
                std::size_t bytes = 0;
                for (int level = 0; level < spec.levels; ++level) bytes += vkRunLevelBytes(spec, level);
                const auto back = vkHostBuffer(gpu, device, cleanup, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, nullptr);
                readBack[i] = back.first;
                readBackMemory[i] = back.second;
            }
        }

        // Descriptors and a pipeline per dispatch.
        std::vector<VkDescriptorPoolSize> poolSizes = {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 64},
                                                       {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 64},
                                                       {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 64},
                                                       {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 64}};
        VkDescriptorPoolCreateInfo descriptorPoolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
        descriptorPoolInfo.maxSets = std::uint32_t(std::max<std::size_t>(run.dispatches.size(), 1));
        descriptorPoolInfo.poolSizeCount = std::uint32_t(poolSizes.size());
        descriptorPoolInfo.pPoolSizes = poolSizes.data();
        VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
        vkCheck(vkCreateDescriptorPool(device, &descriptorPoolInfo, nullptr, &descriptorPool), "vkCreateDescriptorPool");
        cleanup.steps.push_back([=] { vkDestroyDescriptorPool(device, descriptorPool, nullptr); });
        struct Prepared { VkPipeline pipeline; VkPipelineLayout layout; VkDescriptorSet set; };
        std::vector<Prepared> prepared;
        for (const VkRunDispatch& dispatch : run.dispatches) {
            std::vector<VkDescriptorSetLayoutBinding> layoutBindings;
            for (const VkRunBinding& b : dispatch.bindings)
                layoutBindings.push_back({b.binding, b.type, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
            VkDescriptorSetLayoutCreateInfo setLayoutInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
            setLayoutInfo.bindingCount = std::uint32_t(layoutBindings.size());
            setLayoutInfo.pBindings = layoutBindings.data();
            VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
            vkCheck(vkCreateDescriptorSetLayout(device, &setLayoutInfo, nullptr, &setLayout), "vkCreateDescriptorSetLayout");
            cleanup.steps.push_back([=] { vkDestroyDescriptorSetLayout(device, setLayout, nullptr); });
            VkDescriptorSetAllocateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
            setInfo.descriptorPool = descriptorPool;
            setInfo.descriptorSetCount = 1;
            setInfo.pSetLayouts = &setLayout;
            VkDescriptorSet set = VK_NULL_HANDLE;
            vkCheck(vkAllocateDescriptorSets(device, &setInfo, &set), "vkAllocateDescriptorSets");
            // Every write's info must outlive vkUpdateDescriptorSets: reserved up front.
            std::vector<VkDescriptorImageInfo> imageInfos;
            std::vector<VkDescriptorBufferInfo> bufferInfos;
            imageInfos.reserve(dispatch.bindings.size());
            bufferInfos.reserve(dispatch.bindings.size());
            std::vector<VkWriteDescriptorSet> writes;
            for (const VkRunBinding& b : dispatch.bindings) {
                VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
                w.dstSet = set;
                w.dstBinding = b.binding;
                w.descriptorCount = 1;
                w.descriptorType = b.type;
                if (b.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER || b.type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER) {
                    bufferInfos.push_back({buffers.at(std::size_t(b.buffer)).first, 0, VK_WHOLE_SIZE});
                    w.pBufferInfo = &bufferInfos.back();
                } else {
                    const VkRunImage& spec = run.images.at(std::size_t(b.image));
                    const bool sampled = b.type == VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
                    VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
                    viewInfo.image = images[std::size_t(b.image)];
                    viewInfo.viewType = sampled ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D;
                    viewInfo.format = spec.format;
                    viewInfo.subresourceRange = {
                        VkImageAspectFlags(vkRunIsDepth(spec.format) ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT),
                        sampled ? 0u : std::uint32_t(b.level), sampled ? std::uint32_t(spec.levels) : 1u, 0, 1};
                    VkImageView view = VK_NULL_HANDLE;
                    vkCheck(vkCreateImageView(device, &viewInfo, nullptr, &view), "vkCreateImageView");
                    cleanup.steps.push_back([=] { vkDestroyImageView(device, view, nullptr); });
                    VkSampler sampler = VK_NULL_HANDLE;
                    if (sampled) {
                        const VkRunSampler& s = b.sampler;
                        VkSamplerCustomBorderColorCreateInfoEXT custom{VK_STRUCTURE_TYPE_SAMPLER_CUSTOM_BORDER_COLOR_CREATE_INFO_EXT};
                        std::memcpy(custom.customBorderColor.float32, &s.border.x, sizeof(float) * 4);
                        custom.format = spec.format;
                        VkSamplerCreateInfo samplerInfo{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
                        samplerInfo.magFilter = samplerInfo.minFilter = s.linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
                        samplerInfo.mipmapMode = s.mipmap;
                        samplerInfo.addressModeU = samplerInfo.addressModeV = samplerInfo.addressModeW = s.address;
                        samplerInfo.maxLod = s.maxLod;
                        samplerInfo.compareEnable = s.compare ? VK_TRUE : VK_FALSE;
                        samplerInfo.compareOp = s.compareOp;
                        samplerInfo.borderColor = s.border == glm::vec4(1.0f) ? VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE
                                                  : vkRunStandardBorder(s.border)  ? VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK
                                                                              : VK_BORDER_COLOR_FLOAT_CUSTOM_EXT;
                        if (!vkRunStandardBorder(s.border)) samplerInfo.pNext = &custom;
                        vkCheck(vkCreateSampler(device, &samplerInfo, nullptr, &sampler), "vkCreateSampler");
                        cleanup.steps.push_back([=] { vkDestroySampler(device, sampler, nullptr); });
                    }
                    imageInfos.push_back({sampler, view, VK_IMAGE_LAYOUT_GENERAL});
                    w.pImageInfo = &imageInfos.back();
                }
                writes.push_back(w);
            }
            vkUpdateDescriptorSets(device, std::uint32_t(writes.size()), writes.data(), 0, nullptr);

            VkShaderModuleCreateInfo moduleInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
            moduleInfo.codeSize = dispatch.spirv.size() * 4;
            moduleInfo.pCode = dispatch.spirv.data();
            VkShaderModule module = VK_NULL_HANDLE;
            vkCheck(vkCreateShaderModule(device, &moduleInfo, nullptr, &module), "vkCreateShaderModule");
            cleanup.steps.push_back([=] { vkDestroyShaderModule(device, module, nullptr); });
            VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
            layoutInfo.setLayoutCount = 1;
            layoutInfo.pSetLayouts = &setLayout;
            VkPipelineLayout layout = VK_NULL_HANDLE;
            vkCheck(vkCreatePipelineLayout(device, &layoutInfo, nullptr, &layout), "vkCreatePipelineLayout");
            cleanup.steps.push_back([=] { vkDestroyPipelineLayout(device, layout, nullptr); });
            VkComputePipelineCreateInfo pipelineInfo{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
            pipelineInfo.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
            pipelineInfo.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
            pipelineInfo.stage.module = module;
            pipelineInfo.stage.pName = "main";
            pipelineInfo.layout = layout;
            VkPipeline pipeline = VK_NULL_HANDLE;
            vkCheck(vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &pipelineInfo, nullptr, &pipeline),
                    "vkCreateComputePipelines");
            cleanup.steps.push_back([=] { vkDestroyPipeline(device, pipeline, nullptr); });
            prepared.push_back({pipeline, layout, set});
        }

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
        // Upload (or clear) every image, then GENERAL for everything after.
        for (std::size_t i = 0; i < images.size(); ++i) {
            const VkRunImage& spec = run.images[i];
            const VkImageAspectFlags aspect = vkRunIsDepth(spec.format) ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
            VkImageMemoryBarrier toCopy{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
            toCopy.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
            toCopy.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
            toCopy.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
            toCopy.srcQueueFamilyIndex = toCopy.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            toCopy.image = images[i];
            toCopy.subresourceRange = {aspect, 0, std::uint32_t(spec.levels), 0, 1};
            vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0,
                                 nullptr, 1, &toCopy);
            if (staging[i]) {
                VkBufferImageCopy copy{};
                copy.imageSubresource = {aspect, 0, 0, 1};
                copy.imageExtent = {std::uint32_t(spec.size), std::uint32_t(spec.size), 1};
                vkCmdCopyBufferToImage(cb, staging[i], images[i], VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
            } else if (!vkRunIsDepth(spec.format)) {
                const VkClearColorValue zero{};
                vkCmdClearColorImage(cb, images[i], VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &zero, 1, &toCopy.subresourceRange);
            }
            VkImageMemoryBarrier toGeneral = toCopy;
            toGeneral.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
            toGeneral.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
            toGeneral.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
            toGeneral.newLayout = VK_IMAGE_LAYOUT_GENERAL;
            vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 0, nullptr,
                                 0, nullptr, 1, &toGeneral);
        }
        // Each dispatch sees what the one before wrote.
        VkMemoryBarrier between{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        between.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
        between.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
        for (std::size_t d = 0; d < run.dispatches.size(); ++d) {
            vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_COMPUTE, prepared[d].pipeline);
            vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_COMPUTE, prepared[d].layout, 0, 1, &prepared[d].set, 0,
                                    nullptr);
            vkCmdDispatch(cb, run.dispatches[d].groupsX, run.dispatches[d].groupsY, 1);
            vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1,
                                 &between, 0, nullptr, 0, nullptr);
        }
        // Read back: the images' levels into their buffers; the buffers are host-coherent.
        VkMemoryBarrier toTransfer{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        toTransfer.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
        toTransfer.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_HOST_READ_BIT;
        vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                             VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toTransfer, 0, nullptr,
                             0, nullptr);
        for (std::size_t i = 0; i < images.size(); ++i) {
            if (!readBack[i]) continue;
            const VkRunImage& spec = run.images[i];
            VkDeviceSize offset = 0;
            for (int level = 0; level < spec.levels; ++level) {
                const std::uint32_t side = std::uint32_t(std::max(spec.size >> level, 1));
                VkBufferImageCopy copy{};
                copy.bufferOffset = offset;
                copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, std::uint32_t(level), 0, 1};
                copy.imageExtent = {side, side, 1};
                vkCmdCopyImageToBuffer(cb, images[i], VK_IMAGE_LAYOUT_GENERAL, readBack[i], 1, &copy);
                offset += vkRunLevelBytes(spec, level);
            }
        }
        VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr,
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

        const auto copyOut = [&](VkDeviceMemory memory, std::size_t bytes) {
            std::vector<std::uint8_t> out(bytes);
            void* mapped = nullptr;
            vkCheck(vkMapMemory(device, memory, 0, VK_WHOLE_SIZE, 0, &mapped), "vkMapMemory (read back)");
            std::memcpy(out.data(), mapped, bytes);
            vkUnmapMemory(device, memory);
            return out;
        };
        for (std::size_t i = 0; i < images.size(); ++i) {
            std::size_t bytes = 0;
            for (int level = 0; readBack[i] && level < run.images[i].levels; ++level) bytes += vkRunLevelBytes(run.images[i], level);
            result.images.push_back(readBack[i] ? copyOut(readBackMemory[i], bytes) : std::vector<std::uint8_t>());
        }
        for (std::size_t i = 0; i < buffers.size(); ++i) result.buffers.push_back(copyOut(buffers[i].second, run.buffers[i].size()));
    } catch (const std::exception& e) {
        result.error = e.what();
        result.images.clear();
        result.buffers.clear();
    }
    return result;
}

}  // namespace shadowlab::test
