#pragma once
// glTF extensionsRequired: compressed geometry (Draco, meshopt) refuses the file with a clear message; the extensions
// ShadowLab handles or can safely ignore pass; anything else passes with a warning.
#include "scene/gltf_common.h"

#include <string>
#include <string_view>

namespace shadowlab::gltf {

// The error for a file that requires compressed geometry extension `ext`.
std::string compressedGeometryError(const std::string& ext);

// When tinygltf refuses a file, a required compression extension is usually why (its accessors have no bufferView):
// read extensionsRequired from the JSON ourselves to say so. Best effort; empty when the JSON cannot be read.
std::string unsupportedRequiredExtension(std::string_view json);

// false + error when the model requires compressed geometry; unknown required extensions only warn.
bool checkRequiredExtensions(const tg::Model& model, const Warn& warn, std::string& error);

}  // namespace shadowlab::gltf
