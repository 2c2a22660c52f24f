// libFuzzer target: the bytes of a .gltf or .glb (chosen by the "glTF" magic, as for a file). External URIs
// resolve against a folder that does not exist. Whatever the bytes, loading ends in a scene that keeps the Scene
// invariants (finite positions, unit normals, indices in range) or in an error.
#include "scene/gltf_loader.h"

#include <cstddef>
#include <cstdint>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::vector<unsigned char> bytes(data, data + size);
    shadowlab::SceneLoadResult r = shadowlab::loadGltfSceneFromMemory(bytes, "fuzz", "/nonexistent-shadowlab-fuzz");
    if (r.scene && !r.scene->invariantError().empty()) __builtin_trap();
    if (!r.scene && r.error.empty()) __builtin_trap();  // a refusal always says why
    return 0;
}
