#include "accuracy/accuracy_meter.h"

#include "views/view_select.h"

#include "accuracy/accuracy_metrics.h"
#include "accuracy/accuracy_overlay.h"
#include "accuracy/gbuffer_pass.h"
#include "accuracy/gpu_accuracy_counter.h"
#include "accuracy/light_isolation.h"
#include "accuracy/shadow_boundary.h"
#include "frame/renderer.h"
#include "gl/program.h"
#include "gl/texture_read_back.h"
#include "light/scene_lights.h"
#include "reference/embree_scene.h"
#include "reference/parallel_rows.h"
#include "reference/soft_visibility.h"
#include "reference/visibility.h"
#include "shading/main_pass.h"
#include "scene/scene_casters.h"
#include "views/shadow_view.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <future>
#include <optional>

namespace shadowlab {

namespace {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// What the surface samples depend on.
struct SurfaceKey {
    glm::dvec3 position, target;
    double fovYDeg, nearPlane, farPlane, orthoHalfHeight;
    int width, height;
    bool operator==(const SurfaceKey&) const = default;
};

void setStage(AccuracyProgress* progress, float fraction, const char* stage) {
    if (!progress) return;
    progress->fraction = progress->base + progress->span * fraction;
    progress->setStage(stage);
}

bool cancelled(const AccuracyProgress* progress) { return progress && progress->cancel.load(); }

// The coarse-map warning: when most shadowed pixels lie within k texels of a true edge, acne and leak (which skip
// them) read near 0 whatever the map does.
std::string coarseMapWarning(const AccuracyReport& r) {
    const AccuracyCounts& c = r.counts;
    if (c.shadowed == 0 || double(c.shadowedNearEdge) <= kCoarseMapShare * double(c.shadowed)) return "";
    char text[400];
    std::snprintf(text, sizeof text,
                  "coarse map: %.0f %% of the shadowed pixels lie within k = %.1f texels (%.3g world units) of a true "
                  "edge, so acne and leak cannot judge this map; read wrong pixels (%.2f %%) and mean error (%.4f)",
                  100.0 * double(c.shadowedNearEdge) / double(c.shadowed), r.kTexels, r.kTexels * r.texelWorldSize,
                  r.wrongPercent, r.meanError);
    return text;
}

// Per-pixel unit conversions for the edge error: a shadow-map texel's world size at p, and a main-view pixel's
// world size at p's depth (both the CPU metrics and the GPU counter's upload use these).
struct EdgeUnits {
    const SurfaceSamples& samples;
    const ShadowBoundary& boundary;  // knows the texel of every light kind (a point light's: its cube face's)
    glm::dvec3 eye, forward;
    const Camera& viewCamera;
    int viewHeight;

