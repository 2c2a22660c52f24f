#include "light/scene_lights.h"
#include "frame/renderer.h"

#include "gl/gl_errors.h"

#include <glm/ext/matrix_transform.hpp>

#include <cmath>
#include <cstring>
#include <functional>

namespace shadowlab {

namespace {

void hashCombine(std::size_t& seed, std::size_t value) { seed ^= value + 0x9e3779b97f4a7c15ULL + (seed << 6) + (seed >> 2); }

template <typename T>
void hashBytes(std::size_t& seed, const T& value) {
    std::size_t chunk = 0;
    const auto* bytes = reinterpret_cast<const unsigned char*>(&value);
    for (std::size_t i = 0; i < sizeof(T); ++i) {
        chunk = chunk * 131 + bytes[i];
        if (i % 8 == 7) hashCombine(seed, std::exchange(chunk, 0));
    }
    hashCombine(seed, chunk);
}

std::string joinLines(const std::vector<std::string>& lines) {
    std::string out;
    for (const std::string& line : lines) out += (out.empty() ? "" : "; ") + line;
    return out;
}

}  // namespace

std::size_t sceneFingerprint(const Scene& scene) {
    std::size_t seed = std::hash<const void*>{}(&scene);
    hashCombine(seed, scene.meshes.size());
    for (const Mesh& mesh : scene.meshes) {
        hashCombine(seed, std::hash<const void*>{}(mesh.positions.data()));
        hashCombine(seed, mesh.positions.size());
        hashCombine(seed, mesh.indices.size());
        hashCombine(seed, std::size_t(mesh.material + 1));
    }
    for (const Instance& instance : scene.instances) {
        hashCombine(seed, std::size_t(instance.mesh));
        hashBytes(seed, instance.transform);
    }
    for (const Material& material : scene.materials) {
        hashCombine(seed, std::size_t(material.alphaMode));
        hashBytes(seed, material.alphaCutoff);
        hashBytes(seed, material.baseColorFactor.a);
        hashBytes(seed, material.doubleSided);
        hashBytes(seed, material.uvTransform);
    }
    return seed;
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

std::string Renderer::shadowPassReason(const ShadowInputs& now, bool reallocated) const {
    if (!lastShadow_) return "first frame";
    if (reallocated) return "shadow map reallocated";
    std::vector<std::string> reasons;
    if (now.sceneFingerprint != lastShadow_->sceneFingerprint) reasons.push_back("scene changed");
    if (now.lightViewProjection != lastShadow_->lightViewProjection) reasons.push_back("light changed");
    const ShadowMapSettings& a = now.shadow;
    const ShadowMapSettings& b = lastShadow_->shadow;
    if (a.depthBias != b.depthBias || a.slopeScaledDepthBias != b.slopeScaledDepthBias ||
        a.depthBiasClamp != b.depthBiasClamp)
        reasons.push_back("bias changed");
    if (a.cullMode != b.cullMode) reasons.push_back("cull mode changed");
    if (now.depthClamp != lastShadow_->depthClamp) reasons.push_back("depth clamp changed");
    return joinLines(reasons);
}

FrameStats Renderer::render(const Scene& scene, const Settings& requested, const Camera& camera,
                            RenderTarget& target) {
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

    // Settings with the scene's light applied (light.useSceneLight); normal offset needs no separate copy.
    Settings settings = requested;
    settings = withEffectiveLights(requested, scene);
    stats.lightSource = describeLightSource(requested, scene);

    const std::size_t fingerprint = sceneFingerprint(scene);
    if (!gpuScene_ || &gpuScene_->scene() != &scene || gpuSceneFingerprint_ != fingerprint) {
        // The render origin is the scene's centre: every matrix is built relative to it in double precision.
        const glm::dvec3 origin = scene.bounds.empty ? glm::dvec3(0.0) : glm::dvec3(scene.bounds.center());
        gpuScene_ = std::make_unique<GpuScene>(scene, origin);
        gpuSceneFingerprint_ = fingerprint;
    }
    stats.renderOrigin = gpuScene_->origin();
    stats.sceneTriangles = scene.triangleCount();

    // A resolution the GPU refuses keeps the previous map (and says so); with no map at all there is no frame.
    const std::string mapError = shadowMap_.ensure(settings.lights[0].shadow.resolution, settings.lights[0].shadow.format,
                                                   info_.maxTextureSize);
    if (!mapError.empty()) {
        if (!shadowMap_.valid()) {
            stats.error = mapError;
            return stats;
        }
        stats.warnings.push_back(mapError);
        settings.lights[0].shadow.resolution = shadowMap_.resolution();
        settings.lights[0].shadow.format = shadowMap_.format();
    }
    stats.shadowMapReallocated = shadowMap_.generation() != mapGenerationRendered_;

    std::string lightError;
    std::optional<LightSpace> light = buildLightSpace(settings, scene.bounds, stats.renderOrigin, lightError);
    if (!light) {
        stats.error = lightError;
        return stats;
    }
    stats.light = *light;
    stats.shadowMapResolution = shadowMap_.resolution();
    stats.shadowMapFormat = shadowMap_.format();
    stats.shadowMapBytes = shadowMap_.memoryBytes();
    // The receivers' depths in the map change only with the scene and the light: not recomputed for a bias edit.
    if (!receivers_ || receivers_->fingerprint != fingerprint ||
        receivers_->lightViewProjection != light->viewProjection() || receivers_->resolution != light->resolution)
        receivers_ = Receivers{fingerprint, light->viewProjection(), light->resolution,
                               receiverDepths(scene, *light, stats.renderOrigin)};
    stats.bias = biasReport(settings.lights[0].shadow, shadowMap_.format(), *light, receivers_->depths);
    if (settings.lights[0].shadow.depthBiasClamp != 0.0f && !shadowPass_->hasPolygonOffsetClamp())
        stats.warnings.push_back("shadow.depthBiasClamp: glPolygonOffsetClamp is not available; the clamp is ignored");

    const ShadowInputs inputs{fingerprint, light->viewProjection(), settings.lights[0].shadow,
                              settings.lights[0].projection.depthClamp};
    const std::string reason = shadowPassReason(inputs, stats.shadowMapReallocated);
    if (!reason.empty()) {
        timer_.begin(TimedPass::Shadow);
        const ShadowPassCounts counts =
            shadowPass_->run(*gpuScene_, *light, settings.lights[0].shadow, settings.lights[0].projection.depthClamp, shadowMap_);
        timer_.end(TimedPass::Shadow);
        stats.shadowPass = {true, reason, timer_.latestMilliseconds(TimedPass::Shadow)};
        stats.castersDrawn = counts.castersDrawn;
        stats.castersSkipped = counts.castersSkipped;
        stats.alphaTestedCasters = counts.alphaTestedCasters;
        stats.shadowTriangles = counts.trianglesDrawn;
        lastShadow_ = inputs;
        mapGenerationRendered_ = shadowMap_.generation();
    } else {
        stats.shadowPass = {false, "unchanged: light, casters and shadow settings are the same", std::nullopt};
    }

    shadowMap_.configureSamplers(settings.sampler, settings.filter.kind);
    const glm::dmat4 view = camera.view(stats.renderOrigin);
    stats.cameraViewProjection = camera.projection(double(target.width()) / target.height()) * view;
    MainPassInput in;
    in.scene = gpuScene_.get();
    in.light = &*light;
    in.shadowMap = &shadowMap_;
    in.settings = &settings;
    in.viewProjection = stats.cameraViewProjection;
    in.cameraPosition = camera.position - stats.renderOrigin;
    timer_.begin(TimedPass::Main);
    const std::set<std::string> variants = mainPass_.run(in, target);
    timer_.end(TimedPass::Main);
    stats.mainPass = {true, "every frame", timer_.latestMilliseconds(TimedPass::Main)};
    stats.mainVariants.assign(variants.begin(), variants.end());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    stats.ok = true;
    return stats;
}

void Renderer::waitForTimings(FrameStats& stats) {
    if (stats.shadowPass.ran) stats.shadowPass.milliseconds = timer_.latestMilliseconds(TimedPass::Shadow, true);
    if (stats.mainPass.ran) stats.mainPass.milliseconds = timer_.latestMilliseconds(TimedPass::Main, true);
}

}  // namespace shadowlab
