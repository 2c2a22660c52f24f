#include "scene/gltf_camera_precheck.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace shadowlab::gltf {

namespace {

using nlohmann::json;

// "" when tinygltf can parse the camera, else why not (the properties glTF requires, as numbers).
std::string brokenBecause(const json& camera) {
    if (!camera.is_object()) return "it is not an object";
    const auto type = camera.find("type");
    if (type == camera.end() || !type->is_string()) return "it has no \"type\" string";
    const std::string& kind = type->get_ref<const std::string&>();
    if (kind != "perspective" && kind != "orthographic") return {};  // importCamera refuses an unknown type
    const auto object = camera.find(kind);
    if (object == camera.end() || !object->is_object()) return "it has no \"" + kind + "\" object";
    const std::vector<const char*> required =
        kind == "perspective" ? std::vector<const char*>{"yfov", "znear"}
                              : std::vector<const char*>{"xmag", "ymag", "znear", "zfar"};
    for (const char* key : required) {
        const auto value = object->find(key);
        if (value == object->end()) return std::string(key) + " is missing";
        if (!value->is_number()) return std::string(key) + " " + value->dump() + " is not a number";
    }
    return {};
}

}  // namespace

std::optional<std::string> standInBrokenCameras(std::string_view text) {
    if (text.find("\"cameras\"") == std::string_view::npos) return std::nullopt;  // the common case: no second parse
    json doc = json::parse(text.begin(), text.end(), nullptr, /*allow_exceptions=*/false);
    if (!doc.is_object()) return std::nullopt;
    const auto cameras = doc.find("cameras");
    if (cameras == doc.end() || !cameras->is_array()) return std::nullopt;
    bool replaced = false;
    for (json& camera : *cameras) {
        const std::string why = brokenBecause(camera);
        if (why.empty()) continue;
        json standIn = {{"type", "perspective"},
                        {"perspective", {{"yfov", 1.0}, {"znear", 1.0}}},
                        {"extras", {{kRefusedCameraKey, why}}}};
        if (camera.is_object() && camera.contains("name") && camera["name"].is_string()) standIn["name"] = camera["name"];
        camera = std::move(standIn);
        replaced = true;
    }
    if (!replaced) return std::nullopt;
    return doc.dump(-1, ' ', false, json::error_handler_t::replace);
}

std::vector<unsigned char> glbWithJson(const std::vector<unsigned char>& glb, std::string_view oldJson,
                                       const std::string& text) {
    // Header (12 bytes), then the JSON chunk (length, type, data padded with spaces to 4 bytes), then the rest.
    std::string padded = text;
    while (padded.size() % 4) padded += ' ';
    const std::size_t restAt = std::size_t(oldJson.data() + oldJson.size() - reinterpret_cast<const char*>(glb.data()));
    std::size_t rest = restAt;
    while (rest % 4 && rest < glb.size()) ++rest;  // the old chunk's padding
    std::vector<unsigned char> out(glb.begin(), glb.begin() + 12);
    auto put32 = [&](std::uint32_t v) {
        unsigned char b[4];
        std::memcpy(b, &v, 4);
        out.insert(out.end(), b, b + 4);
    };
    put32(std::uint32_t(padded.size()));
    put32(0x4E4F534Au);  // "JSON"
    out.insert(out.end(), padded.begin(), padded.end());
    out.insert(out.end(), glb.begin() + std::ptrdiff_t(std::min(rest, glb.size())), glb.end());
    const std::uint32_t total = std::uint32_t(out.size());
    std::memcpy(out.data() + 8, &total, 4);
    return out;
}

}  // namespace shadowlab::gltf
