#include "scene/scene_casters.h"

#include <functional>
#include <string_view>
#include <unordered_set>

namespace shadowlab {

std::vector<char> castingNodes(const Scene& scene, const CasterSettings& casters) {
    const std::unordered_set<std::string_view> excluded(casters.excluded.begin(), casters.excluded.end());
    std::vector<char> casts(scene.nodes.size(), 1);
    // Parents precede their children (the loader records them so): one pass carries an exclusion down.
    for (std::size_t n = 0; n < scene.nodes.size(); ++n) {
        const SceneNode& node = scene.nodes[n];
        const bool parentCasts = node.parent < 0 || casts[std::size_t(node.parent)];
        casts[n] = parentCasts && !excluded.count(node.path);
    }
    return casts;
}

std::vector<char> castingInstances(const Scene& scene, const CasterSettings& casters) {
    std::vector<char> out(scene.instances.size(), 1);
    if (casters.excluded.empty()) return out;
    const std::vector<char> nodes = castingNodes(scene, casters);
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        const int node = scene.instances[i].node;
        out[i] = node < 0 || node >= int(nodes.size()) || nodes[std::size_t(node)];
    }
    return out;
}

std::vector<std::string> unknownCasterPathWarnings(const Scene& scene, const CasterSettings& casters) {
    std::unordered_set<std::string_view> known;
    for (const SceneNode& node : scene.nodes) known.insert(node.path);
    std::vector<std::string> warnings;
    for (const std::string& path : casters.excluded)
        if (!known.count(path))
            warnings.push_back("casters.excluded: no node '" + path + "' in scene " + scene.name +
                               " (its paths are listed by the editor's Outliner); ignored");
    return warnings;
}

std::size_t withCasters(std::size_t sceneFingerprint, const std::vector<char>& castingInstances) {
    const std::size_t casters =
        std::hash<std::string_view>{}(std::string_view(castingInstances.data(), castingInstances.size()));
    return sceneFingerprint ^ (casters * 0x9e3779b97f4a7c15ULL);
}

}  // namespace shadowlab
