#pragma once
// What one Renderer::render call did: which passes ran and why, what they cost, and what the bias amounts to.
#include "light/depth_bias.h"
#include "light/light_space.h"
#include "settings/settings.h"

#include <glm/ext/matrix_double4x4.hpp>

#include <optional>
#include <string>
#include <vector>

namespace shadowlab {

struct PassStats {
    bool ran = false;
    std::string reason;                   // why it ran or was skipped, e.g. "light changed", "unchanged"
    std::optional<double> milliseconds;   // newest finished timing of this pass (GPU: may lag a few frames)
};

struct FrameStats {
    bool ok = false;
    std::string error;                  // when !ok: why nothing was drawn (the previous image is unchanged)
    std::vector<std::string> warnings;  // drawn, but something was refused or approximated

    PassStats shadowPass;
    PassStats mainPass;
    std::string timingSource;           // "GPU (timer queries)" or "CPU (software rasterizer, ...)"

    bool shadowMapReallocated = false;
    int shadowMapResolution = 0;
    DepthFormat shadowMapFormat = DepthFormat::D32F;
    std::size_t shadowMapBytes = 0;
    int castersDrawn = 0;
    int castersSkipped = 0;
    int alphaTestedCasters = 0;
    std::size_t shadowTriangles = 0;
    std::size_t sceneTriangles = 0;
    std::vector<std::string> mainVariants;  // the #define sets compiled into the programs this frame used

    LightSpace light;
    std::string lightSource;  // which light was used, in words
    BiasReport bias;  // what the bias amounts to at this scene's receivers
    glm::dvec3 renderOrigin{0.0};
    glm::dmat4 cameraViewProjection{1.0};  // render-origin-relative
};

// World position -> pixel (x right, y down, in [0,w)x[0,h)) using the frame's camera; for tests and picking.
bool projectToPixel(const FrameStats& stats, const glm::dvec3& world, int width, int height, double& px, double& py);

}  // namespace shadowlab
