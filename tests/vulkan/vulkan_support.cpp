#include "vulkan_support.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

namespace shadowlab::test {

void vkCheck(VkResult result, const char* what) {
    if (result != VK_SUCCESS) throw std::runtime_error(std::string(what) + " failed (VkResult " + std::to_string(result) + ")");
}

std::uint32_t vkMemoryType(VkPhysicalDevice gpu, std::uint32_t bits, VkMemoryPropertyFlags flags) {
    VkPhysicalDeviceMemoryProperties props;
    vkGetPhysicalDeviceMemoryProperties(gpu, &props);
    for (std::uint32_t i = 0; i < props.memoryTypeCount; ++i)
        if ((bits & (1u << i)) && (props.memoryTypes[i].propertyFlags & flags) == flags) return i;
    throw std::runtime_error("no suitable Vulkan memory type");
}

std::pair<VkBuffer, VkDeviceMemory> vkHostBuffer(VkPhysicalDevice gpu, VkDevice device, VkCleanup& cleanup,
                                                 VkDeviceSize size, VkBufferUsageFlags usage, const void* data) {
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = std::max<VkDeviceSize>(size, 4);
    info.usage = usage;
    VkBuffer buffer = VK_NULL_HANDLE;
    vkCheck(vkCreateBuffer(device, &info, nullptr, &buffer), "vkCreateBuffer");
    cleanup.steps.push_back([=] { vkDestroyBuffer(device, buffer, nullptr); });
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(device, buffer, &req);
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex =
        vkMemoryType(gpu, req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    VkDeviceMemory memory = VK_NULL_HANDLE;
    vkCheck(vkAllocateMemory(device, &alloc, nullptr, &memory), "vkAllocateMemory");
    cleanup.steps.push_back([=] { vkFreeMemory(device, memory, nullptr); });
    vkCheck(vkBindBufferMemory(device, buffer, memory, 0), "vkBindBufferMemory");
    if (data) {
        void* mapped = nullptr;
        vkCheck(vkMapMemory(device, memory, 0, VK_WHOLE_SIZE, 0, &mapped), "vkMapMemory");
        std::memcpy(mapped, data, std::size_t(size));
        vkUnmapMemory(device, memory);
    }
    return {buffer, memory};
}

VkFirstDevice vkFirstDevice(VkCleanup& cleanup, const char* applicationName) {
    VkFirstDevice first;
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = applicationName;
    app.apiVersion = VK_API_VERSION_1_1;
    VkInstanceCreateInfo instanceInfo{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    instanceInfo.pApplicationInfo = &app;
    VkInstance instance = VK_NULL_HANDLE;
    if (vkCreateInstance(&instanceInfo, nullptr, &instance) != VK_SUCCESS) {
        first.error = "vkCreateInstance failed: no Vulkan implementation";
        return first;
    }
    cleanup.steps.push_back([=] { vkDestroyInstance(instance, nullptr); });
    std::uint32_t count = 0;
    vkEnumeratePhysicalDevices(instance, &count, nullptr);
    if (count == 0) {
        first.error = "no Vulkan physical device";
        return first;
    }
    std::vector<VkPhysicalDevice> gpus(count);
    vkEnumeratePhysicalDevices(instance, &count, gpus.data());
    first.gpu = gpus[0];
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(first.gpu, &props);
    first.name = props.deviceName;
    return first;
}

bool vkHasExtension(VkPhysicalDevice gpu, const char* name) {
    std::uint32_t count = 0;
    vkEnumerateDeviceExtensionProperties(gpu, nullptr, &count, nullptr);
    std::vector<VkExtensionProperties> extensions(count);
    vkEnumerateDeviceExtensionProperties(gpu, nullptr, &count, extensions.data());
    for (const VkExtensionProperties& e : extensions)
        if (std::strcmp(e.extensionName, name) == 0) return true;
    return false;
}

}  // namespace shadowlab::test
