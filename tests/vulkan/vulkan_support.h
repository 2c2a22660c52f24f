#pragma once
// What the Vulkan test passes (vulkan_depth_pass, vulkan_lookup_pass) share: a checked call, destruction in reverse
// order however a pass ends, a memory type, and a host-visible buffer filled from memory.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace shadowlab::test {

// Throws std::runtime_error "WHAT failed (VkResult N)" unless `result` is VK_SUCCESS.
void vkCheck(VkResult result, const char* what);

// Destroys what was created, in reverse order, however the pass ends.
struct VkCleanup {
    std::vector<std::function<void()>> steps;
    ~VkCleanup() {
        for (auto it = steps.rbegin(); it != steps.rend(); ++it) (*it)();
    }
};

// The first memory type among `bits` with every flag of `flags`; throws when there is none.
std::uint32_t vkMemoryType(VkPhysicalDevice gpu, std::uint32_t bits, VkMemoryPropertyFlags flags);

// A host-visible, coherent buffer of `size` bytes (at least 4) for `usage`, bound to its own memory and filled from
// `data` when given; both are destroyed by `cleanup`.
std::pair<VkBuffer, VkDeviceMemory> vkHostBuffer(VkPhysicalDevice gpu, VkDevice device, VkCleanup& cleanup,
                                                 VkDeviceSize size, VkBufferUsageFlags usage, const void* data);

// A Vulkan 1.1 instance (destroyed by `cleanup`) and its first physical device; gpu VK_NULL_HANDLE with `error` set
// when there is no implementation or no device (the caller skips its check).
struct VkFirstDevice {
    VkPhysicalDevice gpu = VK_NULL_HANDLE;
    std::string name;
    std::string error;
};
VkFirstDevice vkFirstDevice(VkCleanup& cleanup, const char* applicationName);

// Whether `gpu` offers the device extension `name`.
bool vkHasExtension(VkPhysicalDevice gpu, const char* name);

}  // namespace shadowlab::test
