#include "scene/gltf_extensions.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>

namespace shadowlab::gltf {
namespace {

bool isCompressedGeometry(const std::string& ext) {
    return ext == "KHR_draco_mesh_compression" || ext == "EXT_meshopt_compression" || ext == "KHR_meshopt_compression";
}

}  // namespace

std::string compressedGeometryError(const std::string& ext) {
    return "requires " + ext + " (compressed geometry), which ShadowLab cannot decode";
}

std::string unsupportedRequiredExtension(std::string_view text) {
    const nlohmann::json j = nlohmann::json::parse(text.begin(), text.end(), nullptr, /*allow_exceptions=*/false);
    if (!j.is_object() || !j.contains("extensionsRequired") || !j["extensionsRequired"].is_array()) return {};
    for (const nlohmann::json& ext : j["extensionsRequired"])
        if (ext.is_string() && isCompressedGeometry(ext.get<std::string>())) return ext.get<std::string>();
    return {};
}

bool checkRequiredExtensions(const tg::Model& model, const Warn& warn, std::string& error) {
    for (const std::string& ext : model.extensionsRequired) {
        if (isCompressedGeometry(ext)) {
            error = compressedGeometryError(ext);
            return false;
        }
        const bool handled = ext == "KHR_texture_transform" || ext == "KHR_lights_punctual" ||
                             ext == "KHR_mesh_quantization" || ext.rfind("KHR_materials_", 0) == 0;
        if (!handled) warn("requires extension " + ext + ", which ShadowLab ignores: the scene may look wrong");
    }
    return true;
}

}  // namespace shadowlab::gltf
