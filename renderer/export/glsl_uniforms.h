#pragma once
// The renderer's GLSL as another program takes it: its loose uniforms (`uniform vec4 uTechnique;`) either baked into
// constants with the exported values, or, for Vulkan (which has no loose uniforms), each put in a uniform block of
// its own and every sampler given a descriptor binding. Only the declaration lines change; the code that reads them
// is the renderer's own. No GL here.
#include <map>
#include <string>
#include <vector>

namespace shadowlab {

// `uniform TYPE NAME;` (or NAME[N]) for each name in `values` becomes `const TYPE NAME = VALUE;`. A name asked for that
// the text does not declare is an error (std::runtime_error naming it): the export and the shader disagree.
std::string bakeUniforms(const std::string& glsl, const std::map<std::string, std::string>& values);

// One descriptor the Vulkan text declares: set 0, its binding, what it is.
struct VulkanBinding {
    int binding = 0;
    std::string name;         // the uniform's GLSL name ("uMaps2D", "uSize")
    std::string declaration;  // "sampler2DArrayShadow uMaps2D[1]" / "std140 block { int uSize; }"
    bool block = false;       // a uniform buffer (std140, the value at offset 0), else a combined image sampler / image
};

// The text with every loose uniform that is left made Vulkan's: a sampler or image gets `layout(set = 0, binding = B)`
// (an image keeps its format and binding if it has one, and is listed), a value gets a std140 block of its own at the
// next binding. Bindings count up from `firstBinding` past those the text already uses.
std::string vulkanUniforms(const std::string& glsl, int firstBinding, std::vector<VulkanBinding>& bindings);

}  // namespace shadowlab
