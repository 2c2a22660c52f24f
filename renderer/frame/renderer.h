#pragma once
// The only entry point for a frame. Decides which passes must run (a shadow map whose light, casters and shadow
// settings did not change is not re-rendered), which shader variants they need, runs them, and reports FrameStats.
#include "context/gl_info.h"
#include "frame/camera.h"
#include "frame/frame_stats.h"
#include "frame/gpu_scene.h"
#include "frame/render_target.h"
#include "shading/main_pass.h"
#include "shadow/shadow_map.h"
#include "shadow/shadow_pass.h"
#include "timing/pass_timer.h"

#include <memory>
#include <optional>

namespace shadowlab {

class Renderer {
public:
    // Needs a current GL 4.5 context. Throws std::runtime_error if the built-in shaders do not build.
    Renderer();

    // Invalid settings (see Settings::validate) or a light that cannot be built: nothing is drawn and
    // FrameStats::error says why; the renderer keeps its previous state.
    FrameStats render(const Scene& scene, const Settings& settings, const Camera& camera, RenderTarget& target);

    // Call after editing a Scene in place (geometry or materials), so the next frame re-uploads it.
    void sceneChanged() { gpuScene_.reset(); }

    // Forces the next frame's shadow pass (benchmarks time it every frame).
    void invalidateShadowMap() { lastShadow_.reset(); }

    // Waits for the newest GPU timings (benchmarks, one-shot renders); fills the stats' milliseconds.
    void waitForTimings(FrameStats& stats);

    const ShadowMap& shadowMap() const { return shadowMap_; }
    // The scene as last uploaded (null before the first frame): the pixel probe's G-buffer draws the same draws.
    const GpuScene* gpuScene() const { return gpuScene_.get(); }
    const GlInfo& glInfo() const { return info_; }

private:
    // What the last shadow pass drew from; the next one runs only if one of these changed.
    struct ShadowInputs {
        std::size_t sceneFingerprint = 0;  // includes the scene's address
        glm::dmat4 lightViewProjection{0.0};
        ShadowMapSettings shadow;
        bool depthClamp = true;
    };
    std::string shadowPassReason(const ShadowInputs& now, bool reallocated) const;

    GlInfo info_;
    ShadowMap shadowMap_;
    std::unique_ptr<ShadowPass> shadowPass_;
    MainPass mainPass_;
    PassTimer timer_;
    std::unique_ptr<GpuScene> gpuScene_;
    std::size_t gpuSceneFingerprint_ = 0;
    std::optional<ShadowInputs> lastShadow_;
    std::uint64_t mapGenerationRendered_ = 0;  // the shadow map allocation the last shadow pass drew into
    struct Receivers {
        std::size_t fingerprint = 0;
        glm::dmat4 lightViewProjection{0.0};
        int resolution = 0;
        ReceiverDepths depths;
    };
    std::optional<Receivers> receivers_;  // the scene's depths in the map, for the bias report
};

// Changes whenever geometry, instances or alpha-relevant material values of the scene change.
std::size_t sceneFingerprint(const Scene& scene);

}  // namespace shadowlab
