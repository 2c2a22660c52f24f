#pragma once
// Keys of a Scene that tell what changed between two frames: its geometry (what the GPU upload and the shadow maps'
// contents depend on) apart from its instances' transforms (an animation step). "Only the transforms changed" is
// decided from these keys: GpuScene::sameGeometry (layout or contents: the GPU holds copies) and the reference's
// EmbreeScene::sameGeometry (layout alone: its alpha masks read the scene's buffers); the renderer's motion logic
// reads the draws that moved from the same update (frame/gpu_scene.h: SceneUpload::moved).
#include "scene/scene.h"

#include <cstddef>

namespace shadowlab {

// The scene's layout without transforms, by address: the Scene object, its meshes' buffers and sizes, which mesh
// each instance draws, the materials' depth-relevant values. Cheap; equal for the same scene (or one edited in place:
// Renderer::sceneChanged).
std::size_t layoutFingerprint(const Scene& scene);
// The same from the contents (a posed copy of a scene has the scene's): vertices, indices, materials, the
// instance -> mesh list, images by size.
std::size_t geometryFingerprint(const Scene& scene);
// The instances' transforms alone.
std::size_t transformsFingerprint(const Scene& scene);
// Changes whenever geometry, instances or alpha-relevant material values of the scene change (layout + transforms).
std::size_t sceneFingerprint(const Scene& scene);

}  // namespace shadowlab
