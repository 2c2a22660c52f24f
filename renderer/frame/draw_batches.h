#pragma once
// A list of a GpuScene's draws drawn in a few calls: grouped by a key (the state a pass sets between draws: face
// culling, an alpha-tested material), each group one glMultiDrawElementsIndirect whose commands pick their model
// matrices from the scene's transform buffer through baseInstance (frame/gpu_scene.h: kDrawIndexAttribute). Which
// draws go in is the caller's list: the batching draws a selection, it does not make one.
#include "frame/gpu_scene.h"
#include "gl/gl_objects.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace shadowlab {

struct DrawBatch {
    std::uint64_t key = 0;
    std::uint32_t firstDraw = 0;  // a draw of the group (index into GpuScene::draws()): set the group's state from it
    GLsizei commands = 0;         // the draws it holds
    std::size_t offset = 0;       // its first command in the indirect buffer, in bytes
};

class DrawBatches {
public:
    DrawBatches();  // needs a current GL 4.5 context

    // Groups `draws` (indices into scene.draws()) by keyOf(index), in increasing key order and, within a group, in
    // the list's order; uploads one indirect command per draw (count, one instance, first index, base vertex,
    // baseInstance = the draw's index). Replaces the previous build.
    const std::vector<DrawBatch>& build(const GpuScene& scene, const std::vector<std::uint32_t>& draws,
                                        const std::function<std::uint64_t(std::uint32_t)>& keyOf);
    // One glMultiDrawElementsIndirect of a group of the last build; the caller has bound the scene (GpuScene::bind)
    // and set the group's program and state.
    void draw(const DrawBatch& batch) const;

private:
    gl::Buffer commands_;
    std::vector<DrawBatch> batches_;
};

}  // namespace shadowlab
