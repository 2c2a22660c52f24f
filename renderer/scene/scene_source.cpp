#include "scene/scene_source.h"

#include "scene/builtin_scenes.h"
#include "scene/gltf_loader.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <system_error>

namespace shadowlab {
namespace {

std::string lowercase(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

std::string joinedBuiltinNames() {
    std::string names;
    for (const std::string& n : builtinSceneNames()) names += (names.empty() ? "" : ", ") + n;
    return names;
}

SceneLoadResult failure(std::string message) {
    SceneLoadResult r;
    r.error = std::move(message);
    return r;
}

}  // namespace

SceneLoadResult loadScene(const std::string& spec) {
    const std::string prefix = kBuiltinPrefix;
    if (spec.rfind(prefix, 0) == 0) {
        const std::string name = spec.substr(prefix.size());
        std::optional<Scene> scene = makeBuiltinScene(name);
        if (!scene) return failure("unknown built-in scene '" + name + "'; available: " + joinedBuiltinNames());
        return SceneLoadResult{std::move(scene), {}};
    }
    if (spec.empty())
        return failure("no scene given: use builtin:NAME (" + joinedBuiltinNames() + ") or a .gltf/.glb file");

    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path path(spec);
    if (!fs::exists(path, ec))
        return failure(spec + ": scene file not found (use builtin:NAME for a built-in scene: " +
                       joinedBuiltinNames() + ")");
    if (fs::is_directory(path, ec)) return failure(spec + ": is a directory, not a .gltf/.glb file");
    // *.gltf.json copies (JSON glTF under another extension) are accepted too; the loader sniffs the content.
    const std::string ext = lowercase(path.extension().string());
    if (ext != ".gltf" && ext != ".glb" && ext != ".json")
        return failure(spec + ": unsupported scene file type '" + ext + "' (ShadowLab loads .gltf and .glb)");
    return loadGltfScene(spec);
}

}  // namespace shadowlab
