#include "vulkan_lookup_pass.h"

#include "vulkan_support.h"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <stdexcept>

namespace shadowlab::test {

namespace {

bool hasExtension(VkPhysicalDevice gpu, const char* name) {
    std::uint32_t count = 0;
    vkEnumerateDeviceExtensionProperties(gpu, nullptr, &count, nullptr);
    std::vector<VkExtensionProperties> extensions(count);
    vkEnumerateDeviceExtensionProperties(gpu, nullptr, &count, extensions.data());
    for (const VkExtensionProperties& e : extensions)
        if (std::strcmp(e.extensionName, name) == 0) return true;
    return false;
}

}  // namespace

std::vector<std::uint32_t> compileCompute(const std::string& text, const std::string& name, std::string& error) {
    const std::filesystem::path folder = std::filesystem::path(SHADOWLAB_TEST_OUTPUT) / "export-glsl";
    std::filesystem::create_directories(folder);
    const std::filesystem::path source = folder / (name + ".comp"), spirv = folder / (name + ".spv");
    std::ofstream(source) << text;
    const std::string command = "glslangValidator -V -o '" + spirv.string() + "' '" + source.string() + "' 2>&1";
    std::string log;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) {
        error = "could not run glslangValidator";
        return {};
    }
    char buffer[512];
    while (std::fgets(buffer, sizeof buffer, pipe)) log += buffer;
    if (pclose(pipe) != 0) {
        error = source.string() + ":\n" + log;
        return {};
    }
    std::ifstream in(spirv, std::ios::binary);
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::vector<std::uint32_t> words(bytes.size() / 4);
    std::memcpy(words.data(), bytes.data(), words.size() * 4);
    return words;
}

