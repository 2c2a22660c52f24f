#pragma once
// The only entry point for a frame. The planner (views/shadow_planner.h) says which shadow views the frame needs and
// why: a view is rendered only when its light, casters or shadow settings changed, and skipped when it cannot change
// the picture (no caster in its volume, a volume the camera does not see, a light that casts no shadow). The
// Renderer allocates the map arrays, carries out the plan, then runs the main pass, specialised to the frame's light
// set and filter. FrameStats lists every view and why.
#include "context/gl_info.h"
#include "frame/camera.h"
#include "frame/depth_bounds_pass.h"
#include "frame/frame_stats.h"
#include "frame/gpu_scene.h"
#include "frame/render_target.h"
#include "scene/scene_fingerprint.h"
#include "shading/main_pass.h"
#include "shadow/shadow_map.h"
#include "shadow/moments_pass.h"
#include "shadow/shadow_pass.h"
#include "views/shadow_planner.h"
#include "timing/pass_timer.h"

#include <map>
#include <memory>
#include <optional>
#include <utility>

namespace shadowlab {

// The camera a frame's cascades fit to when it is not the one the picture is drawn from (the editor's "freeze the
// cascades' camera": the user flies out and looks at cascades fitted to where the camera was), with the aspect
// (width / height) of the view it was frozen in.
struct FitCamera {
    Camera camera;
    double aspect = 1.0;
    bool operator==(const FitCamera&) const = default;
};

class Renderer {
public:
    // Needs a current GL 4.5 context. Throws std::runtime_error if the built-in shaders do not build.
    Renderer();

    // Invalid settings (see Settings::validate) or a light that cannot be built: nothing is drawn and
    // FrameStats::error says why; the renderer keeps its previous state. `fitCamera`: the camera cascades fit to and
    // are picked by, when not `camera` (nullptr: `camera`): the editor's frozen cascades, and the flicker
    // measure, which draws frame f+1's pixels with frame f's cascades.
    FrameStats render(const Scene& scene, const Settings& settings, const Camera& camera, RenderTarget& target,
                      const FitCamera* fitCamera = nullptr);

    // Call after editing a Scene in place (geometry or materials), so the next frame re-uploads it.
    void sceneChanged() { gpuScene_.reset(); }

    // Forces the next frame to render every shadow view (benchmarks time them every frame).
    void invalidateShadowMap() { forceReason_ = "forced: every view re-rendered (invalidateShadowMap)"; }

    // Waits for the newest GPU timings (benchmarks, one-shot renders); fills the stats' milliseconds.
    void waitForTimings(FrameStats& stats);

    // The first shadow view's map (light 0's in a one-light scene); an empty map before the first frame.
    const ShadowMap& shadowMap() const;
    // The map of a view of the last frame (nullptr for lights without a view).
    const ShadowMap* viewMap(const ShadowViewId& view) const;
    // The same by cube face (-1: the light's single view).
    const ShadowMap* viewMap(std::size_t light, int face) const;
    // The scene as last uploaded (null before the first frame): the pixel probe's G-buffer draws the same draws.
    const GpuScene* gpuScene() const { return gpuScene_.get(); }
    const GlInfo& glInfo() const { return info_; }
    // A moments technique's stored moments of a view of the last frame, texels [x0, x0+w) x [y0, y0+h) (row 0 =
    // bottom; a cube face's layer); empty when the frame used a depth technique or the view is unknown.
    std::vector<glm::vec4> viewMoments(const ShadowViewId& view, int x0, int y0, int w, int h, int level = 0) const;
    // Where that view's moments are stored (texture 0: a depth technique or an unknown view).
    MomentsLayer viewMomentsLayer(const ShadowViewId& view) const;

private:
    struct ViewState {
        ShadowMap map;          // its layer of its group's array
        MapGroup group;
        ShadowMap staticDepth;  // shadow.update cachedStatic: its static casters alone (the cached depth)
    };
    // A stable cascade's page of static casters (views/cascade_scroll.h: cascadePages), drawn before its copy.
    ShadowMap pageScratch_;
    // Draws a view the plan renders (every caster, or through its cached static depth); its counts.
    // `casterDraws`: each caster's draw; `statics`: 1 per static caster (empty unless a light caches).
    ShadowPassCounts renderView(const PlannedView& p, const LightSettings& light, ViewState& state,
                                const std::vector<std::size_t>& casterDraws, const std::vector<char>& statics);

    GlInfo info_;
    std::map<MapGroup, ShadowMapArray> arrays_;
    std::map<ShadowViewId, ViewState> views_;
    std::optional<ShadowPlan> previousPlan_;  // the plan the last frame carried out: what each view's map holds
    std::optional<std::pair<Settings, MainVariantKey>> variant_;  // the last frame's settings and their variant
    std::string forceReason_;                 // not empty: the next frame renders every view (invalidateShadowMap)
    ShadowSampler sampler_{false};
    ShadowSampler reversedSampler_{true};
    std::unique_ptr<ShadowPass> shadowPass_;
    std::unique_ptr<DepthBoundsPass> depthBoundsPass_;  // made when a light first asks for projection.depthBounds
    std::unique_ptr<MomentsPass> momentsPass_;          // made when a moments technique is first chosen
    // The seen depths the last frame without a fit camera fitted its cascades to: a frame with a fit camera (frozen
    // cascades, the flicker measure's previous-frame cascades) fits to them as that frame did.
    std::optional<ViewDepths> ownCameraDepths_;
    MainPass mainPass_;
    PassTimer timer_;
    std::unique_ptr<GpuScene> gpuScene_;
    // The casters' motion: each draw's sphere last frame, the frame's moves, which casters are static.
    std::vector<CasterSphere> drawSpheres_;
    CasterMotion motion_;
    std::size_t transformsFingerprint_ = 0;  // the instances' transforms as last seen
    std::uint64_t frames_ = 0;
    std::optional<ShadowViewId> firstView_;  // the first view of the last frame (shadowMap())
    struct Receivers {
        std::size_t fingerprint = 0;
        glm::dmat4 lightViewProjection{0.0};
        int resolution = 0;
        ReceiverDepths depths;
    };
    // The scene's depths in the first view's map (a cascaded light's: in each cascade's), for the bias report.
    std::vector<Receivers> receivers_;
};

}  // namespace shadowlab
