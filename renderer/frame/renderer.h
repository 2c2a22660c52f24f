#pragma once
// The only entry point for a frame. Plans the shadow views (a directional or spot light has one, a point light six
// cube faces): a view is rendered only when its light, casters or shadow settings changed, and skipped when it cannot
// change the picture (no caster in its volume, a volume the camera does not see, a light that casts no shadow).
// Then the main pass, specialised to the frame's light set and filter. FrameStats lists every view and why.
#include "context/gl_info.h"
#include "frame/camera.h"
#include "frame/frame_stats.h"
#include "frame/gpu_scene.h"
#include "frame/render_target.h"
#include "shading/main_pass.h"
#include "shadow/shadow_map.h"
#include "shadow/shadow_pass.h"
#include "timing/pass_timer.h"

#include <map>
#include <memory>
#include <optional>
#include <utility>

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

    // Forces the next frame to render every shadow view (benchmarks time them every frame).
    void invalidateShadowMap() {
        for (auto& [key, state] : views_) state.rendered.reset();
    }

    // Waits for the newest GPU timings (benchmarks, one-shot renders); fills the stats' milliseconds.
    void waitForTimings(FrameStats& stats);

    // The first shadow view's map (light 0's in a one-light scene); an empty map before the first frame.
    const ShadowMap& shadowMap() const;
    // The map of view `view` of FrameStats::views of the last frame (nullptr for lights without a view).
    const ShadowMap* viewMap(std::size_t light, int face) const;
    // The scene as last uploaded (null before the first frame): the pixel probe's G-buffer draws the same draws.
    const GpuScene* gpuScene() const { return gpuScene_.get(); }
    const GlInfo& glInfo() const { return info_; }

private:
    // What a view's map was last rendered from; the next render runs only if one of these changed.
    struct ViewInputs {
        std::size_t sceneFingerprint = 0;  // includes the scene's address
        glm::dmat4 viewProjection{0.0};
        LightSettings light;               // compared through the key table's shadow-view tags
        std::uint64_t mapGeneration = 0;
        bool empty = false;                // no caster in its volume: the map was cleared
        bool operator==(const ViewInputs&) const = default;
    };
    struct ViewState {
        ShadowMap map;
        std::optional<ViewInputs> rendered;
    };
    using ViewKey = std::pair<std::size_t, int>;  // light, face
    struct GroupKey {
        bool cube = false;
        int resolution = 0;
        DepthFormat format = DepthFormat::D32F;
        bool reversedZ = false;  // an array holds maps of one convention: its sampler compares LEQUAL or GEQUAL
        auto operator<=>(const GroupKey&) const = default;
    };
    static std::string viewReason(const std::optional<ViewInputs>& last, const ViewInputs& now);

    GlInfo info_;
    std::map<GroupKey, ShadowMapArray> arrays_;
    std::map<ViewKey, ViewState> views_;
    ShadowSampler sampler_{false};
    ShadowSampler reversedSampler_{true};
    std::unique_ptr<ShadowPass> shadowPass_;
    MainPass mainPass_;
    PassTimer timer_;
    std::unique_ptr<GpuScene> gpuScene_;
    std::size_t gpuSceneFingerprint_ = 0;
    ViewKey firstView_{0, -2};  // the first view of the last frame (shadowMap())
    struct Receivers {
        std::size_t fingerprint = 0;
        glm::dmat4 lightViewProjection{0.0};
        int resolution = 0;
        ReceiverDepths depths;
    };
    std::optional<Receivers> receivers_;  // the scene's depths in the first view's map, for the bias report
};

// Changes whenever geometry, instances or alpha-relevant material values of the scene change.
std::size_t sceneFingerprint(const Scene& scene);

}  // namespace shadowlab
