#include "scene/scene_casters.h"

#include <functional>
#include <string_view>
#include <unordered_set>

namespace shadowlab {

namespace {

// Per Scene::nodes: 1 when the node or an ancestor is marked (`marked(node)`). Parents precede their children (the
// loader records them so): one pass carries a mark down.
template <typename Marked>
std::vector<char> markedSubtrees(const Scene& scene, Marked marked) {
    std::vector<char> out(scene.nodes.size(), 0);
    for (std::size_t n = 0; n < scene.nodes.size(); ++n) {
        const SceneNode& node = scene.nodes[n];
        out[n] = (node.parent >= 0 && out[std::size_t(node.parent)]) || marked(n);
    }
    return out;
}

std::vector<char> listedSubtrees(const Scene& scene, const std::vector<std::string>& paths) {
    const std::unordered_set<std::string_view> listed(paths.begin(), paths.end());
    return markedSubtrees(scene, [&](std::size_t n) { return listed.count(scene.nodes[n].path) > 0; });
}

// A node flag per instance (`instanceOfNoNode` for an instance no node placed).
std::vector<char> perInstance(const Scene& scene, const std::vector<char>& nodes, char instanceOfNoNode) {
    std::vector<char> out(scene.instances.size(), instanceOfNoNode);
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        const int node = scene.instances[i].node;
        if (node >= 0 && node < int(nodes.size())) out[i] = nodes[std::size_t(node)];
    }
    return out;
}

}  // namespace

std::vector<char> castingNodes(const Scene& scene, const CasterSettings& casters) {
    std::vector<char> casts = listedSubtrees(scene, casters.excluded);
    for (char& c : casts) c = !c;
    return casts;
}

std::vector<char> castingInstances(const Scene& scene, const CasterSettings& casters) {
    std::vector<char> out(scene.instances.size(), 1);
    if (casters.excluded.empty()) return out;
    return perInstance(scene, castingNodes(scene, casters), 1);
}

std::vector<char> staticNodes(const Scene& scene, const std::vector<int>& chosen, const CasterSettings& casters) {
    std::unordered_set<int> driven;  // the file's node indices a chosen animation drives
    for (int a : chosen)
        if (a >= 0 && a < int(scene.animations.size()))
            for (const AnimationChannel& channel : scene.animations[std::size_t(a)].channels) driven.insert(channel.node);
    const std::vector<char> moving =
        markedSubtrees(scene, [&](std::size_t n) { return driven.count(scene.nodes[n].gltfIndex) > 0; });
    const std::vector<char> forcedStatic = listedSubtrees(scene, casters.forcedStatic);
    const std::vector<char> forcedDynamic = listedSubtrees(scene, casters.forcedDynamic);
    std::vector<char> nodes(scene.nodes.size());
    for (std::size_t n = 0; n < nodes.size(); ++n) nodes[n] = forcedStatic[n] || (!moving[n] && !forcedDynamic[n]);
    return nodes;
}

std::vector<char> staticInstances(const Scene& scene, const std::vector<int>& chosen, const CasterSettings& casters) {
    return perInstance(scene, staticNodes(scene, chosen, casters), 1);
}

std::vector<std::string> unknownCasterPathWarnings(const Scene& scene, const CasterSettings& casters) {
    std::unordered_set<std::string_view> known;
    for (const SceneNode& node : scene.nodes) known.insert(node.path);
    std::vector<std::string> warnings;
    const std::pair<const char*, const std::vector<std::string>*> lists[] = {
        {"casters.excluded", &casters.excluded}, {"casters.static", &casters.forcedStatic},
        {"casters.dynamic", &casters.forcedDynamic}};
    for (const auto& [key, paths] : lists)
        for (const std::string& path : *paths)
            if (!known.count(path))
                warnings.push_back(std::string(key) + ": no node '" + path + "' in scene " + scene.name +
                                   " (its paths are listed by the editor's Outliner); ignored");
    return warnings;
}

std::size_t withCasters(std::size_t sceneFingerprint, const std::vector<char>& castingInstances) {
    const std::size_t casters =
        std::hash<std::string_view>{}(std::string_view(castingInstances.data(), castingInstances.size()));
    return sceneFingerprint ^ (casters * 0x9e3779b97f4a7c15ULL);
}

}  // namespace shadowlab
