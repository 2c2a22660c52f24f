#pragma once
// A camera tinygltf cannot parse (no "perspective" object, a yfov that is missing or not a number, ...) would make
// it refuse the whole file. Before it reads the file, each such camera is swapped for a valid stand-in that carries
// why in its extras; importCamera (gltf_cameras.h) then refuses that camera alone, with the reason, and the rest of
// the file loads.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace shadowlab::gltf {

// The extras key a stand-in camera carries its refusal in.
inline constexpr const char* kRefusedCameraKey = "shadowlabRefused";

// The JSON text with every structurally broken camera replaced, or nullopt when there is none (or the text is not a
// JSON object: tinygltf reports that).
std::optional<std::string> standInBrokenCameras(std::string_view json);

// A GLB whose JSON chunk is `json` and whose other chunks are those of `glb` (the header's lengths updated).
std::vector<unsigned char> glbWithJson(const std::vector<unsigned char>& glb, std::string_view oldJson,
                                       const std::string& json);

}  // namespace shadowlab::gltf
