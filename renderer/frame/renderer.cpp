#include "light/scene_lights.h"
#include "frame/renderer.h"

#include "gl/gl_errors.h"
#include "light/blur_texel.h"
#include "light/volume_overlap.h"
#include "scene/hash_combine.h"
#include "scene/scene_animation.h"
#include "scene/scene_casters.h"
#include "settings/settings_fields.h"
#include "shading/filters/filter_technique.h"
#include "views/depth_bounds.h"

#include <glm/ext/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <string_view>

namespace shadowlab {

namespace {

std::string joinLines(const std::vector<std::string>& lines) {
    std::string out;
    for (const std::string& line : lines) out += (out.empty() ? "" : "; ") + line;
    return out;
}

}  // namespace

std::vector<ShadowView> frameViewsOf(const FrameStats& stats, std::size_t light) {
    std::vector<ShadowView> views;
    for (const ShadowViewStats& v : stats.views)
        if (v.hasView && v.light == light) views.push_back({v.light, v.kind, v.index, v.space, v.slice});
    return views;
}

std::vector<ShadowView> frameCascades(const FrameStats& stats) {
    for (const ShadowViewStats& v : stats.views)
        if (v.hasView) return v.kind == ShadowViewKind::Cascade ? frameViewsOf(stats, v.light) : std::vector<ShadowView>{};
    return {};
}

bool projectToPixel(const FrameStats& stats, const glm::dvec3& world, int width, int height, double& px, double& py) {
    const glm::dvec4 clip = stats.cameraViewProjection * glm::dvec4(world - stats.renderOrigin, 1.0);
    if (clip.w <= 0.0) return false;
    const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
    px = (ndc.x * 0.5 + 0.5) * width;
    py = (1.0 - (ndc.y * 0.5 + 0.5)) * height;
    return px >= 0.0 && py >= 0.0 && px < width && py < height && std::abs(ndc.z) <= 1.0;
}

Renderer::Renderer()
    : info_(queryGlInfo()),
      shadowPass_(std::make_unique<ShadowPass>()),
      timer_(info_.softwareRasterizer ? TimingSource::CpuAroundFinish : TimingSource::GpuQueries) {}

const ShadowMap& Renderer::shadowMap() const {
    static const ShadowMap empty;
    const ShadowMap* first = firstView_ ? viewMap(*firstView_) : nullptr;
    return first ? *first : empty;
}

const ShadowMap* Renderer::viewMap(const ShadowViewId& view) const {
    const auto it = views_.find(view);
    return it == views_.end() || !it->second.map.valid() ? nullptr : &it->second.map;
}

const ShadowMap* Renderer::viewMap(std::size_t light, int face) const {
    return viewMap(face >= 0 ? ShadowViewId{light, ShadowViewKind::CubeFace, face} : ShadowViewId{light});
}

FrameStats Renderer::render(const Scene& scene, const Settings& requested, const Camera& camera,
                            RenderTarget& target, const FitCamera* fitCamera) {
    FrameStats stats;
    stats.timingSource = timer_.sourceLabel();
    if (std::vector<std::string> problems = requested.validate(); !problems.empty()) {
        stats.error = "invalid settings: " + joinLines(problems);
        return stats;
    }
    if (target.width() < 1 || target.height() < 1) {
        stats.error = "the render target has no size";
        return stats;
    }

    // The frame's lights: the settings' or the scene's (useSceneLights).
    Settings settings = withEffectiveLights(requested, scene);
    stats.lightSource = describeLightSource(requested, scene);
    stats.lightCount = settings.lights.size();

    // The geometry is uploaded once. Only transforms changed (an animation step, in place or a posed copy:
    // GpuScene::sameGeometry): the transform buffer is updated and the draws that moved dirty only the views they
    // touch (the planner's CasterMotion).
    const std::size_t transforms = transformsFingerprint(scene);
    const glm::dvec3 origin = renderOriginOf(scene.bounds);
    std::vector<std::size_t> movedDraws;
    bool uploaded = false;
    if (gpuScene_ && gpuScene_->sameGeometry(scene)) {
        if (&gpuScene_->scene() != &scene || transforms != transformsFingerprint_ || origin != gpuScene_->origin()) {
            movedDraws = gpuScene_->updateTransforms(scene, origin).moved;
            stats.sceneUpload = {true, gpuScene_->lastUpload().describe(), std::nullopt};
        } else {
            stats.sceneUpload = {false, "unchanged", std::nullopt};
        }
    } else {
        // Every matrix is built relative to the render origin in double precision.
        gpuScene_ = std::make_unique<GpuScene>(scene, origin);
        uploaded = true;
        stats.sceneUpload = {true, gpuScene_->lastUpload().describe(), std::nullopt};
    }
    // The scene as posed: its geometry and transforms (what the receivers' depths of the bias report follow).
    std::size_t fingerprint = gpuScene_->geometryFingerprint();
    hashCombine(fingerprint, transforms);
    if (stats.sceneUpload.ran) {
        stats.geometryBytesUploaded = gpuScene_->lastUpload().geometryBytes;
        stats.transformBytesUploaded = gpuScene_->lastUpload().transformBytes;
    }
    // What casts (casters.excluded): the planner names a change of the key; the maps' contents follow it.
    gpuScene_->setCasting(castingInstances(scene, settings.casters));
    // The casters (the draws that cast, in draw order) and what moved since the last frame. An upload after
    // sceneChanged() knows no previous pose: a map drawn before it is stale if any transform changed meanwhile.
    const std::vector<GpuDraw>& draws = gpuScene_->draws();
    std::vector<CasterSphere> spheres;
    std::vector<std::size_t> casterDraws;
    std::vector<std::size_t> casterOf(draws.size(), std::size_t(-1));
    for (std::size_t d = 0; d < draws.size(); ++d) {
        if (!draws[d].casts) continue;
        casterOf[d] = spheres.size();
        spheres.push_back(casterSphere(draws[d]));
        casterDraws.push_back(d);
    }
    motion_.moved.clear();
    if (uploaded && transforms != transformsFingerprint_) {
        motion_.pose += 2;
    } else {
        for (std::size_t d : movedDraws) {
            if (casterOf[d] == std::size_t(-1)) continue;  // moves no shadow
            const Instance& instance = scene.instances[draws[d].instance];
            const bool named = instance.node >= 0 && std::size_t(instance.node) < scene.nodes.size();
            motion_.moved.push_back({casterOf[d],
                                     named ? scene.nodes[std::size_t(instance.node)].path
                                           : "instance " + std::to_string(draws[d].instance),
                                     d < drawSpheres_.size() ? drawSpheres_[d] : CasterSphere{},
                                     spheres[casterOf[d]]});
        }
        if (!motion_.moved.empty()) ++motion_.pose;
    }
    transformsFingerprint_ = transforms;
    drawSpheres_.resize(draws.size());
    for (std::size_t d = 0; d < draws.size(); ++d) drawSpheres_[d] = casterSphere(draws[d]);
    // Static casters (a cachedStatic light caches them): what no playing animation moves, or casters.static.
    std::vector<char> staticCasters;
    const bool anyCached = std::any_of(settings.lights.begin(), settings.lights.end(), [](const LightSettings& l) {
        return l.shadow.update == ShadowUpdate::CachedStatic;
    });
    if (anyCached) {
        std::string playError;
        const std::vector<int> playing = chosenAnimations(scene, settings.animation.play, playError).value_or(std::vector<int>{});
        const std::vector<char> instances = staticInstances(scene, playing, settings.casters);
        for (std::size_t d : casterDraws) staticCasters.push_back(instances[draws[d].instance]);
    }
    stats.renderOrigin = gpuScene_->origin();
    stats.sceneTriangles = scene.triangleCount();
    const glm::dmat4 view = camera.view(stats.renderOrigin);
    stats.cameraViewProjection = camera.projection(double(target.width()) / target.height()) * view;

    // The depth-bounds fit (projection.depthBounds): the depths the camera sees, this frame's (a depth prepass, read
    // back before planning) or the previous frame's (reduced after its main pass).
    const double aspect = double(target.width()) / target.height();
    const ViewCamera viewCamera = viewCameraOf(camera, aspect, stats.renderOrigin);
    const DepthBounds boundsWanted = depthBoundsWanted(settings);
    std::optional<ViewDepths> lastFrameDepths;
    if (depthBoundsPass_) lastFrameDepths = depthBoundsPass_->collect();  // a pending one is always read, used or not
    if (boundsWanted != DepthBounds::Off && !depthBoundsPass_) depthBoundsPass_ = std::make_unique<DepthBoundsPass>();
    std::optional<ViewDepths> seenDepths;
    if (boundsWanted == DepthBounds::SameFrame) {
        timer_.begin(TimedPass::DepthBounds);
        seenDepths = depthBoundsPass_->measureNow(*gpuScene_, stats.cameraViewProjection, camera.projection(aspect),
                                                  target);
        timer_.end(TimedPass::DepthBounds);
        stats.depthBoundsPass = {true, "projection.depthBounds sameFrame: a depth prepass, reduced and read back",
                                 timer_.latestMilliseconds(TimedPass::DepthBounds)};
    } else if (boundsWanted == DepthBounds::PreviousFrame) {
        seenDepths = lastFrameDepths;
    } else {
        stats.depthBoundsPass = {false, "projection.depthBounds is off for every cascaded light", std::nullopt};
    }
    // The cascades fit the fit camera when one is given (frozen cascades, the flicker measure's previous frame): the
    // depths this camera sees do not bound that camera's view, so they keep the depths the last frame of their own
    // camera fitted to (the cascades as they were, not cascades that change with the picture's camera). The kept
    // bounds change only when what is seen leaves them or they grow twice too loose (keptDepthBounds).
    ViewCamera cascadeCamera =
        fitCamera ? viewCameraOf(fitCamera->camera, fitCamera->aspect, stats.renderOrigin) : viewCamera;
    if (!fitCamera) ownCameraDepths_ = keptDepthBounds(ownCameraDepths_, seenDepths);
    cascadeCamera.seenDepths = boundsWanted == DepthBounds::Off ? std::nullopt : ownCameraDepths_;
    stats.seenDepths = cascadeCamera.seenDepths;
    for (const LightSettings& light : settings.lights) {
        std::string fallback;
        cascadeDepthBounds(light, cascadeCamera, &fallback);
        if (!fallback.empty() && std::find(stats.warnings.begin(), stats.warnings.end(), fallback) == stats.warnings.end())
            stats.warnings.push_back(fallback);
    }

    // The plan: each casting light's views, grouped into map arrays by (2D or cube, resolution, format, convention),
    // each decided against what its map holds (the plan the previous frame carried out).
    // Cascades follow the fit camera; what the picture's camera cannot see is still judged from the picture's camera.
    ShadowPlan plan = planShadowViews({scene, requested, stats.renderOrigin, &cascadeCamera, stats.cameraViewProjection,
                                       spheres, gpuScene_->geometryFingerprint(), info_.maxTextureSize,
                                       previousPlan_ ? &*previousPlan_ : nullptr,
                                       std::exchange(forceReason_, std::string()), &motion_,
                                       anyCached ? &staticCasters : nullptr, frames_++});
    if (!plan.error.empty()) {
        stats.error = plan.error;
        return stats;  // nothing was drawn: the previous plan still says what the maps hold
    }
    // From here a failure may leave arrays reallocated or views half drawn: the next frame renders every view.
    previousPlan_.reset();
    settings = plan.settings;
    stats.warnings.insert(stats.warnings.end(), plan.warnings.begin(), plan.warnings.end());
    for (const LightWithoutView& l : plan.lightsWithoutViews) {
        ShadowViewStats entry;
        entry.light = l.light;
        entry.name = viewName(l.light, ShadowViewKind::Single, 0);
        entry.reason = l.reason;
        stats.views.push_back(entry);
    }

    // Allocate the arrays: each group's layers, reallocated when its count changes; unused arrays are freed.
    for (const auto& [group, layers] : plan.layers) {
        ShadowMapArray& array = arrays_[group];
        const std::uint64_t before = array.generation();
        if (std::string error = array.ensure(group.cube, group.resolution, group.format, layers,
                                             info_.maxTextureSize, info_.maxArrayTextureLayers);
            !error.empty()) {
            if (!array.valid()) arrays_.erase(group);
            stats.error = error;
            return stats;
        }
        array.setReversedZ(group.reversedZ);
        stats.shadowMapReallocated = stats.shadowMapReallocated || array.generation() != before;
    }
    for (auto it = arrays_.begin(); it != arrays_.end();)
        it = plan.layers.count(it->first) ? std::next(it) : arrays_.erase(it);
    for (auto it = views_.begin(); it != views_.end();) {
        const bool used = std::any_of(plan.views.begin(), plan.views.end(),
                                      [&](const PlannedView& p) { return p.view.id() == it->first; });
        it = used ? std::next(it) : views_.erase(it);
    }

    // Run or clear each view the planner says; the others keep their maps.
    double shadowMilliseconds = 0.0;
    bool anyMilliseconds = false;
    std::vector<std::string> ranReasons;
    bool anySkippedForOtherReason = false;
    for (std::size_t v = 0; v < plan.views.size(); ++v) {
        const PlannedView& p = plan.views[v];
        const LightSettings& light = settings.lights[p.view.light];
        ViewState& state = views_[p.view.id()];
        state.group = p.group;
        const ShadowMapArray& array = arrays_.at(p.group);
        if (std::string error = state.map.attach(array, p.layer); !error.empty()) {
            stats.error = error;
            return stats;
        }
        ShadowViewStats entry;
        entry.light = p.view.light;
        entry.kind = p.view.kind;
        entry.index = p.view.index;
        entry.face = p.view.cubeFace();
        entry.name = viewName(p.view);
        entry.hasView = true;
        entry.space = p.view.space;
        entry.slice = p.view.slice;
        entry.resolution = array.resolution();
        entry.format = array.format();
        entry.memoryBytes = state.map.memoryBytes();
        entry.reason = p.reason;
        entry.cache = cacheStateName(p.cache);
        switch (p.action) {
        case ViewAction::Keep: break;
        case ViewAction::SkipUnseen: anySkippedForOtherReason = true; break;
        case ViewAction::Clear:
            clearShadowMap(state.map, p.view.space.reversedZ);  // read as lit everywhere; no draw
            anySkippedForOtherReason = true;
            break;
        case ViewAction::Render: {
            const int timed = PassTimer::kFirstViewPass + int(v);
            timer_.begin(timed);
            const ShadowPassCounts counts = renderView(p, light, state, casterDraws, staticCasters);
            timer_.end(timed);
            if (p.cache == CacheState::StaticPlusDynamic) entry.texelsRedrawn = std::size_t(p.rect.area());
            if (p.cache == CacheState::Scrolled)
                for (const TexelRect& strip : exposedStrips(p.scroll, state.map.resolution()))
                    entry.texelsRedrawn += std::size_t(strip.area());
            entry.ran = true;
            entry.milliseconds = timer_.latestMilliseconds(timed);
            entry.castersDrawn = counts.castersDrawn;
            entry.castersSkipped = counts.castersSkipped;
            entry.drawCalls = counts.drawCalls;
            stats.shadowDrawCalls += counts.drawCalls;
            entry.triangles = counts.trianglesDrawn;
            stats.castersDrawn += counts.castersDrawn;
            stats.castersSkipped += counts.castersSkipped;
            stats.alphaTestedCasters += counts.alphaTestedCasters;
            stats.shadowTriangles += counts.trianglesDrawn;
            if (entry.milliseconds) {
                shadowMilliseconds += *entry.milliseconds;
                anyMilliseconds = true;
            }
            ranReasons.push_back(plan.views.size() == 1 ? p.reason : entry.name + ": " + p.reason);
            break;
        }
        }
        stats.views.push_back(entry);
    }
    std::stable_sort(stats.views.begin(), stats.views.end(), [](const ShadowViewStats& a, const ShadowViewStats& b) {
        return a.light != b.light ? a.light < b.light : a.index < b.index;
    });
    for (const auto& [group, array] : arrays_) stats.shadowMapBytes += array.memoryBytes();
    if (!ranReasons.empty()) {
        stats.shadowPass = {true, joinLines(ranReasons), anyMilliseconds ? std::optional<double>(shadowMilliseconds)
                                                                         : std::nullopt};
    } else {
        stats.shadowPass = {false,
                            plan.views.empty() ? "no light casts a shadow"
                            : anySkippedForOtherReason ? "skipped: no view needed rendering (see the views)"
                                                       : "unchanged: light, casters and shadow settings are the same",
                            std::nullopt};
    }

    // The first view: what one-light reports (bias, the map viewer, the probe) describe.
    if (!plan.views.empty()) {
        const ShadowView& first = plan.views.front().view;
        firstView_ = first.id();
        const ShadowMap& map = views_.at(first.id()).map;
        stats.light = first.space;
        stats.shadowMapResolution = map.resolution();
        stats.shadowMapFormat = map.format();
        // The bias report's views: every cascade of a cascaded first light (the texel-relative terms and the
        // receivers differ per cascade), else the first view.
        std::vector<const ShadowView*> reported{&first};
        if (first.kind == ShadowViewKind::Cascade)
            for (const PlannedView& planned : plan.views)
                if (planned.view.light == first.light && planned.view.id() != first.id()) reported.push_back(&planned.view);
        receivers_.resize(reported.size());
        for (std::size_t r = 0; r < reported.size(); ++r) {
            const ShadowView& v = *reported[r];
            // The receivers' depths in the map change only with the scene and the view: not recomputed for a bias edit.
            if (receivers_[r].fingerprint != fingerprint || receivers_[r].lightViewProjection != v.space.viewProjection() ||
                receivers_[r].resolution != v.space.resolution)
                receivers_[r] = Receivers{fingerprint, v.space.viewProjection(), v.space.resolution,
                                          receiverDepths(scene, v.space, stats.renderOrigin)};
            stats.viewBias.push_back({viewName(v), biasReport(settings.lights[v.light].shadow,
                                                              views_.at(v.id()).map.format(), v.space,
                                                              receivers_[r].depths)});
        }
        stats.bias = stats.viewBias.front().bias;
        const bool clamps = std::any_of(settings.lights.begin(), settings.lights.end(), [](const LightSettings& l) {
            return l.castsShadows && l.shadow.depthBiasClamp != 0.0f;
        });
        if (clamps && !shadowPass_->hasPolygonOffsetClamp())
            stats.warnings.push_back("shadow.depthBiasClamp: glPolygonOffsetClamp is not available; the clamp is ignored");
    } else {
        firstView_.reset();
    }

    // A moments technique: the views' moments, brought up to date for the views just drawn (or new moments settings).
    const FilterTechnique& technique = filterTechnique(settings.filter.kind);
    if (technique.moments) {
        if (!momentsPass_) momentsPass_ = std::make_unique<MomentsPass>();
        std::vector<MomentsView> momentViews;
        for (std::size_t v = 0; v < plan.views.size(); ++v) {
            const PlannedView& p = plan.views[v];
            const LightSpace& space = p.view.space;
            const double texelWorld = blurTexelWorldSize(space);  // world blur widths
            momentViews.push_back({p.view.id(), viewName(p.view), p.group, p.layer,
                                   p.action == ViewAction::Render || p.action == ViewAction::Clear, texelWorld,
                                   space.perspective, float(space.nearPlane), float(space.farPlane)});
        }
        MomentsPassResult moments = momentsPass_->run(settings.filter, arrays_, momentViews, timer_);
        momentsPass_->configureSampler(settings.filter, settings.sampler);
        stats.momentsPass = moments.moments;
        stats.blurPass = moments.blur;
        stats.mipsPass = moments.mips;
        stats.warnings.insert(stats.warnings.end(), moments.warnings.begin(), moments.warnings.end());
    } else {
        if (momentsPass_) momentsPass_->release();
        const std::string reason = std::string("filter.kind ") + technique.name + " compares depth: no moments";
        stats.momentsPass = {false, reason, std::nullopt};
        stats.blurPass = stats.mipsPass = {false, reason, std::nullopt};
    }

    // The main pass: every enabled light, each casting one with its map array and layer.
    sampler_.configure(settings.sampler, settings.filter.kind);
    reversedSampler_.configure(settings.sampler, settings.filter.kind);
    MainPassInput in;
    in.scene = gpuScene_.get();
    in.settings = &settings;
    // The variant from the key table's variant-tagged keys: derived again only when the settings changed.
    if (!variant_ || !(variant_->first == settings)) variant_.emplace(settings, mainVariantKey(settings));
    in.variant = variant_->second;
    in.viewProjection = stats.cameraViewProjection;
    in.cameraPosition = camera.position - stats.renderOrigin;
    in.cameraForward = viewCamera.forward;
    in.cascadeEye = cascadeCamera.eye;
    in.cascadeForward = cascadeCamera.forward;
    in.pixelPerDepth = 2.0 * viewCamera.tanHalfFovY / double(target.height());
    in.renderOrigin = stats.renderOrigin;
    std::map<MapGroup, int> arrayIndex;
    for (const auto& [group, array] : arrays_) {
        std::vector<GLuint>& list = group.cube ? in.mapsCube : in.maps2D;
        arrayIndex[group] = int(list.size());
        // A moments technique reads the group's moments (one bilinear sampler), else its depth through a compare sampler.
        list.push_back(technique.moments ? momentsPass_->texture(group) : array.texture());
        (group.cube ? in.samplersCube : in.samplers2D)
            .push_back(technique.moments ? momentsPass_->sampler()
                                         : group.reversedZ ? reversedSampler_.id() : sampler_.id());
    }
    for (std::size_t i = 0; i < settings.lights.size(); ++i) {
        if (!settings.lights[i].enabled) continue;
        MainPassLight l;
        l.settings = &settings.lights[i];
        const auto casting = std::find_if(plan.views.begin(), plan.views.end(),
                                          [&](const PlannedView& p) { return p.view.light == i; });
        if (casting != plan.views.end()) {
            l.space = &casting->view.space;
            l.mapArray = arrayIndex.at(casting->group);
            l.layer = casting->group.cube ? casting->layer / 6 : casting->layer;
            if (casting->view.kind == ShadowViewKind::Cascade)
                for (auto c = casting; c != plan.views.end() && c->view.light == i; ++c)
                    l.cascades.push_back({&c->view, c->layer});
        }
        in.lights.push_back(l);
    }
    timer_.begin(TimedPass::Main);
    const std::set<std::string> variants = mainPass_.run(in, target);
    timer_.end(TimedPass::Main);
    stats.mainPass = {true, "every frame", timer_.latestMilliseconds(TimedPass::Main)};
    if (boundsWanted == DepthBounds::PreviousFrame) {
        timer_.begin(TimedPass::DepthBounds);
        depthBoundsPass_->reduceMainDepth(camera.projection(aspect), target);
        timer_.end(TimedPass::DepthBounds);
        stats.depthBoundsPass = {true, "projection.depthBounds previousFrame: this frame's depth, reduced for the next",
                                 timer_.latestMilliseconds(TimedPass::DepthBounds)};
    }
    stats.mainVariants.assign(variants.begin(), variants.end());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    previousPlan_ = std::move(plan);  // what each view's map now holds: the next frame's planner compares with it
    stats.ok = true;
    return stats;
}

ShadowPassCounts Renderer::renderView(const PlannedView& p, const LightSettings& light, ViewState& state,
                                      const std::vector<std::size_t>& casterDraws,
                                      const std::vector<char>& statics) {
    const LightSpace& space = p.view.space;
    const bool clamp = light.depthClampApplies();
    // Without its cached depth (a map the GPU refused to allocate) the view is drawn whole, every caster.
    const bool cacheMissing = (p.cache == CacheState::StaticPlusDynamic || p.cache == CacheState::Scrolled) &&
                              (!state.staticDepth.valid() || state.staticDepth.resolution() != state.map.resolution() ||
                               state.staticDepth.format() != state.map.format());
    if (!p.fromStaticCache || cacheMissing ||
        (p.cache == CacheState::Full &&
         !state.staticDepth.ensure(state.map.resolution(), state.map.format(), info_.maxTextureSize).empty()))
        return shadowPass_->run(*gpuScene_, space, light.shadow, clamp, state.map);
    // The view's casters (castersInVolume) narrowed to the static or the dynamic ones.
    std::vector<char> staticDraw(gpuScene_->draws().size(), 0);
    for (std::size_t c = 0; c < casterDraws.size() && c < statics.size(); ++c) staticDraw[casterDraws[c]] = statics[c];
    const CasterSelection inVolume = castersInVolume(*gpuScene_, space);
    auto narrowed = [&](auto keep) {
        CasterSelection selection;
        selection.skipped = inVolume.skipped;
        for (std::uint32_t d : inVolume.draws)
            if (keep(d)) selection.draws.push_back(d);
        return selection;
    };
    // Copies rectangle `r` of one map to (x, y) of another (the cached static depth and the view's layer).
    auto copy = [](const ShadowMap& from, const TexelRect& r, const ShadowMap& to, int x, int y) {
        glCopyImageSubData(from.texture(), GL_TEXTURE_2D, 0, r.x0, r.y0, 0, to.texture(), GL_TEXTURE_2D, 0, x, y, 0,
                           r.x1 - r.x0, r.y1 - r.y0, 1);
    };
    auto copyCache = [&](const TexelRect& r) { copy(state.staticDepth, r, state.map, r.x0, r.y0); };
    const TexelRect whole{0, 0, state.map.resolution(), state.map.resolution()};
    auto add = [](ShadowPassCounts& sum, const ShadowPassCounts& c) {
        sum.castersDrawn += c.castersDrawn;
        sum.alphaTestedCasters += c.alphaTestedCasters;
        sum.trianglesDrawn += c.trianglesDrawn;
        sum.drawCalls += c.drawCalls;
    };
    // A stable cascade's static casters go in pages of the light's texel grid (views/cascade_scroll.h), so a scrolled
    // map stores what a whole one does, bit for bit; `region`'s texels of `into` get them.
    const std::vector<CascadePage> allPages =
        p.view.kind == ShadowViewKind::Cascade && light.projection.cascadeFit == CascadeFit::Stable
            ? cascadePages(space, whole)
            : std::vector<CascadePage>{};
    const bool paged = !allPages.empty() && pageScratch_.ensure(allPages.front().space.resolution, state.map.format(),
                                                                info_.maxTextureSize).empty();
    auto drawStatics = [&](const TexelRect& region, const ShadowMap& into) {
        ShadowPassCounts counts;
        for (const CascadePage& page : cascadePages(space, region)) {
            CasterSelection pageCasters = castersInVolume(*gpuScene_, page.space);
            std::erase_if(pageCasters.draws, [&](std::uint32_t d) { return staticDraw[d] == 0; });
            pageCasters.skipped = 0;
            pageCasters.scissor = page.inPage;
            add(counts, shadowPass_->run(*gpuScene_, pageCasters, page.space, light.shadow, clamp, pageScratch_));
            copy(pageScratch_, page.inPage, into, page.inMap.x0, page.inMap.y0);
        }
        return counts;
    };
    if (p.cache == CacheState::Scrolled && paged) {
        // The cached static depth moved by whole texels into the layer, the strips that came into view drawn from
        // their pages, the result cached, the dynamic casters over it.
        const int n = state.map.resolution();
        const TexelRect target = scrollTarget(p.scroll, n);
        if (!target.empty()) copy(state.staticDepth, scrollSource(p.scroll, n), state.map, target.x0, target.y0);
        ShadowPassCounts counts;
        counts.castersSkipped = inVolume.skipped;
        for (const TexelRect& strip : exposedStrips(p.scroll, n)) add(counts, drawStatics(strip, state.map));
        copy(state.map, whole, state.staticDepth, 0, 0);
        CasterSelection dynamics = narrowed([&](std::uint32_t d) { return staticDraw[d] == 0; });
        dynamics.clear = false;
        add(counts, shadowPass_->run(*gpuScene_, dynamics, space, light.shadow, clamp, state.map));
        return counts;
    }
    if (p.cache == CacheState::StaticPlusDynamic) {
        std::vector<char> listed(staticDraw.size(), 0);
        for (std::size_t c : p.dynamicCasters) listed[casterDraws[c]] = 1;
        copyCache(p.rect);
        CasterSelection over = narrowed([&](std::uint32_t d) { return listed[d] != 0; });
        over.scissor = p.rect;
        over.clear = false;
        return shadowPass_->run(*gpuScene_, over, space, light.shadow, clamp, state.map);
    }
    // Full (or a scroll whose page could not be allocated): the static casters into the cached depth, a copy of it,
    // the dynamic casters over it.
    ShadowPassCounts counts;
    counts.castersSkipped = inVolume.skipped;
    if (paged)
        add(counts, drawStatics(whole, state.staticDepth));
    else
        counts = shadowPass_->run(*gpuScene_, narrowed([&](std::uint32_t d) { return staticDraw[d] != 0; }), space,
                                  light.shadow, clamp, state.staticDepth);
    copyCache(whole);
    CasterSelection dynamics = narrowed([&](std::uint32_t d) { return staticDraw[d] == 0; });
    dynamics.clear = false;
    add(counts, shadowPass_->run(*gpuScene_, dynamics, space, light.shadow, clamp, state.map));
    return counts;
}

void Renderer::waitForTimings(FrameStats& stats) {
    double total = 0.0;
    bool any = false;
    // Views were timed under kFirstViewPass + their planning index; that index follows the order they ran in.
    int planningIndex = 0;
    for (ShadowViewStats& view : stats.views) {
        if (!view.hasView) continue;
        if (view.ran) {
            view.milliseconds = timer_.latestMilliseconds(PassTimer::kFirstViewPass + planningIndex, true);
            if (view.milliseconds) {
                total += *view.milliseconds;
                any = true;
            }
        }
        ++planningIndex;
    }
    if (stats.shadowPass.ran && any) stats.shadowPass.milliseconds = total;
    if (stats.mainPass.ran) stats.mainPass.milliseconds = timer_.latestMilliseconds(TimedPass::Main, true);
    if (stats.depthBoundsPass.ran)
        stats.depthBoundsPass.milliseconds = timer_.latestMilliseconds(TimedPass::DepthBounds, true);
    if (stats.momentsPass.ran) stats.momentsPass.milliseconds = timer_.latestMilliseconds(TimedPass::Moments, true);
    if (stats.blurPass.ran) stats.blurPass.milliseconds = timer_.latestMilliseconds(TimedPass::Blur, true);
    if (stats.mipsPass.ran) stats.mipsPass.milliseconds = timer_.latestMilliseconds(TimedPass::Mips, true);
}

MomentsLayer Renderer::viewMomentsLayer(const ShadowViewId& view) const {
    const auto it = views_.find(view);
    if (!momentsPass_ || it == views_.end()) return {};
    return momentsPass_->layer(it->second.group, it->second.map.layer());
}

std::vector<glm::vec4> Renderer::viewMoments(const ShadowViewId& view, int x0, int y0, int w, int h, int level) const {
    const auto it = views_.find(view);
    if (!momentsPass_ || it == views_.end() || !momentsPass_->texture(it->second.group)) return {};
    return momentsPass_->read(it->second.group, it->second.map.layer(), x0, y0, w, h, level);
}

}  // namespace shadowlab