    EdgeUnits(const SurfaceSamples& s, const ShadowBoundary& b, const Camera& camera, const glm::dvec3& origin,
              int height)
        : samples(s),
          boundary(b),
          eye(camera.position - origin),
          forward(glm::normalize(camera.target - camera.position)),
          viewCamera(camera),
          viewHeight(height) {}
    double worldPerTexel(std::size_t i) const { return boundary.texelWorldSizeAt(samples.point[i]); }
    double worldPerPixel(std::size_t i) const {
        return viewCamera.worldPerPixel(glm::dot(samples.point[i] - eye, forward), viewHeight);
    }
};

// Texels per screen pixel over the measured pixels: the texel density view's ratio (shaders/main.frag.glsl).
// The ratios per row on all cores; the three percentiles from one list (each selection only reorders it, and the
// p-th value does not depend on the order).
TexelDensity texelDensityOf(const std::vector<std::uint8_t>& measured, const EdgeUnits& units, int width,
                            int height) {
    std::vector<std::vector<double>> rows(static_cast<std::size_t>(height));
    parallelRows(height, [&](int row) {
        const std::size_t first = std::size_t(row) * std::size_t(width);
        for (std::size_t i = first; i < first + std::size_t(width); ++i) {
            if (!measured[i]) continue;
            const double texel = units.worldPerTexel(i);
            if (texel > 0.0) rows[std::size_t(row)].push_back(units.worldPerPixel(i) / texel);
        }
    });
    std::vector<double> ratios;
    for (const std::vector<double>& row : rows) ratios.insert(ratios.end(), row.begin(), row.end());
    TexelDensity d;
    d.pixels = ratios.size();
    if (ratios.empty()) return d;
    d.p5 = percentile(ratios, 5);
    d.median = percentile(ratios, 50);
    d.p95 = percentile(ratios, 95);
    return d;
}

// What the BVH is built from: the scene's geometry and which of its instances cast.
std::size_t referenceFingerprint(const Scene& scene, const std::vector<char>& casting) {
    return withCasters(sceneFingerprint(scene), casting);
}

std::string invalidSettings(const Settings& settings) {
    std::string text;
    for (const std::string& p : settings.validate()) text += (text.empty() ? "" : "; ") + p;
    return text.empty() ? "" : "invalid settings: " + text;
}

// What measure() and remeasure() measure: light 0 alone, in a view of at least 1x1; nullopt with `error` otherwise.
std::optional<Settings> measuredSettings(const Settings& given, const Scene& scene, int width, int height,
                                         std::string& error) {
    if (width < 1 || height < 1) {
        error = "view size must be at least 1x1";
        return std::nullopt;
    }
    if (error = invalidSettings(given); !error.empty()) return std::nullopt;
    // Several lights: the caller chooses one (light_accuracy.h measures each); never light 0 silently.
    if (effectiveLights(given, scene).size() > 1) {
        error = singleLightError(given, scene, "the accuracy meter");
        return std::nullopt;
    }
    return isolateLight(given, scene, 0, error);
}

}  // namespace

namespace {

double share(std::size_t part, std::size_t whole) { return whole ? 100.0 * double(part) / double(whole) : 0.0; }

}  // namespace

double AccuracyReport::causePercentOfWrong(MismatchCause cause) const {
    return share(counts.causeWrong[std::size_t(cause)], counts.wrong);
}

double AccuracyReport::causePercentOfAcne(MismatchCause cause) const {
    return share(counts.causeAcne[std::size_t(cause)], counts.acne);
}

double AccuracyReport::causePercentOfLeak(MismatchCause cause) const {
    return share(counts.causeLeak[std::size_t(cause)], counts.leak);
}

MismatchCause AccuracyReport::mainCause() const {
    // Beyond k first: the blur next to true edges is in every picture and rarely what to fix.
    MismatchCause best = MismatchCause::None;
    std::size_t most = 0;
    for (MismatchCause cause : allCauses()) {
        const std::size_t n = counts.causePixels[std::size_t(cause)];
        if (cause != MismatchCause::NearEdge && n > most) {
            most = n;
            best = cause;
        }
    }
    if (best == MismatchCause::None && counts.causePixels[std::size_t(MismatchCause::NearEdge)] > 0)
        best = MismatchCause::NearEdge;
    return best;
}

struct AccuracyMeter::Impl {
    Renderer renderer;
    Renderer* toolRenderer = nullptr;  // setToolRenderer: draws the tool frame instead of `renderer`
    FrameStats lastToolFrame;
    RenderTarget toolTarget;
    gl::TextureReadBack toolReadBack;  // the tool frame's S, read in place
    GBufferPass gbuffer;

    // Scene: the BVH, rebuilt only when the geometry changes (the G-buffer draws the tool renderer's upload).
    const Scene* scene = nullptr;
    std::size_t fingerprint = 0;
    glm::dvec3 origin{0.0};
    std::unique_ptr<EmbreeScene> bvh;

    // Camera and size: the surface samples.
    std::optional<SurfaceKey> surfaceKey;
    SurfaceSamples samples;
    double gbufferMs = 0.0;

    // Light: exact visibility.
    std::optional<ReferenceLight> visibilityLight;
    VisibilityResult visibility;

    // Light size and ray count: the soft reference (for a light of size > 0).
    std::optional<std::pair<ReferenceLight, SoftLight>> softKey;
    SoftVisibilityResult soft;

    // Light space (map size, projection): the boundary in texels and each pixel's distance to it.
    std::optional<std::pair<std::vector<glm::dmat4>, int>> boundaryKey;  // every view's matrix, the resolution
    std::optional<ShadowBoundary> boundary;
    double boundaryMs = 0.0;

