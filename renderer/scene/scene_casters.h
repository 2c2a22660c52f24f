#pragma once
// What casts shadows: the settings' excluded node paths (casters.excluded) applied to a scene's node hierarchy. The
// shadow pass and the exact-visibility reference both take their casters from here, so a node left out of the maps
// never blocks a reference ray either (every accuracy number compares like with like).
#include "scene/scene.h"
#include "settings/settings.h"

#include <cstddef>
#include <string>
#include <vector>

namespace shadowlab {

// Per Scene::nodes: 1 when the node casts (neither it nor an ancestor is excluded).
std::vector<char> castingNodes(const Scene& scene, const CasterSettings& casters);

// Per Scene::instances: 1 when the instance casts (an instance of no node always does).
std::vector<char> castingInstances(const Scene& scene, const CasterSettings& casters);

// Per Scene::nodes: 1 when the node is static: none of the animations `chosen` (indices into Scene::animations)
// drives it or an ancestor, or casters.static names it (or an ancestor), unless casters.dynamic does (casters.static
// wins where both name it).
std::vector<char> staticNodes(const Scene& scene, const std::vector<int>& chosen, const CasterSettings& casters);

// Per Scene::instances: 1 when the instance is a static caster (its node is, staticNodes). An instance of no node is
// static.
std::vector<char> staticInstances(const Scene& scene, const std::vector<int>& chosen, const CasterSettings& casters);

// One warning per excluded path no node of the scene has ("casters.excluded: no node 'X' in scene S; ignored"):
// a preset tuned on an older version of a file still loads.
// The same for casters.static and casters.dynamic.
std::vector<std::string> unknownCasterPathWarnings(const Scene& scene, const CasterSettings& casters);

// A scene's geometry fingerprint combined with its casting instances: what the maps and the reference are built from
// (changes whenever either does).
std::size_t withCasters(std::size_t sceneFingerprint, const std::vector<char>& castingInstances);

}  // namespace shadowlab
