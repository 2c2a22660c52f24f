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

}  // namespace shadowlab::test