    // Live accuracy: the reference on the GPU, uploaded for the boundary it was built from.
    std::unique_ptr<GpuAccuracyCounter> counter;
    bool counterCurrent = false;

    // Forgets everything traced from the scene; keeps the BVH when `keepBvh` (its instances are about to move).
    void dropScene(bool keepBvh = false) {
        scene = nullptr;
        if (!keepBvh) bvh.reset();
        surfaceKey.reset();
        visibilityLight.reset();
        softKey.reset();
        boundaryKey.reset();
        counterCurrent = false;
    }

    // The tool's own frame into toolTarget: the shadow factor S of every pixel, exactly as the main pass computes it.
    FrameStats renderToolFrame(const Scene& drawn, const Settings& settings, const Camera& camera, int width,
                               int height, const Camera* shadowCamera = nullptr) {
        Settings toolSettings = settings;
        toolSettings.view = ViewMode::Shadow;
        if (std::string error = toolTarget.resize(width, height, GL_RGBA32F); !error.empty()) {
            FrameStats failed;
            failed.ok = false;
            failed.error = error;
            return failed;
        }
        // The shadow camera sees through the same view (this target's aspect).
        const std::optional<FitCamera> fit =
            shadowCamera ? std::optional<FitCamera>(FitCamera{*shadowCamera, double(width) / height}) : std::nullopt;
        lastToolFrame = (toolRenderer ? *toolRenderer : renderer)
                            .render(drawn, toolSettings, camera, toolTarget, fit ? &*fit : nullptr);
        return lastToolFrame;
    }

