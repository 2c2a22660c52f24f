#pragma once
// The reference's parts run by hand (G-buffer surface samples + Embree visibility) for tests that check them
// against closed-form answers, and a place to write overlay pictures.
#include "accuracy/accuracy_meter.h"
#include "accuracy/gbuffer_pass.h"
#include "frame/renderer.h"
#include "reference/embree_scene.h"
#include "reference/visibility.h"

#include <memory>
#include <string>

namespace shadowlab::test {

struct ReferenceView {
    FrameStats stats;                 // the tool's frame (light space, camera, render origin)
    SurfaceSamples samples;
    VisibilityResult visibility;
    ReferenceLight light;
    std::unique_ptr<EmbreeScene> bvh;

    glm::dvec3 world(std::size_t i) const { return samples.point[i] + stats.renderOrigin; }
    PixelClass at(int x, int y) const { return visibility.classes[std::size_t(y) * std::size_t(samples.width) + std::size_t(x)]; }
};

ReferenceView traceReference(const Scene& scene, const Settings& settings, int width, int height);

// Writes an AccuracyReport's overlay under the test output folder (look at it!) and returns the path.
std::string saveOverlay(const AccuracyReport& report, const std::string& name);

// A camera looking straight down at (x, 0, z) from height h.
Settings topDownAt(Settings s, float x, float z, float h);

// A wall standing on the floor (x in [-0.2, 0.2], y in [0, 4], z in [-3, 3]) under a sun across it (direction
// (1, -1, 0)): its shadow lies on x in [0.2, 4.2] and its side edge at z = 3 runs from the wall's foot (contact) to
// its top's shadow. atContactWallEdge gives `s` that light and a camera 7 above the edge's middle (2.5, 0, 3).
Scene contactWallScene();
Settings atContactWallEdge(Settings s);

}  // namespace shadowlab::test
