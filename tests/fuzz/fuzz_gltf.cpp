// libFuzzer target: the bytes of a .gltf or .glb (chosen by the "glTF" magic, as for a file). External URIs
// resolve against a folder that does not exist. Whatever the bytes, loading ends in a scene that keeps the Scene
// invariants (finite positions, unit normals, indices in range) or in an error; posed by its animations at their
// start, midpoint and past their end, it keeps them too.
#include "scene/gltf_loader.h"
#include "scene/scene_animation.h"

#include <cstddef>
#include <cstdint>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::vector<unsigned char> bytes(data, data + size);
    shadowlab::SceneLoadResult r = shadowlab::loadGltfSceneFromMemory(bytes, "fuzz", "/nonexistent-shadowlab-fuzz");
    if (r.scene && !r.scene->invariantError().empty()) __builtin_trap();
    if (!r.scene && r.error.empty()) __builtin_trap();  // a refusal always says why
    if (r.scene && !r.scene->animations.empty()) {
        std::vector<int> all;
        for (std::size_t i = 0; i < r.scene->animations.size(); ++i) all.push_back(int(i));
        const shadowlab::AnimationSpan span = shadowlab::animationSpan(*r.scene, all);
        for (double t : {span.start, (span.start + span.end) * 0.5, span.end + 1.0}) {
            shadowlab::poseScene(*r.scene, all, t);
            if (!r.scene->invariantError().empty()) __builtin_trap();
        }
    }
    return 0;
}