    // The true boundary in this light space's texels (rebuilt when the map's size or projection changed).
    void ensureBoundary(const Scene& drawn, const FrameStats& stats, const ReferenceLight& light,
                        AccuracyReport& report) {
        const std::vector<ShadowView> cascades = frameCascades(stats);
        std::pair<std::vector<glm::dmat4>, int> key{{stats.light.viewProjection()}, stats.light.resolution};
        for (const ShadowView& c : cascades) key.first.push_back(c.space.viewProjection());
        if (boundaryKey && *boundaryKey == key) return;
        const auto t = Clock::now();
        BoundaryProbe probe;
        probe.bvh = bvh.get();
        probe.light = light;
        probe.sceneRadius = drawn.bounds.empty ? 1.0 : double(drawn.bounds.radius());
        boundary.emplace(samples, visibility.classes, stats.light, probe, cascades);
        boundaryKey = key;
        counterCurrent = false;
        report.cost.boundaryMs = msSince(t);
    }
};

AccuracyMeter::AccuracyMeter() : impl_(std::make_unique<Impl>()) {}
AccuracyMeter::~AccuracyMeter() = default;

void AccuracyMeter::sceneChanged() {
    impl_->dropScene();
    impl_->renderer.sceneChanged();
}

void AccuracyMeter::setToolRenderer(Renderer* renderer) { impl_->toolRenderer = renderer; }

const FrameStats& AccuracyMeter::lastToolFrame() const { return impl_->lastToolFrame; }

FrameStats AccuracyMeter::drawToolFrame(const Scene& scene, const Settings& given, const Camera& camera, int width,
                                        int height) {
    std::string error;
    const std::optional<Settings> settings = measuredSettings(given, scene, width, height, error);
    if (!settings) {
        FrameStats failed;
        failed.error = error;
        return failed;
    }
    return impl_->renderToolFrame(scene, *settings, camera, width, height);
}

AccuracyReport AccuracyMeter::measure(const Scene& scene, const Settings& given, const Camera& camera, int width,
                                      int height, AccuracyProgress* progress, const Camera* shadowCamera) {
    Impl& m = *impl_;
    const auto start = Clock::now();
    AccuracyReport report;
    auto fail = [&](std::string error) {
        report.ok = false;
        report.error = std::move(error);
        return report;
    };
    auto stop = [&] {
        report.cancelled = true;
        return fail("cancelled");
    };
    std::string settingsError;
    const std::optional<Settings> isolated = measuredSettings(given, scene, width, height, settingsError);
    if (!isolated) return fail(settingsError);
    const Settings& settings = *isolated;

    // The BVH, once per scene geometry and set of casters; when only instance transforms changed (an animation
    // step), its top level follows them and the mesh BVHs stay. Everything traced from it is traced again.
    const std::vector<char> casting = castingInstances(scene, settings.casters);
    const std::size_t fingerprint = referenceFingerprint(scene, casting);
    report.cost.bvhReused = m.scene == &scene && m.fingerprint == fingerprint && m.bvh;
    report.cost.bvhUpdated =
        !report.cost.bvhReused && m.scene == &scene && m.bvh && m.bvh->sameGeometry(scene, casting);
    // A BVH built from scratch does not wait for the tool frame: Embree builds it on the other cores while this
    // thread drives the GPU. Its origin is the one the renderer takes for this scene (checked below).
    const glm::dvec3 bvhOrigin = renderOriginOf(scene.bounds);
    std::future<std::unique_ptr<EmbreeScene>> bvhBuild;
    if (!report.cost.bvhReused && !report.cost.bvhUpdated)
        bvhBuild = std::async(std::launch::async, [&scene, bvhOrigin, &casting] {
            return std::make_unique<EmbreeScene>(scene, bvhOrigin, casting);
        });

    // The tool's own frame: the shadow factor S of every pixel, exactly as the main pass computes it.
    setStage(progress, 0.0f, "rendering the tool's frame");
    const gl::ProgramBuildTally programsBefore = gl::programBuildTally();
    auto t = Clock::now();
    FrameStats stats = m.renderToolFrame(scene, settings, camera, width, height, shadowCamera);
    if (!stats.ok) return fail(stats.error);
    report.cost.toolRenderMs = msSince(t);
    report.warnings = stats.warnings;
    for (const ShadowViewStats& view : stats.views) report.shadowViewsRendered += view.ran ? 1 : 0;
    const std::size_t count = std::size_t(width) * std::size_t(height);
    std::vector<float> shadowFactor(count);
    std::vector<std::uint8_t> toolCovered(count);
    // Red and green only (half the bytes of the RGBA32F frame): the shadow view writes grey, S in every channel,
    // and the clear colour's red and green differ, so red == green tells a drawn pixel.
    static_assert(kClearColour[0] != kClearColour[1], "the tool frame's coverage test needs red != green");
    const bool readBack = m.toolReadBack.read(
        m.toolTarget.colorTexture(), GL_RG, GL_FLOAT, count * 2 * sizeof(float), [&](const void* pixels) {
            const float* frame = static_cast<const float*>(pixels);
            parallelRows(height, [&](int row) {
                const std::size_t src = std::size_t(height - 1 - row) * std::size_t(width);
                const std::size_t dst = std::size_t(row) * std::size_t(width);
                for (std::size_t x = 0; x < std::size_t(width); ++x) {
                    const float* px = &frame[(src + x) * 2];
                    shadowFactor[dst + x] = px[0];
                    toolCovered[dst + x] = px[0] == px[1] ? 1 : 0;
                }
            });
        });
    if (!readBack) return fail("the tool frame's read-back buffer could not be mapped (GPU out of memory?)");
    report.cost.toolFrameMs = msSince(t);
    report.cost.toolReadBackMs = report.cost.toolFrameMs - report.cost.toolRenderMs;
    if (cancelled(progress)) return stop();

    if (report.cost.bvhUpdated) {
        setStage(progress, 0.1f, "moving the BVH's instances");
        m.dropScene(true);
        m.origin = stats.renderOrigin;
        report.cost.instancesMoved = m.bvh->updateTransforms(scene, m.origin);
        m.scene = &scene;
        m.fingerprint = fingerprint;
        report.cost.bvhUpdateMs = m.bvh->updateMilliseconds();
    } else if (!report.cost.bvhReused) {
        setStage(progress, 0.1f, "building the BVH");
        m.dropScene();
        m.origin = stats.renderOrigin;
        m.bvh = bvhBuild.get();
        if (m.origin != bvhOrigin) m.bvh = std::make_unique<EmbreeScene>(scene, m.origin, casting);
        m.scene = &scene;
        m.fingerprint = fingerprint;
        report.cost.bvhBuildMs = m.bvh->buildMilliseconds();
    }
    report.cost.triangles = m.bvh->triangles();
    if (cancelled(progress)) return stop();

    // Surface samples, once per camera and size.
    const SurfaceKey surfaceKey{camera.position, camera.target,   camera.fovYDeg, camera.nearPlane,
                                camera.farPlane, camera.orthoHalfHeight, width, height};
    const bool surfaceReused = m.surfaceKey && *m.surfaceKey == surfaceKey;
    if (!surfaceReused) {
        setStage(progress, 0.3f, "G-buffer: rebuilding surface points");
        t = Clock::now();
        m.surfaceKey.reset();
        m.visibilityLight.reset();
        m.softKey.reset();
        m.boundaryKey.reset();
        // The G-buffer draws the geometry the tool frame just drew (its renderer's upload, posed as this scene).
        const GpuScene* drawn = (m.toolRenderer ? *m.toolRenderer : m.renderer).gpuScene();
        if (!drawn) return fail("the tool frame uploaded no scene for the G-buffer");
        if (std::string error = m.gbuffer.render(*drawn, stats.cameraViewProjection, width, height,
                                                 camera.position - m.origin, m.samples);
            !error.empty())
            return fail(error);
        m.gbufferMs = msSince(t);
        m.surfaceKey = surfaceKey;
        report.cost.gbufferMs = m.gbufferMs;
        report.cost.gbufferDrawMs = m.gbuffer.lastTimings().drawMs;
        report.cost.gbufferReadBackMs = m.gbuffer.lastTimings().readBackMs;
        report.cost.gbufferRebuildMs = m.gbuffer.lastTimings().rebuildMs;
    }
    if (cancelled(progress)) return stop();

    // Exact visibility, once per light.
    const ReferenceLight light = referenceLight(settings.lights[0], m.origin);
    const bool visibilityReused = m.visibilityLight && *m.visibilityLight == light;
    if (!visibilityReused) {
        setStage(progress, 0.45f, "tracing shadow rays");
        m.visibilityLight.reset();
        m.boundaryKey.reset();
        const double radius = scene.bounds.empty ? 1.0 : double(scene.bounds.radius());
        m.visibility = traceVisibility(*m.bvh, m.samples, light, radius, progress ? &progress->cancel : nullptr);
        if (m.visibility.cancelled) return stop();
        m.visibilityLight = light;
        report.cost.traceMs = m.visibility.milliseconds;
        report.cost.rays = m.visibility.rays;
        report.cost.raysPerSecond =
            m.visibility.milliseconds > 0.0 ? double(m.visibility.rays) / (m.visibility.milliseconds * 1e-3) : 0.0;
        report.cost.threads = m.visibility.threads;
    }

    // The soft reference, once per light, size and ray count (a hard light has none: version 2's numbers only).
    const SoftLight disc = softLight(settings.lights[0], settings.reference.softRays);
    if (disc.soft()) {
        const std::pair<ReferenceLight, SoftLight> softKey{light, disc};
        if (!(visibilityReused && m.softKey && *m.softKey == softKey)) {
            setStage(progress, 0.6f, "tracing the soft reference");
            m.softKey.reset();
            const double radius = scene.bounds.empty ? 1.0 : double(scene.bounds.radius());
            m.soft = traceSoftVisibility(*m.bvh, m.samples, m.visibility.classes, light, disc, radius,
                                         progress ? &progress->cancel : nullptr);
            if (m.soft.cancelled) return stop();
            m.softKey = softKey;
            report.soft.traceMs = m.soft.milliseconds;
            report.soft.tracedRays = m.soft.rays;
            report.soft.threads = m.soft.threads;
        }
    }

    // The true boundary in this light space's texels.
    setStage(progress, 0.85f, "finding the true shadow boundary");
    m.ensureBoundary(scene, stats, light, report);
    report.cost.referenceReused = surfaceReused && visibilityReused;
    if (cancelled(progress)) return stop();

    // The numbers and the picture.
    setStage(progress, 0.9f, "measuring");
    t = Clock::now();
    report.kTexels = acceptanceRadiusTexels(settings.filter);
    report.texelWorldSize = stats.light.texelWorldSize;
    // No boundary in view: distances are capped at the map's size (so every number stays finite).
    const double cap = double(stats.light.resolution);
    const double k = report.kTexels;
    ShadowBoundary& boundary = *m.boundary;
    // The pixels whose distance and cause the metrics need (the visibly wrong ones), on all cores first.
    // Per row on all cores; joined in row order, the list is in pixel order as before.
    std::vector<std::vector<std::size_t>> mismatchedRows(static_cast<std::size_t>(height));
    parallelRows(height, [&](int row) {
        const std::size_t first = std::size_t(row) * std::size_t(width);
        for (std::size_t i = first; i < first + std::size_t(width); ++i) {
            const PixelClass c = m.visibility.classes[i];
            if (!isScored(c) || !toolCovered[i] || !std::isfinite(shadowFactor[i])) continue;
            if (visiblyWrong(isLit(c), shadowFactor[i])) mismatchedRows[std::size_t(row)].push_back(i);
        }
    });
    std::vector<std::size_t> mismatched;
    for (const std::vector<std::size_t>& row : mismatchedRows) mismatched.insert(mismatched.end(), row.begin(), row.end());
    const std::size_t probedBefore = boundary.probedPixels();
    const auto probeStart = Clock::now();
    boundary.prepare(mismatched, k);
    report.cost.probeMs = msSince(probeStart);
    report.cost.probedPixels = boundary.probedPixels() - probedBefore;
    auto distance = [&](std::size_t i) { return std::min(boundary.distance(i, k), cap); };

    // A cause for each of them (shadow rays toward the light under the shadow pass's rules), on all cores.
    CauseContext causeContext;
    causeContext.bvh = m.bvh.get();
    causeContext.light = light;
    causeContext.lightSpace = stats.light;
    causeContext.cascades = frameCascades(stats);
    causeContext.cullMode = settings.lights[0].shadow.cullMode;
    causeContext.depthClamp = settings.lights[0].depthClampApplies();
    causeContext.sceneRadius = scene.bounds.empty ? 1.0 : double(scene.bounds.radius());
    const auto causesStart = Clock::now();
    std::vector<MismatchCause> causes(count, MismatchCause::None);
    const int chunks = int((mismatched.size() + 63) / 64);
    parallelRows(chunks, [&](int chunk) {
        const std::size_t end = std::min(mismatched.size(), std::size_t(chunk + 1) * 64);
        for (std::size_t j = std::size_t(chunk) * 64; j < end; ++j) {
            const std::size_t i = mismatched[j];
            causes[i] = decideCause(causeContext, m.samples.point[i], m.samples.normal[i], m.visibility.classes[i],
                                    distance(i), k);
        }
    });
    report.cost.causesMs = msSince(causesStart);

    const EdgeUnits units(m.samples, boundary, camera, m.origin, height);
    MetricsInput input;
    input.classes = &m.visibility.classes;
    input.shadowFactor = &shadowFactor;
    input.toolCovered = &toolCovered;
    input.k = k;
    input.distance = distance;
    input.cause = [&](std::size_t i, double) { return causes[i]; };
    input.worldPerTexel = [&](std::size_t i) { return units.worldPerTexel(i); };
    input.worldPerPixel = [&](std::size_t i) { return units.worldPerPixel(i); };
    MetricsResult metrics = computeMetrics(input);
    static_cast<AccuracyNumbers&>(report) = metrics;
    report.width = width;
    report.height = height;
    // The pictures and the per-pixel copies need nothing computed below: they are made on other threads while this
    // one computes the rest of the numbers (their fresh buffers are first written on one thread each).
    const auto overlaysStart = Clock::now();
    auto overlay = [&](OverlayKind kind) {
        return std::async(std::launch::async, [&, kind] {
            return makeOverlay(kind, width, height, m.visibility.classes, shadowFactor, m.visibility.lambert, metrics,
                               boundary, settings.ambient);
        });
    };
    auto errorOverlay = overlay(OverlayKind::Error);
    auto causeOverlay = overlay(OverlayKind::Cause);
    std::future<std::vector<std::uint8_t>> softOverlay;
    if (disc.soft())
        softOverlay = std::async(std::launch::async, [&] {
            return makeSoftOverlay(width, height, m.visibility.classes, shadowFactor, m.visibility.lambert,
                                   m.soft.visibility, metrics.measured, settings.ambient);
        });
    auto copies = std::async(std::launch::async, [&] {
        report.pixelClass = m.visibility.classes;
        report.pixelLambert = m.visibility.lambert;
        if (disc.soft()) report.pixelSoftVisibility = m.soft.visibility;
    });
    report.texelDensity = texelDensityOf(metrics.measured, units, width, height);
    if (disc.soft()) {
        SoftMetricsInput softInput;
        softInput.width = width;
        softInput.height = height;
        softInput.measured = &metrics.measured;
        softInput.visibility = &m.soft.visibility;
        softInput.shadowFactor = &shadowFactor;
        softInput.points = &m.samples.point;
        softInput.normals = &m.samples.normal;
        softInput.worldPerTexel = [&](std::size_t i) { return units.worldPerTexel(i); };
        const SoftAccuracy softCost = report.soft;
        report.soft = computeSoftMetrics(softInput);
        report.soft.traceMs = softCost.traceMs;
        report.soft.tracedRays = softCost.tracedRays;
        report.soft.threads = softCost.threads;
        report.soft.light = 0;  // of these settings; measureLights names the light's index
        report.soft.size = double(settings.lights[0].size);
        report.soft.sizeUnit = settings.lights[0].type == LightType::Directional ? "degrees" : "world units";
        report.soft.rays = disc.rays;
    }
    // Per row on all cores (a shadowed pixel's distance is a nearest-point query), the counts summed after.
    report.pixelOnBoundary.assign(count, 0);
    std::vector<std::size_t> boundaryPixels(std::size_t(height), 0), shadowedNearEdge(std::size_t(height), 0);
    parallelRows(height, [&](int row) {
        const std::size_t first = std::size_t(row) * std::size_t(width);
        for (std::size_t i = first; i < first + std::size_t(width); ++i) {
            report.pixelOnBoundary[i] = boundary.onBoundary(i) ? 1 : 0;
            boundaryPixels[std::size_t(row)] += report.pixelOnBoundary[i];
            const PixelClass c = m.visibility.classes[i];
            if (isScored(c) && !isLit(c) && toolCovered[i] && boundary.visibleDistance(i) <= k)
                ++shadowedNearEdge[std::size_t(row)];
        }
    });
    for (int row = 0; row < height; ++row) {
        report.counts.boundaryPixels += boundaryPixels[std::size_t(row)];
        report.counts.shadowedNearEdge += shadowedNearEdge[std::size_t(row)];
    }
    report.coarseMapWarning = coarseMapWarning(report);
    report.overlayRgba = errorOverlay.get();
    report.causeOverlayRgba = causeOverlay.get();
    if (softOverlay.valid()) report.softOverlayRgba = softOverlay.get();
    copies.get();
    report.cost.overlaysMs = msSince(overlaysStart);
    report.pixelShadow = std::move(shadowFactor);
    report.pixelCause = std::move(metrics.causes);  // the overlays above were the last to read them
    report.pixelMark = std::move(metrics.marks);
    report.pixelMeasured = std::move(metrics.measured);
    if (const std::vector<ShadowView> cascades = frameCascades(stats); !cascades.empty()) {
        std::vector<std::int8_t> cascadeOf(count, -1);
        parallelRows(height, [&](int row) {
            const std::size_t first = std::size_t(row) * std::size_t(width);
            for (std::size_t i = first; i < first + std::size_t(width); ++i)
                if (report.pixelMeasured[i]) cascadeOf[i] = std::int8_t(selectView(cascades, m.samples.point[i]).view);
        });
        std::vector<double> texelWorld;
        for (const ShadowView& c : cascades) texelWorld.push_back(c.space.texelWorldSize);
        report.cascades = cascadeAccuracy(report, cascadeOf, texelWorld);
    }
    report.cost.metricsMs = msSince(t);
    report.cost.totalMs = msSince(start);
    const gl::ProgramBuildTally programsAfter = gl::programBuildTally();
    report.cost.programsBuilt = programsAfter.programs - programsBefore.programs;
    report.cost.programBuildMs = programsAfter.milliseconds - programsBefore.milliseconds;
    setStage(progress, 1.0f, "done");
    report.ok = true;
    return report;
}

AccuracyReport AccuracyMeter::remeasure(const Scene& scene, const Settings& given, const Camera& camera,
                                        int width, int height) {
    Impl& m = *impl_;
    const auto start = Clock::now();
    AccuracyReport report;
    report.live = true;
    auto fail = [&](std::string error, bool needsReference = false) {
        report.ok = false;
        report.needsReference = needsReference;
        report.error = std::move(error);
        return report;
    };
    std::string settingsError;
    const std::optional<Settings> isolated = measuredSettings(given, scene, width, height, settingsError);
    if (!isolated) return fail(settingsError);
    const Settings& settings = *isolated;
    // The reference must describe this view: scene, camera and size here, the light after the frame says where.
    const SurfaceKey surfaceKey{camera.position, camera.target,   camera.fovYDeg, camera.nearPlane,
                                camera.farPlane, camera.orthoHalfHeight, width, height};
    if (m.scene != &scene || !m.bvh ||
        m.fingerprint != referenceFingerprint(scene, castingInstances(scene, settings.casters)) || !m.surfaceKey ||
        !(*m.surfaceKey == surfaceKey))
        return fail("no reference for this view (scene, casters, camera or size changed): measure it first", true);

    auto t = Clock::now();
    const FrameStats stats = m.renderToolFrame(scene, settings, camera, width, height);
    if (!stats.ok) return fail(stats.error);
    report.warnings = stats.warnings;
    report.cost.toolFrameMs = msSince(t);
    const ReferenceLight light = referenceLight(settings.lights[0], m.origin);
    if (!m.visibilityLight || !(*m.visibilityLight == light))
        return fail("no reference for this light (it moved): measure it first", true);
    report.cost.bvhReused = report.cost.referenceReused = true;
    report.cost.triangles = m.bvh->triangles();
    report.cost.rays = m.visibility.rays;
    m.ensureBoundary(scene, stats, light, report);

    const double k = acceptanceRadiusTexels(settings.filter);
    report.kTexels = k;
    report.texelWorldSize = stats.light.texelWorldSize;
    ShadowBoundary& boundary = *m.boundary;
    if (!m.counter) m.counter = std::make_unique<GpuAccuracyCounter>();
    if (!m.counterCurrent) {
        t = Clock::now();
        const EdgeUnits units(m.samples, boundary, camera, m.origin, height);
        const std::size_t count = std::size_t(width) * std::size_t(height);
        std::vector<float> worldPerTexel(count, 0.0f), screenPerTexel(count, 0.0f);
        for (std::size_t i = 0; i < count; ++i) {
            if (!isScored(m.visibility.classes[i])) continue;
            const double perTexel = units.worldPerTexel(i), perPixel = units.worldPerPixel(i);
            worldPerTexel[i] = float(perTexel);
            screenPerTexel[i] = perPixel > 0.0 ? float(perTexel / perPixel) : 0.0f;  // as computeMetrics
        }
        m.counter->upload(width, height, m.visibility.classes, boundary, k, worldPerTexel, screenPerTexel);
        m.counterCurrent = true;
        report.cost.uploadMs = msSince(t);
    }

    // Pixels mismatched for the first time at a distance the boundary has not probed yet: probe them on the CPU (as
    // measure() would) and count again.
    const double cap = double(stats.light.resolution);
    t = Clock::now();
    GpuAccuracyCounter::Result counted = m.counter->count(m.toolTarget.colorTexture(), k, cap, boundary.probes());
    for (int round = 0; !counted.unresolved.empty() && round < 3; ++round) {
        const auto probeStart = Clock::now();
        const std::size_t probedBefore = boundary.probedPixels();
        boundary.prepare(std::vector<std::size_t>(counted.unresolved.begin(), counted.unresolved.end()), k);
        m.counter->update(counted.unresolved, boundary, k);
        report.cost.probedPixels += boundary.probedPixels() - probedBefore;
        report.cost.probeMs += msSince(probeStart);
        counted = m.counter->count(m.toolTarget.colorTexture(), k, cap, boundary.probes());
    }
    if (!counted.unresolved.empty()) return fail("live accuracy: the boundary left pixels undecided");
    static_cast<AccuracyNumbers&>(report) = counted.numbers;
    report.cost.metricsMs = msSince(t) - report.cost.probeMs;
    report.coarseMapWarning = coarseMapWarning(report);
    report.width = width;
    report.height = height;
    report.cost.totalMs = msSince(start);
    report.ok = true;
    return report;
}

}  // namespace shadowlab
