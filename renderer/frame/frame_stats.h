#pragma once
// What one Renderer::render call did: which passes ran and why, what they cost, and what the bias amounts to.
#include "light/depth_bias.h"
#include "light/light_space.h"
#include "settings/settings.h"
#include "views/shadow_view.h"

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

// One shadow view of the frame (a directional or spot light's map, or one cube face of a point light's), rendered or
// skipped, and why. Lights that cast no shadow are listed once (face -1) with the reason.
struct ShadowViewStats {
    std::size_t light = 0;  // index into the frame's lights (the effective ones: useSceneLights resolved)
    ShadowViewKind kind = ShadowViewKind::Single;
    int index = 0;          // the view's index among its light's views (a cube face: 0..5)
    int face = -1;          // a point light's cube face (0..5, GL order +X,-X,+Y,-Y,+Z,-Z); -1 otherwise
    std::string name;       // "light 0", "light 2 +X"
    bool hasView = false;   // false: the light casts no shadow (disabled, castsShadows off)
    LightSpace space;
    CascadeSlice slice;     // a cascade's slice of the camera's frustum
    bool ran = false;
    std::string reason;
    std::string cache = "reused";  // what its map got: reused, static + dynamic, full (views/shadow_planner.h)
    std::size_t texelsRedrawn = 0; // static + dynamic: the rectangle copied from its cached depth and drawn over
    std::optional<double> milliseconds;
    int resolution = 0;
    DepthFormat format = DepthFormat::D32F;
    std::size_t memoryBytes = 0;  // its layer of the map array
    int castersDrawn = 0;
    int castersSkipped = 0;  // outside the view's volume
    int drawCalls = 0;       // multi-draw calls the pass issued (one per group of casters sharing their state)
    std::size_t triangles = 0;
};

struct FrameStats {
    bool ok = false;
    std::string error;                  // when !ok: why nothing was drawn (the previous image is unchanged)
    std::vector<std::string> warnings;  // drawn, but something was refused or approximated

    PassStats shadowPass;  // all shadow views together: ran if any ran, the time of those that ran
    PassStats mainPass;
    // projection.depthBounds: the depth prepass and its reduction (sameFrame) or the main depth's reduction for the
    // next frame (previousFrame); not run when no cascaded light asks for it.
    PassStats depthBoundsPass;
    // What this frame sent of the scene: "geometry uploaded, N bytes" (a new or changed scene), "transforms updated,
    // N bytes" (only instances moved: the transform buffer's changed entries), or not run ("unchanged").
    PassStats sceneUpload;
    std::size_t geometryBytesUploaded = 0;
    std::size_t transformBytesUploaded = 0;
    // A moments technique (filter.kind vsm, evsm2, evsm4, msm): the views' depth converted to moments, and their blur;
    // each runs only for the views the shadow pass re-rendered (or whose moments settings changed).
    PassStats momentsPass;
    PassStats blurPass;
    PassStats mipsPass;  // filter.momentMips: the moments' mip levels, for the same views
    std::optional<ViewDepths> seenDepths;  // the seen depths the cascades were fitted to (raw, before quantizing)
    std::vector<ShadowViewStats> views;  // every view of every light (see ShadowViewStats)
    std::size_t lightCount = 0;          // the frame's lights (the effective ones)
    std::string timingSource;           // "GPU (timer queries)" or "CPU (software rasterizer, ...)"

    bool shadowMapReallocated = false;       // some map array was (re)allocated this frame
    int shadowMapResolution = 0;             // the first view's map (light 0 in one-light scenes)
    DepthFormat shadowMapFormat = DepthFormat::D32F;
    std::size_t shadowMapBytes = 0;          // every map array together
    int castersDrawn = 0;                    // summed over the views that ran
    int castersSkipped = 0;
    int shadowDrawCalls = 0;                 // summed over the views that ran
    int alphaTestedCasters = 0;
    std::size_t shadowTriangles = 0;
    std::size_t sceneTriangles = 0;
    std::vector<std::string> mainVariants;  // the #define sets compiled into the programs this frame used

    LightSpace light;         // the first view's light space (light 0's in one-light scenes)
    std::string lightSource;  // which lights were used, in words
    BiasReport bias;  // what the first view's bias amounts to at this scene's receivers
    // A cascaded first light: the bias in every cascade (its own receivers, texel and depth range), nearest first;
    // viewBias[0].bias == bias. Otherwise the first view's alone.
    struct ViewBias {
        std::string name;  // "light 0 cascade:1"
        BiasReport bias;
    };
    std::vector<ViewBias> viewBias;
    glm::dvec3 renderOrigin{0.0};
    glm::dmat4 cameraViewProjection{1.0};  // render-origin-relative
};

// The frame's views of light `light` (those it rendered or kept), in order, as the view selection takes them
// (views/view_select.h).
std::vector<ShadowView> frameViewsOf(const FrameStats& stats, std::size_t light);
// The cascades of the frame's first casting light (what one-light tools describe); empty when it has none.
std::vector<ShadowView> frameCascades(const FrameStats& stats);

// World position -> pixel (x right, y down, in [0,w)x[0,h)) using the frame's camera; for tests and picking.
bool projectToPixel(const FrameStats& stats, const glm::dvec3& world, int width, int height, double& px, double& py);

}  // namespace shadowlab
