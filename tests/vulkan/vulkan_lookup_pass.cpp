#include "vulkan_lookup_pass.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace shadowlab::test {

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
    const std::size_t pointCount = input.points.size() / 2;
    VkRun run;
    VkRunImage map;
    map.format = input.format;
    map.size = input.resolution;
    map.texelBytes = int(input.texels.size() / std::max<std::size_t>(std::size_t(input.resolution) * input.resolution, 1));
    map.texels = input.texels;
    run.images.push_back(map);
    const auto* points = reinterpret_cast<const std::uint8_t*>(input.points.data());
    run.buffers.emplace_back(points, points + input.points.size() * sizeof(glm::vec4));
    run.buffers.emplace_back(pointCount * sizeof(float), std::uint8_t(0));
    VkRunDispatch dispatch;
    dispatch.spirv = input.spirv;
    for (const auto& [binding, sampler] : input.maps) {
        VkRunBinding b;
        b.binding = binding;
        b.type = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
        b.image = 0;
        b.sampler = sampler;
        dispatch.bindings.push_back(b);
    }
    dispatch.bindings.push_back({10, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, -1, 0, {}, 0});
    dispatch.bindings.push_back({11, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, -1, 0, {}, 1});
    dispatch.groupsX = std::uint32_t((pointCount + 63) / 64);
    run.dispatches.push_back(dispatch);
    const VkRunResult ran = runComputeVulkan(run);
    LookupPassResult result;
    result.noDevice = ran.noDevice;
    result.error = ran.error;
    result.deviceName = ran.deviceName;
    if (ran.error.empty() && ran.buffers.size() == 2) {
        result.shadow.resize(pointCount);
        std::memcpy(result.shadow.data(), ran.buffers[1].data(), pointCount * sizeof(float));
    }
    return result;
}

}  // namespace shadowlab::test