LookupPassResult runLookupVulkan(const LookupPassInput& input) {
    LookupPassResult result;
    VkCleanup cleanup;
    try {
        VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
        app.pApplicationName = "shadowlab-vulkan-lookup-check";
        app.apiVersion = VK_API_VERSION_1_1;
        VkInstanceCreateInfo instanceInfo{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
        instanceInfo.pApplicationInfo = &app;
        VkInstance instance = VK_NULL_HANDLE;
        if (vkCreateInstance(&instanceInfo, nullptr, &instance) != VK_SUCCESS) {
            result.noDevice = true;
            result.error = "vkCreateInstance failed: no Vulkan implementation";
            return result;
        }
        cleanup.steps.push_back([=] { vkDestroyInstance(instance, nullptr); });
        std::uint32_t count = 0;
        vkEnumeratePhysicalDevices(instance, &count, nullptr);
        if (count == 0) {
            result.noDevice = true;
            result.error = "no Vulkan physical device";
            return result;
        }
        std::vector<VkPhysicalDevice> gpus(count);
        vkEnumeratePhysicalDevices(instance, &count, gpus.data());
        const VkPhysicalDevice gpu = gpus[0];
        VkPhysicalDeviceProperties props;
        vkGetPhysicalDeviceProperties(gpu, &props);
        result.deviceName = props.deviceName;
        std::uint32_t familyCount = 0;
        vkGetPhysicalDeviceQueueFamilyProperties(gpu, &familyCount, nullptr);
        std::vector<VkQueueFamilyProperties> families(familyCount);
        vkGetPhysicalDeviceQueueFamilyProperties(gpu, &familyCount, families.data());
        std::uint32_t family = familyCount;
        for (std::uint32_t i = 0; i < familyCount && family == familyCount; ++i)
            if (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) family = i;
        if (family == familyCount) throw std::runtime_error("no compute queue");
        // A border that is neither transparent black nor opaque white needs VK_EXT_custom_border_color.
        const bool standardBorder = input.border == glm::vec4(0.0f) || input.border == glm::vec4(1.0f);
        const char* customBorderName = VK_EXT_CUSTOM_BORDER_COLOR_EXTENSION_NAME;
        if (!standardBorder && !hasExtension(gpu, customBorderName))
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
        if (!standardBorder) {
            deviceInfo.pNext = &borderFeature;
            deviceInfo.enabledExtensionCount = 1;
            deviceInfo.ppEnabledExtensionNames = &customBorderName;
        }
        VkDevice device = VK_NULL_HANDLE;
        vkCheck(vkCreateDevice(gpu, &deviceInfo, nullptr, &device), "vkCreateDevice");
        cleanup.steps.push_back([=] { vkDestroyDevice(device, nullptr); });
        VkQueue queue = VK_NULL_HANDLE;
        vkGetDeviceQueue(device, family, 0, &queue);

        auto makeBuffer = [&](VkDeviceSize size, VkBufferUsageFlags usage, const void* data) {
            return vkHostBuffer(gpu, device, cleanup, size, usage, data);
        };
        const VkDeviceSize pointBytes = input.points.size() * sizeof(glm::vec4);
        const std::size_t pointCount = input.points.size() / 2;
        const auto points = makeBuffer(pointBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, input.points.data());
        const auto shadows = makeBuffer(pointCount * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, nullptr);
        const auto staging = makeBuffer(input.texels.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, input.texels.data());

        // The map: one 2D-array layer in the exported format, sampled.
        const std::uint32_t res = std::uint32_t(input.resolution);
        VkImageCreateInfo imageInfo{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
        imageInfo.imageType = VK_IMAGE_TYPE_2D;
        imageInfo.format = input.format;
        imageInfo.extent = {res, res, 1};
        imageInfo.mipLevels = 1;
        imageInfo.arrayLayers = 1;
        imageInfo.samples = VK_SAMPLE_COUNT_1_BIT;
        imageInfo.tiling = VK_IMAGE_TILING_OPTIMAL;
        imageInfo.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
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
        viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY;
        viewInfo.format = input.format;
        viewInfo.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        VkImageView view = VK_NULL_HANDLE;
        vkCheck(vkCreateImageView(device, &viewInfo, nullptr, &view), "vkCreateImageView");
        cleanup.steps.push_back([=] { vkDestroyImageView(device, view, nullptr); });

        VkSamplerCustomBorderColorCreateInfoEXT customBorder{VK_STRUCTURE_TYPE_SAMPLER_CUSTOM_BORDER_COLOR_CREATE_INFO_EXT};
        std::memcpy(customBorder.customBorderColor.float32, &input.border.x, sizeof(float) * 4);
        customBorder.format = input.format;
        VkSamplerCreateInfo samplerInfo{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
        samplerInfo.magFilter = VK_FILTER_LINEAR;
        samplerInfo.minFilter = VK_FILTER_LINEAR;
        samplerInfo.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
        samplerInfo.addressModeU = samplerInfo.addressModeV = samplerInfo.addressModeW = input.addressMode;
        samplerInfo.maxLod = 0.0f;
        samplerInfo.borderColor = input.border == glm::vec4(1.0f) ? VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE
                                  : standardBorder                  ? VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK
                                                                    : VK_BORDER_COLOR_FLOAT_CUSTOM_EXT;
        if (!standardBorder) samplerInfo.pNext = &customBorder;
        VkSampler sampler = VK_NULL_HANDLE;
        vkCheck(vkCreateSampler(device, &samplerInfo, nullptr, &sampler), "vkCreateSampler");
        cleanup.steps.push_back([=] { vkDestroySampler(device, sampler, nullptr); });

        // Descriptors: the map, the points, the shadows.
        const VkDescriptorSetLayoutBinding bindings[3] = {
            {input.mapBinding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
            {10, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
            {11, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr}};
        VkDescriptorSetLayoutCreateInfo setLayoutInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
        setLayoutInfo.bindingCount = 3;
        setLayoutInfo.pBindings = bindings;
        VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
        vkCheck(vkCreateDescriptorSetLayout(device, &setLayoutInfo, nullptr, &setLayout), "vkCreateDescriptorSetLayout");
        cleanup.steps.push_back([=] { vkDestroyDescriptorSetLayout(device, setLayout, nullptr); });
        const VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1},
                                               {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2}};
        VkDescriptorPoolCreateInfo descriptorPoolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
        descriptorPoolInfo.maxSets = 1;
        descriptorPoolInfo.poolSizeCount = 2;
        descriptorPoolInfo.pPoolSizes = sizes;
        VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
        vkCheck(vkCreateDescriptorPool(device, &descriptorPoolInfo, nullptr, &descriptorPool), "vkCreateDescriptorPool");
        cleanup.steps.push_back([=] { vkDestroyDescriptorPool(device, descriptorPool, nullptr); });
        VkDescriptorSetAllocateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
        setInfo.descriptorPool = descriptorPool;
        setInfo.descriptorSetCount = 1;
        setInfo.pSetLayouts = &setLayout;
        VkDescriptorSet set = VK_NULL_HANDLE;
        vkCheck(vkAllocateDescriptorSets(device, &setInfo, &set), "vkAllocateDescriptorSets");
        const VkDescriptorImageInfo imageDescriptor{sampler, view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
        const VkDescriptorBufferInfo pointsDescriptor{points.first, 0, VK_WHOLE_SIZE};
        const VkDescriptorBufferInfo shadowsDescriptor{shadows.first, 0, VK_WHOLE_SIZE};
        VkWriteDescriptorSet writes[3] = {};
        for (int i = 0; i < 3; ++i) {
            writes[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
            writes[i].dstSet = set;
            writes[i].dstBinding = bindings[i].binding;
            writes[i].descriptorCount = 1;
            writes[i].descriptorType = bindings[i].descriptorType;
        }
        writes[0].pImageInfo = &imageDescriptor;
        writes[1].pBufferInfo = &pointsDescriptor;
        writes[2].pBufferInfo = &shadowsDescriptor;
        vkUpdateDescriptorSets(device, 3, writes, 0, nullptr);

        VkShaderModuleCreateInfo moduleInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
        moduleInfo.codeSize = input.spirv.size() * 4;
        moduleInfo.pCode = input.spirv.data();
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
        VkImageMemoryBarrier toCopy{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
        toCopy.srcAccessMask = 0;
        toCopy.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        toCopy.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        toCopy.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
        toCopy.srcQueueFamilyIndex = toCopy.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        toCopy.image = image;
        toCopy.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0,
                             nullptr, 1, &toCopy);
        VkBufferImageCopy copy{};
        copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        copy.imageExtent = {res, res, 1};
        vkCmdCopyBufferToImage(cb, staging.first, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
        VkImageMemoryBarrier toRead = toCopy;
        toRead.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        toRead.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
        toRead.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
        toRead.newLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
        vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 0, nullptr, 0,
                             nullptr, 1, &toRead);
        vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
        vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_COMPUTE, layout, 0, 1, &set, 0, nullptr);
        vkCmdDispatch(cb, std::uint32_t((pointCount + 63) / 64), 1, 1);
        VkBufferMemoryBarrier toHost{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
        toHost.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
        toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        toHost.srcQueueFamilyIndex = toHost.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        toHost.buffer = shadows.first;
        toHost.size = VK_WHOLE_SIZE;
        vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1,
                             &toHost, 0, nullptr);
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
        vkCheck(vkMapMemory(device, shadows.second, 0, VK_WHOLE_SIZE, 0, &mapped), "vkMapMemory (read back)");
        result.shadow.resize(pointCount);
        std::memcpy(result.shadow.data(), mapped, pointCount * sizeof(float));
        vkUnmapMemory(device, shadows.second);
    } catch (const std::exception& e) {
        result.error = e.what();
        result.shadow.clear();
    }
    return result;
}

}  // namespace shadowlab::test
